"""Issue 38, friction 1: the console's names can be pasted. The console names each test by the id
--filter takes ("SUITE/ID", docs/reference/test-ids.md), the same at -j 1 and -j 2, with the name
the test gives itself beside it; pasted into --filter, it runs that test alone.
Run from the suite's own folder with relative paths, as users do."""
import re

import pytest

from conftest import run_runner

# Names itself "speed" whatever its params: the display name differs from the id.
SCRIPT = """import robottestingframework
class TestCase:
    def setup(self, param):
        robottestingframework.setName("speed")
        return True
    def run(self):
        robottestingframework.testCheck(True, "fine")
"""

SUITE = """<suite name="robot">
  <test type="python" param="--speed 80">t.py</test>
  <test type="python" param="--speed 10">t.py</test>
  <test type="exec">ok.sh</test>
</suite>
"""

LINE = re.compile(r"^  passed\s+(\S+(?:\[[^]]*\])?)(?: \(([^)]*)\))?  \(\d+\.\d{3} s\)$", re.M)


def workspace(tmp_path):
    folder = tmp_path / "proj"
    folder.mkdir()
    (folder / "t.py").write_text(SCRIPT)
    (folder / "ok.sh").write_text("#!/bin/sh\nexit 0\n")
    (folder / "ok.sh").chmod(0o755)
    (folder / "robot.xml").write_text(SUITE)
    return folder


def shown(stdout):
    """{id: display name or None} of the console's test lines."""
    return {m.group(1): m.group(2) for m in LINE.finditer(stdout)}


def test_the_console_prints_the_same_ids_at_every_j(tmp_path):
    folder = workspace(tmp_path)
    one = run_runner("--suite", "robot.xml", "-j", "1", cwd=folder)
    two = run_runner("--suite", "robot.xml", "-j", "2", cwd=folder)
    assert one.returncode == 0 and two.returncode == 0, (one, two)
    assert shown(one.stdout) == shown(two.stdout), (one.stdout, two.stdout)
    assert shown(one.stdout) == {"robot/t.py[--speed 80]": "speed",
                                 "robot/t.py[--speed 10]": "speed",
                                 "robot/ok.sh": None}, one.stdout


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_printed_id_pasted_into_filter_runs_that_test(tmp_path, jobs):
    folder = workspace(tmp_path)
    run = run_runner("--suite", "robot.xml", "-j", jobs, cwd=folder)
    assert run.returncode == 0, run
    ids = list(shown(run.stdout))
    assert len(ids) == 3, run.stdout
    for pasted in ids:
        again = run_runner("--suite", "robot.xml", "-j", jobs, "--filter", pasted, cwd=folder)
        assert again.returncode == 0, (pasted, again)
        assert list(shown(again.stdout)) == [pasted], (pasted, again.stdout)
