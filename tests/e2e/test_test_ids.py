"""Every result goes to the test it is about, by the id its events carry: two tests of one
name in one suite stay apart, and a script that renames itself mid-run is followed, in every
output and in both isolation modes. Each repetition of a test has an id of its own too."""
import json
import re
import socket
import time
import xml.etree.ElementTree as ET

import pytest

from conftest import junit_display_names, run_runner, validate_ctrf, validate_junit, validate_tap
from web_run import WebRun, request

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
# Each one's id in the suite (docs/reference/test-ids.md): what every output names it by; the name it
# gives itself is shown beside it on the console and kept in the reports.
IDS = ["twin.py[--fail]", "twin.py", "renaming.py"]


def result_lines(text):
    """(word, name) of each per-test line of the console or text report, in order."""
    found = []
    for line in text.splitlines():
        m = re.match(r"^  (\S+(?: OUT)?)\s+(?:[^/ ]+/)?(.*?)  \(\d+\.\d+ s\)$", line)
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
    r = run_runner("--isolation", isolation, "--suite", suite.name,
                   "--output", "text:r.txt", "--output", "junit:r.xml",
                   "--output", "tap:r.tap", "--output", "json:r.json",
                   "--output", "html:r.html", cwd=tmp_path, timeout=90)
    assert r.returncode == 1, r
    expected_lines = [("FAILED" if failed else "passed", f"{key} ({name})")
                      for key, (name, failed, _) in zip(IDS, EXPECTED)]

    # The console and the text report.
    assert result_lines(r.stdout) == expected_lines, r.stdout
    text = out["txt"].read_text()
    assert result_lines(text) == expected_lines, text
    assert text.index("the failing twin fails") < text.index("passed      twin.py (twin)"), text

    # JUnit.
    validate_junit(out["xml"])
    root = ET.parse(out["xml"]).getroot()
    cases = list(root.iter("testcase"))
    assert [c.get("name") for c in cases] == IDS
    shown = junit_display_names(root)
    assert [shown.get(c) for c in cases] == [name for name, _, _ in EXPECTED]
    for case, (name, failed, problem) in zip(cases, EXPECTED):
        element = case.find("failure")
        assert (element is not None) == failed, ET.tostring(case)
        if problem:
            assert problem in ET.tostring(case, encoding="unicode")

    # TAP.
    validate_tap(out["tap"])
    points = [line.strip() for line in out["tap"].read_text().splitlines()
              if re.match(r"^\s+(not )?ok \d", line)]
    assert points == ["not ok 1 - twin.py[--fail]", "ok 2 - twin.py", "not ok 3 - renaming.py"], \
        points

    # CTRF JSON: a stable testId and this run's executionId, each one per test.
    validate_ctrf(out["json"])
    tests = json.loads(out["json"].read_text())["results"]["tests"]
    assert [(t["name"], t["extra"]["robotology.rtf"]["name"], t["status"]) for t in tests] == [
        (key, name, "failed" if failed else "passed") for key, (name, failed, _) in zip(IDS,
                                                                                      EXPECTED)]
    assert [t["extra"]["robotology.rtf"]["id"] for t in tests] == ["ids/" + key for key in IDS]
    assert [t["testId"] for t in tests] == ["1.1", "1.2", "1.3"]
    assert len({t["executionId"] for t in tests}) == 3
    assert tests[0]["message"] == "the failing twin fails" and "message" not in tests[1]
    assert "fails before the rename" in tests[2]["message"]

    # The HTML report's data.
    html = out["html"].read_text()
    data = json.loads(html.split('id="report-data">', 1)[1].split("</script>", 1)[0])
    shown = data["suites"][0]["tests"]
    assert [(t["name"], t["shown"], t["state"]) for t in shown] == [
        (key, name, "failed" if failed else "passed") for key, (name, failed, _) in zip(IDS,
                                                                                      EXPECTED)]
    assert len({t["id"] for t in shown}) == 3
    texts = [[m["text"] for m in t["messages"]] for t in shown]
    assert any("the failing twin fails" in m for m in texts[0]), texts
    assert not any("failing twin" in m for m in texts[1]), texts  # its own check only
    assert any("fails before the rename" in m for m in texts[2]), texts


# Fails in its second run only; says which run each message comes from.
SECOND_FAILS = """class TestCase:
    def setup(self, param):
        self.k = 0
        return True
    def run(self):
        self.k += 1
        robottestingframework.testReport("inside run %d" % self.k)
        robottestingframework.testCheck(self.k != 2, "run %d holds" % self.k)
"""


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_each_repetition_has_its_own_id_in_the_json_and_the_shapes_stay(
        tmp_path, isolation, suite_file):
    (tmp_path / "second.py").write_text(SECOND_FAILS)
    suite = suite_file("""<suite name="reps">
  <test type="python" repetition="3">second.py</test>
  <test type="python">second.py</test>
</suite>""")
    json_file, xml, tap = tmp_path / "r.json", tmp_path / "r.xml", tmp_path / "r.tap"
    r = run_runner("--isolation", isolation, "--suite", suite.name, "--output", "json:r.json",
                   "--output", "junit:r.xml", "--output", "tap:r.tap", cwd=tmp_path, timeout=90)
    assert r.returncode == 1, r
    validate_ctrf(json_file)
    tests = json.loads(json_file.read_text())["results"]["tests"]
    repeated, once = tests
    rid = repeated["executionId"]
    repetitions = repeated["extra"]["robotology.rtf"]["repetitions"]
    assert [(p["id"], p["index"], p["count"], p["state"]) for p in repetitions] == [
        (f"{rid}#1", 1, 3, "passed"), (f"{rid}#2", 2, 3, "failed"), (f"{rid}#3", 3, 3, "passed")]
    assert "run 2 holds" in repetitions[1]["message"], repetitions
    assert "message" not in repetitions[0] and "message" not in repetitions[2], repetitions
    assert all(p["duration"] >= 0 for p in repetitions)
    # A test that runs once is written as it always was.
    assert once["status"] == "passed" and "repetitions" not in once["extra"]["robotology.rtf"], once

    # JUnit and TAP keep one entry per test, the repetitions in its messages as before.
    validate_junit(xml)
    cases = list(ET.parse(xml).getroot().iter("testcase"))
    assert len(cases) == 2 and cases[0].find("failure") is not None, ET.tostring(cases[0])
    validate_tap(tap)
    points = [line.strip() for line in tap.read_text().splitlines()
              if re.match(r"^\s+(not )?ok \d", line)]
    assert [p.split(" - ")[0] for p in points] == ["not ok 1", "ok 2"], points


def web_events(port):
    """Every change the page's event stream replays from the start, as JSON."""
    stream = socket.create_connection(("127.0.0.1", port), timeout=10)
    stream.sendall(f"GET /events?since=0 HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n".encode())
    received = b""
    deadline = time.monotonic() + 30
    while b'"state":"finished"' not in received and time.monotonic() < deadline:
        received += stream.recv(65536)
    stream.close()
    return [json.loads(line[6:]) for line in received.decode().splitlines()
            if line.startswith("data: ")]


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_the_web_page_shows_the_repetition_each_message_came_in(tmp_path, isolation, suite_file):
    (tmp_path / "second.py").write_text(SECOND_FAILS)
    suite = suite_file("""<suite name="reps">
  <test type="python" repetition="3">second.py</test>
  <test type="python">second.py</test>
</suite>""")
    run = WebRun("--isolation", isolation, "-s", suite.name, "--web-linger", "60", cwd=tmp_path)
    try:
        run.wait_for_line("final page stays")
        snapshot = json.loads(request(run.port, "/snapshot")[2])
        repeated, once = snapshot["suites"][0]["tests"]
        rid = repeated["id"]
        assert repeated["repetition"] == f"{rid}#3", repeated
        came_in = {m["text"]: m.get("repetition") for m in repeated["messages"]}
        for k in (1, 2, 3):
            assert came_in[f"repetition {k}/3"] == f"{rid}#{k}", came_in
        # The failed check and its failure, both in the second repetition.
        assert {m["repetition"] for m in repeated["messages"]
                if "run 2 holds" in m["text"]} == {f"{rid}#2"}, came_in
        # A test that runs once is shown as it always was.
        assert "repetition" not in once and all("repetition" not in m for m in once["messages"])

        # The event stream carries the same ids. A replay sends the latest change of each test
        # (it carries the test's whole state), here its third repetition with every message.
        changes = [c["test"] for c in web_events(run.port)
                   if c.get("type") == "test" and c["test"]["id"] == rid]
        assert changes and changes[-1]["repetition"] == f"{rid}#3", changes
        streamed = {m["text"]: m.get("repetition") for m in changes[-1]["messages"]}
        assert streamed == came_in, streamed
        run.proc.send_signal(2)
        assert run.wait(timeout=10) == 1, run.output()
    finally:
        run.kill()
