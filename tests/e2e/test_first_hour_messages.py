"""Issue 38, friction 9: one line per failed check, and a TAP point's YAML block read, not
pasted. A failed check showed both a "check FAILED:" and a "failure:" line; a point's YAML
`measurements:` was pasted into the check's text (`check ok: ok 3 - loop rate: measurements:
- name: ...`). Through the installed runner, from the suite's folder."""
import json

import pytest

from conftest import run_runner
from web_run import WebRun, request

TAP = """#!/bin/sh
echo 'TAP version 14'
echo '1..3'
echo 'ok 1 - arm moves'
echo 'not ok 2 - gripper closes'
echo 'ok 3 - loop rate'
echo '  ---'
echo '  measurements:'
echo '    - name: rate'
echo '      value: 99.5'
echo '      unit: Hz'
echo '  note: fast enough'
echo '  ...'
"""
PYTHON = """class TestCase:
    def run(self):
        robottestingframework.testCheck(False, "the arm reached its target")
"""


def write_suite(tmp_path):
    (tmp_path / "points.sh").write_text(TAP)
    (tmp_path / "points.sh").chmod(0o755)
    (tmp_path / "arm.py").write_text(PYTHON)
    (tmp_path / "suite.xml").write_text("""<suite name="robot">
  <test type="exec">points.sh</test>
  <test type="python">arm.py</test>
</suite>
""")


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_failed_check_is_one_line_and_yaml_is_not_pasted(tmp_path, jobs):
    write_suite(tmp_path)
    r = run_runner("-s", "suite.xml", "-j", jobs, "--detail", "-o", "json:r.json",
                   "-o", "text:r.txt", cwd=tmp_path)
    assert r.returncode == 1, r
    for failed in ("not ok 2 - gripper closes", "the arm reached its target"):
        assert r.stdout.count(failed) == 1, r.stdout
    assert "check FAILED" not in r.stdout, r.stdout
    # The YAML's measurements are a measurement, not text; its other keys stay the detail.
    assert "measurements:" not in r.stdout, r.stdout
    assert "name: rate" not in r.stdout, r.stdout
    if jobs == "1":  # -j N's console says failed checks only
        assert "check ok: ok 3 - loop rate: note: fast enough" in r.stdout, r.stdout
    text = (tmp_path / "r.txt").read_text()
    assert "measurements:" not in text, text
    assert "measurement: rate = 99.5 Hz" in text, text
    report = json.loads((tmp_path / "r.json").read_text())
    points = next(t for t in report["results"]["tests"] if t["name"] == "points.sh")
    rtf = points["extra"]["robotology.rtf"]
    assert [(m["name"], m["value"], m["unit"]) for m in rtf["measurements"]] == \
        [("rate", 99.5, "Hz")], rtf
    for said in rtf["reports"]:
        assert "measurements:" not in said["message"], rtf["reports"]


def test_the_html_report_and_the_live_page_say_a_failed_check_once(tmp_path):
    """The HTML report's details and the live page listed a failed check twice, as "check
    failed: the arm reached its target" and "failure: the arm reached its target" (the second
    trial of the first hour); they say it once, as the console and the text report do. A
    failure with other words than the check before it stays."""
    write_suite(tmp_path)
    (tmp_path / "two.py").write_text("""class TestCase:
    def run(self):
        robottestingframework.testCheck(False, "the arm reached its target")
        robottestingframework.assertFail("the gripper is stuck")
""")
    (tmp_path / "suite.xml").write_text("""<suite name="robot">
  <test type="python">arm.py</test>
  <test type="python">two.py</test>
</suite>
""")
    r = run_runner("-s", "suite.xml", "-o", "html:r.html", cwd=tmp_path)
    assert r.returncode == 1, r
    html = (tmp_path / "r.html").read_text()
    data = json.loads(html.split('id="report-data">', 1)[1].split("</script>", 1)[0])
    tests = {t["fullId"]: t for suite in data["suites"] for t in suite["tests"]}
    said = [m["text"] for m in tests["robot/arm.py"]["messages"]]
    assert said == ["the arm reached its target"], tests["robot/arm.py"]
    said = [m["text"] for m in tests["robot/two.py"]["messages"]]
    assert said == ["the arm reached its target", "the gripper is stuck"], tests["robot/two.py"]

    run = WebRun("-s", "suite.xml", "--web-linger", "60", cwd=tmp_path)
    try:
        run.wait_for_line("final page stays")
        snapshot = json.loads(request(run.port, "/snapshot")[2])
        tests = {t["name"]: t for t in snapshot["suites"][0]["tests"]}
        said = [(m["kind"], m["text"]) for m in tests["arm.py"]["messages"]]
        assert said == [("failure", "the arm reached its target")], said
        assert tests["arm.py"]["state"] == "failed", tests["arm.py"]
        said = [m["text"] for m in tests["two.py"]["messages"]]
        assert said == ["the arm reached its target", "the gripper is stuck"], said
        run.proc.send_signal(2)
        assert run.wait(timeout=10) == 1
    finally:
        run.kill()
