"""A process fixture's log files (rtf-logs/, or the world's logdir) are attached to its suite
once its processes stopped (issue 22, item 3): every report links them as it links a test's
attachments (CTRF, JUnit [[ATTACHMENT|...]], TAP YAML, HTML), read back by the third-party
readers; a log over the attachment limits is not attached and the suite says so, without
failing. In-process and isolated, one suite at a time and two at once (-j 2)."""
import json
import os
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from conftest import run_runner, validate_ctrf, validate_junit, validate_tap

PASSING = "class TestCase:\n    def run(self):\n        robottestingframework.testReport('ok')\n"


def write_world(folder, name):
    """A world of two processes that each print a line naming their suite, then wait."""
    processes = "".join(
        f'  <process name="{process}" command="/bin/sh -c \'echo {process} of {name} up; '
        f'exec sleep 30\'">\n    <ready timeout="20s"><output>^{process} of {name} up$</output>'
        f'</ready>\n  </process>\n' for process in ("broker", "robot"))
    (folder / f"{name}.world.xml").write_text(f'<world name="{name}">\n{processes}</world>\n')
    (folder / "ok.py").write_text(PASSING)
    (folder / f"{name}.xml").write_text(
        f'<suite name="{name}">\n  <fixture type="process">{name}.world.xml</fixture>\n'
        f'  <test name="ok">ok.py</test>\n</suite>\n')


def html_data(path):
    text = path.read_text()
    return json.loads(text.split('id="report-data">', 1)[1].split("</script>", 1)[0])


@pytest.mark.parametrize("isolation,jobs", [("none", "1"), ("process", "1"), ("process", "2")])
def test_the_process_logs_are_attachments_of_the_suite_in_every_report(tmp_path, isolation, jobs):
    for name in ("arm", "base"):
        write_world(tmp_path, name)
    (tmp_path / "reports").mkdir()
    r = run_runner("--isolation", isolation, "-j", jobs, "--suite", "arm.xml", "--suite",
                   "base.xml", "-o", "junit:reports/r.xml", "-o", "tap:reports/r.tap",
                   "-o", "json:reports/r.json", "-o", "html:reports/r.html", cwd=tmp_path,
                   timeout=150)
    assert r.returncode == 0, r
    expected = {(suite, f"{process}.log"): f"{process} of {suite} up\n"
                for suite in ("arm", "base") for process in ("broker", "robot")}
    # The logs themselves stay where the fixture wrote them.
    for (suite, log), text in expected.items():
        assert (tmp_path / "rtf-logs" / suite / log).read_text() == text

    # CTRF: schema-valid; each suite's attachments beside its time, as a test's are.
    report = validate_ctrf(tmp_path / "reports" / "r.json")
    suites = report["results"]["extra"]["robotology.rtf"]["suites"]
    seen = {}
    for suite in suites:
        for attachment in suite["attachments"]:
            assert attachment["contentType"] == "text/plain", attachment
            assert attachment["extra"]["robotology.rtf"]["description"] == \
                "log of process " + attachment["name"][:-len(".log")]
            seen[(suite["name"], attachment["name"])] = \
                (tmp_path / "reports" / attachment["path"]).read_text()
    assert seen == expected, suites
    for test in report["results"]["tests"]:
        assert "attachments" not in test, test

    # JUnit: valid for the readers; [[ATTACHMENT|absolute path]] in each suite's <system-out>.
    validate_junit(tmp_path / "reports" / "r.xml")
    seen = {}
    for suite in ET.parse(tmp_path / "reports" / "r.xml").getroot().iter("testsuite"):
        out = suite.find("system-out")
        for line in (out.text if out is not None and out.text else "").splitlines():
            if line.startswith("[[ATTACHMENT|") and line.endswith("]]"):
                path = Path(line[len("[[ATTACHMENT|"):-2])
                assert path.is_absolute(), line
                seen[(suite.get("name"), path.name.split("-", 1)[1])] = path.read_text()
    assert seen == expected

    # TAP: strict-valid; the YAML block of each suite's own point lists its logs.
    parsed = validate_tap(tmp_path / "reports" / "r.tap")
    seen = {}
    for point in parsed["points"]:
        if point["depth"] == 0:
            for attachment in (point["diag"] or {}).get("attachments", []):
                seen[(point["name"], attachment["name"])] = \
                    (tmp_path / "reports" / attachment["path"]).read_text()
    assert seen == expected, parsed["points"]

    # HTML: each suite's links (its messages do not repeat them).
    data = html_data(tmp_path / "reports" / "r.html")
    seen = {}
    for suite in data["suites"]:
        for attachment in suite["attachments"]:
            seen[(suite["name"], attachment["name"])] = \
                (tmp_path / "reports" / attachment["path"]).read_text()
        assert not [m for m in suite["messages"] if m["label"] == "attachment"], suite
    assert seen == expected


@pytest.mark.parametrize("isolation", ["none", "process"])
def test_a_log_over_the_limit_is_not_attached_and_the_suite_says_so(tmp_path, isolation):
    write_world(tmp_path, "arm")
    r = run_runner("--isolation", isolation, "--suite", "arm.xml", "-o", "json:r.json",
                   cwd=tmp_path, env={"RTF_ATTACHMENT_MAX_FILE": "10"})
    assert r.returncode == 0, r  # a log the report cannot hold fails nothing
    report = validate_ctrf(tmp_path / "r.json")
    suite = report["results"]["extra"]["robotology.rtf"]["suites"][0]
    assert "attachments" not in suite, suite
    refused = [m["message"] for m in suite["messages"] if "not attached" in m["message"]]
    assert len(refused) == 2 and all("broker.log" in m or "robot.log" in m for m in refused), \
        suite["messages"]
    assert os.path.exists(tmp_path / "rtf-logs" / "arm" / "robot.log")


@pytest.mark.parametrize("isolation", ["none", "process"])
def test_two_suites_of_one_world_file_each_keep_their_own_logs(tmp_path, isolation):
    # Issue 39, 3: the README's own case, two suites starting robot.world.xml at once (-j 2),
    # wrote both worlds into rtf-logs/robot/*.log: each suite's attachment mixed both worlds'
    # lines, and one world's first line was lost.
    (tmp_path / "robot.world.xml").write_text("".join(
        ['<world name="robot">\n'] +
        [f'  <process name="{process}" command="/bin/sh -c \'echo {process} of ${{who}} up; '
         f'exec sleep 30\'">\n    <ready timeout="20s"><output>^{process} of ${{who}} up$'
         f'</output></ready>\n  </process>\n' for process in ("broker", "robot")] +
        ["</world>\n"]))
    # Long enough for the two worlds to be up at once.
    (tmp_path / "slow.py").write_text("import time\n\n\nclass TestCase:\n    def run(self):\n"
                                      "        time.sleep(1.5)\n")
    for name in ("left", "right"):
        (tmp_path / f"{name}.xml").write_text(
            f'<suite name="{name}">\n  <variable name="who">{name}</variable>\n'
            '  <fixture type="process">robot.world.xml</fixture>\n'
            '  <test name="slow">slow.py</test>\n</suite>\n')
    r = run_runner("--isolation", isolation, "-j", "2", "--suite", "left.xml", "--suite",
                   "right.xml", "-o", "json:r.json", cwd=tmp_path, timeout=150)
    assert r.returncode == 0, r
    expected = {(suite, f"{process}.log"): f"{process} of {suite} up\n"
                for suite in ("left", "right") for process in ("broker", "robot")}
    # One folder per suite under the world's log folder, named after the suite.
    for (suite, log), text in expected.items():
        assert (tmp_path / "rtf-logs" / "robot" / suite / log).read_text() == text
    seen = {}
    for suite in validate_ctrf(tmp_path / "r.json")["results"]["extra"]["robotology.rtf"][
            "suites"]:
        for attachment in suite["attachments"]:
            seen[(suite["name"], attachment["name"])] = (tmp_path / attachment["path"]).read_text()
    assert seen == expected


def test_two_world_files_of_one_name_each_keep_their_own_logs(tmp_path):
    # Issue 38's second trial: two suites' folders, each with its own world.xml, both
    # <world name="robot">, run at once (-j 2): both wrote rtf-logs/robot/*.log (the log folder
    # is the world's name), each suite's attachment the other's lines. As for one world file
    # started by two suites, each suite's logs go to rtf-logs/robot/<suite>/.
    for name in ("left", "right"):
        folder = tmp_path / name
        folder.mkdir()
        (folder / "world.xml").write_text(
            '<world name="robot">\n'
            f'  <process name="robot" command="/bin/sh -c \'echo {name} robot up; '
            f'exec sleep 30\'">\n    <ready timeout="20s"><output>^{name} robot up$'
            '</output></ready>\n  </process>\n</world>\n')
        (folder / "slow.py").write_text("import time\n\n\nclass TestCase:\n    def run(self):\n"
                                        "        time.sleep(1.5)\n")
        (folder / "suite.xml").write_text(
            f'<suite name="{name}">\n  <fixture type="process">world.xml</fixture>\n'
            '  <test name="slow">slow.py</test>\n</suite>\n')
    r = run_runner("-j", "2", "--suite", "left/suite.xml", "--suite", "right/suite.xml",
                   "-o", "json:r.json", cwd=tmp_path, timeout=150)
    assert r.returncode == 0, r
    for suite in ("left", "right"):
        assert (tmp_path / "rtf-logs" / "robot" / suite / "robot.log").read_text() == \
            f"{suite} robot up\n"
    seen = {}
    for suite in validate_ctrf(tmp_path / "r.json")["results"]["extra"]["robotology.rtf"][
            "suites"]:
        for attachment in suite["attachments"]:
            seen[suite["name"]] = (tmp_path / attachment["path"]).read_text()
    assert seen == {"left": "left robot up\n", "right": "right robot up\n"}
