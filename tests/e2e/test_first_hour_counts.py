"""Issue 38, friction 6: one count of failures everywhere. The summary said "2 failed" while
the closing line said "3 failed" (a fixture failure counted in one only)."""
import re
import signal
import time

from conftest import marked, run_runner, start_runner


def test_the_summary_and_the_closing_line_count_the_same_failures(tmp_path):
    (tmp_path / "broken.xml").write_text("""<world name="broken" logdir="logs">
  <process name="broken" command="sh -c 'exit 3'">
    <ready timeout="20s"><output>ready</output></ready>
  </process>
</world>
""")
    for name in ("fail1.sh", "fail2.sh", "pass.sh"):
        (tmp_path / name).write_text("#!/bin/sh\nexit %d\n" % (0 if name == "pass.sh" else 1))
        (tmp_path / name).chmod(0o755)
    (tmp_path / "arm.xml").write_text("""<suite name="arm">
  <test type="exec">fail1.sh</test>
  <test type="exec">fail2.sh</test>
  <test type="exec">pass.sh</test>
</suite>""")
    (tmp_path / "base.xml").write_text("""<suite name="base">
  <fixture type="process">broken.xml</fixture>
  <test type="exec">pass.sh</test>
</suite>""")
    r = run_runner("-s", "arm.xml", "-s", "base.xml", cwd=tmp_path)
    assert r.returncode == 1, r
    closing = r.stdout.strip().splitlines()[-1]
    found = re.fullmatch(r"(\d+) passed, (\d+) failed.*", closing)
    assert found, r.stdout
    assert found.group(2) == "3", r.stdout  # two tests and base's fixture
    assert "  failed: 3 (2 tests, 1 fixture)" in r.stdout, r.stdout


def test_interrupted_tests_are_counted_the_same_in_the_summary_and_the_closing_line(
        tmp_path, marker):
    """Through ctest (one runner per test, stopped by SIGTERM) the summary said "1 interrupted"
    and the closing line "0 passed, 2 failed". An interrupted test fails its run (CTest's test
    fails: the exit status is not 0) and the closing line says how many of its failures were
    interrupted, as the summary does."""
    (tmp_path / "started").unlink(missing_ok=True)
    (tmp_path / "slow.sh").write_text("#!/bin/sh\ntouch started\nsleep 30\n")
    (tmp_path / "fast.sh").write_text("#!/bin/sh\nexit 0\n")
    for name in ("slow.sh", "fast.sh"):
        (tmp_path / name).chmod(0o755)
    (tmp_path / "arm.xml").write_text("""<suite name="arm">
  <test type="exec">slow.sh</test>
  <test type="exec">fast.sh</test>
</suite>""")
    proc = start_runner("-s", "arm.xml", env=marked(marker), cwd=tmp_path)
    deadline = time.monotonic() + 20
    while not (tmp_path / "started").exists() and time.monotonic() < deadline:
        time.sleep(0.05)
    proc.send_signal(signal.SIGTERM)
    out, err = proc.communicate(timeout=30)
    assert proc.returncode != 0, (out, err)
    assert "  tests:  2 (2 interrupted)" in out, out
    closing = out.strip().splitlines()[-1]
    assert closing == "0 passed, 2 failed (2 interrupted)", out
