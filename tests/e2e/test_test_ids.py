"""Every result goes to the test it is about, by the id its events carry: two tests of one
name in one suite stay apart, and a script that renames itself mid-run is followed, in every
output and in both isolation modes."""
import json
import re
import xml.etree.ElementTree as ET

import pytest

from conftest import run_runner, validate_ctrf, validate_junit, validate_tap

TWIN = """import robottestingframework
class TestCase:
    def setup(self, param):
        self.failing = "--fail" in param
        robottestingframework.setName("twin")
        return True
    def run(self):
        if self.failing:
            robottestingframework.testCheck(False, "the failing twin fails")
        else:
            robottestingframework.testCheck(True, "the passing twin passes")
"""

RENAMING = """import robottestingframework
class TestCase:
    def setup(self, param):
        return True
    def run(self):
        robottestingframework.testCheck(False, "fails before the rename")
        robottestingframework.setName("renamed mid-run")
        robottestingframework.testReport("after the rename")
"""

# (name, failed, the problem it must carry) in run order.
EXPECTED = [("twin", True, "the failing twin fails"), ("twin", False, None),
            ("renamed mid-run", True, "fails before the rename")]


def result_lines(text):
    """(word, name) of each per-test line of the console or text report, in order."""
    found = []
    for line in text.splitlines():
        m = re.match(r"^  (\S+(?: OUT)?)\s+(.*?)  \(\d+\.\d+ s\)$", line)
        if m and not line.startswith("  suite"):
            found.append((m.group(1), m.group(2)))
    return found


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_same_named_tests_and_a_mid_run_rename_are_attributed_right_everywhere(
        tmp_path, isolation, suite_file):
    (tmp_path / "twin.py").write_text(TWIN)
    (tmp_path / "renaming.py").write_text(RENAMING)
    suite = suite_file("""<suite name="ids">
  <test type="python" param="--fail">twin.py</test>
  <test type="python">twin.py</test>
  <test type="python">renaming.py</test>
</suite>""")
    out = {kind: tmp_path / f"r.{kind}" for kind in ("txt", "xml", "tap", "json", "html")}
    r = run_runner("--isolation", isolation, "--suite", suite,
                   "--output", f"text:{out['txt']}", "--output", f"junit:{out['xml']}",
                   "--output", f"tap:{out['tap']}", "--output", f"json:{out['json']}",
                   "--output", f"html:{out['html']}", cwd=tmp_path, timeout=90)
    assert r.returncode == 1, r
    expected_lines = [("FAILED" if failed else "passed", name) for name, failed, _ in EXPECTED]

    # The console and the text report.
    assert result_lines(r.stdout) == expected_lines, r.stdout
    text = out["txt"].read_text()
    assert result_lines(text) == expected_lines, text
    assert text.index("the failing twin fails") < text.index("passed      twin"), text

    # JUnit.
    validate_junit(out["xml"])
    cases = list(ET.parse(out["xml"]).getroot().iter("testcase"))
    assert [c.get("name") for c in cases] == [name for name, _, _ in EXPECTED]
    for case, (name, failed, problem) in zip(cases, EXPECTED):
        element = case.find("failure")
        assert (element is not None) == failed, ET.tostring(case)
        if problem:
            assert problem in ET.tostring(case, encoding="unicode")

    # TAP.
    validate_tap(out["tap"])
    points = [line.strip() for line in out["tap"].read_text().splitlines()
              if re.match(r"^\s+(not )?ok \d", line)]
    assert points == ["not ok 1 - twin", "ok 2 - twin", "not ok 3 - renamed mid-run"], points

    # CTRF JSON: a stable testId and this run's executionId, each one per test.
    validate_ctrf(out["json"])
    tests = json.loads(out["json"].read_text())["results"]["tests"]
    assert [(t["name"], t["status"]) for t in tests] == [
        (name, "failed" if failed else "passed") for name, failed, _ in EXPECTED]
    assert [t["testId"] for t in tests] == ["1.1", "1.2", "1.3"]
    assert len({t["executionId"] for t in tests}) == 3
    assert tests[0]["message"] == "the failing twin fails" and "message" not in tests[1]
    assert "fails before the rename" in tests[2]["message"]

    # The HTML report's data.
    html = out["html"].read_text()
    data = json.loads(html.split('id="report-data">', 1)[1].split("</script>", 1)[0])
    shown = data["suites"][0]["tests"]
    assert [(t["name"], t["state"]) for t in shown] == [
        (name, "failed" if failed else "passed") for name, failed, _ in EXPECTED]
    assert len({t["id"] for t in shown}) == 3
    texts = [[m["text"] for m in t["messages"]] for t in shown]
    assert any("the failing twin fails" in m for m in texts[0]), texts
    assert not any("twin" in m for m in texts[1]), texts
    assert any("fails before the rename" in m for m in texts[2]), texts
