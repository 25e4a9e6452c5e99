#!/usr/bin/env python3
"""Makes docs/html-report.png: the HTML report of a small run, drawn by headless Chromium
(tests/e2e/browser.py), never by hand.

    /usr/bin/python3 scripts/html-report-screenshot.py --build build [--output FILE]

The run, through the real runner in the build tree: two suites at once (-j 2), "arm" with a
test that measures its tracking error (with limits) and loop rate in 3 repetitions, one of
them outside its limits, and a test that fails; "base" with a Python fixture that takes 0.4 s
to be ready. It runs 4 times into one --history file, so the report shows each measurement
across the repetitions and across the runs, the failing tests open, and the timeline. Its
files go to a temporary folder (--workdir: where that goes), removed at the end."""
import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

SOURCE = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(SOURCE / "tests" / "e2e"))
from browser import chromium  # noqa: E402  (tests/e2e/browser.py, after the path is set)

TRACKING = """import os
class TestCase:
    def run(self):
        n = int(open("count").read()) if os.path.exists("count") else 0
        open("count", "w").write(str(n + 1))
        run = int(os.environ["RUN"])
        error = [0.012, 0.018, 0.015, 0.021][run] + 0.004 * n
        if run == 3 and n == 1:
            error = 0.063  # the elbow overshot: outside its limits
        robottestingframework.testMeasure("joint tracking error", error, "rad", 0, 0.05)
        robottestingframework.testMeasure("loop rate", 99.2 + 0.3 * n - 0.2 * run, "Hz", 95, 105)
"""
BROKEN = """class TestCase:
    def run(self):
        robottestingframework.testReport("reading joint 3")
        robottestingframework.assertFail("joint 3 out of range: 97 deg > 90 deg")
"""
SLOW = """import time
class TestCase:
    def run(self):
        time.sleep(0.3)
        robottestingframework.testReport("moved the arm")
"""
WORLD = """import time
class FixtureManager:
    def setup(self, param):
        time.sleep(0.4)
        robottestingframework.testReport("world is ready after 0.4 s")
        return True
    def tearDown(self):
        time.sleep(0.1)
"""
QUICK = """class TestCase:
    def run(self):
        robottestingframework.testReport("quick look")
"""


def write_suites(folder):
    for name, text in (("tracking.py", TRACKING), ("broken.py", BROKEN), ("slow.py", SLOW),
                       ("world.py", WORLD), ("quick.py", QUICK)):
        (folder / name).write_text(text)
    (folder / "arm.xml").write_text("""<suite name="arm">
  <test name="elbow tracking" repetition="3" tags="arm">tracking.py</test>
  <test param="--speed 30" tags="slow,arm">slow.py</test>
  <test>broken.py</test>
</suite>
""")
    (folder / "base.xml").write_text("""<suite name="base">
  <fixture>world.py</fixture>
  <test>quick.py</test>
</suite>
""")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the build tree")
    parser.add_argument("--output", default=str(SOURCE / "docs" / "html-report.png"))
    parser.add_argument("--workdir", default=None,
                        help="where its temporary folder goes (default: the system's)")
    args = parser.parse_args()
    runner = Path(args.build).resolve() / "bin" / "robottestingframework-testrunner"
    with tempfile.TemporaryDirectory(dir=args.workdir) as temporary:
        folder = Path(temporary).resolve()
        write_suites(folder)
        for run in range(4):
            (folder / "count").unlink(missing_ok=True)
            done = subprocess.run(
                [str(runner), "-j", "2", "--suite", "arm.xml", "--suite", "base.xml",
                 "--history", "h.db", "-o", "html:report.html"], cwd=folder,
                env=dict(os.environ, RUN=str(run)), capture_output=True, text=True, timeout=120)
            if done.returncode not in (0, 1):
                sys.exit(f"the run failed ({done.returncode}):\n{done.stderr}")
        with chromium(folder, window="1200,1250") as driver:
            driver.get((folder / "report.html").as_uri())
            # The failing tests are open by themselves; the measured one shows its plots.
            plots = driver.find_elements("css selector", "svg.measure-plot")
            if len(plots) < 4:
                sys.exit(f"expected the measurement plots, found {len(plots)}")
            driver.save_screenshot(args.output)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
