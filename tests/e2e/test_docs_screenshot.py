"""scripts/html-report-screenshot.py, which makes docs/html-report.png, still works: it runs its
suites through the built runner and saves the page as headless Chromium draws it (here into
the test's folder, not docs/)."""
import struct
import subprocess
import sys

from conftest import BUILD_DIR, SOURCE_DIR


def test_the_script_makes_the_report_picture(tmp_path):
    picture = tmp_path / "html-report.png"
    done = subprocess.run([sys.executable, "-B", str(SOURCE_DIR / "scripts" / "html-report-screenshot.py"),
                           "--build", str(BUILD_DIR), "--output", str(picture),
                           "--workdir", str(tmp_path)],
                          capture_output=True, text=True, timeout=240)
    assert done.returncode == 0, done.stderr
    header = picture.read_bytes()[:24]
    assert header[:8] == b"\x89PNG\r\n\x1a\n"
    width, height = struct.unpack(">II", header[16:24])
    assert width == 1200 and height > 900, (width, height)
    assert [p.name for p in tmp_path.iterdir()] == ["html-report.png"]  # its run is gone
