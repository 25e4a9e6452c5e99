"""Issue 38, friction 9: one line per failed check, and a TAP point's YAML block read, not
pasted. A failed check showed both a "check FAILED:" and a "failure:" line; a point's YAML
`measurements:` was pasted into the check's text (`check ok: ok 3 - loop rate: measurements:
- name: ...`). Through the installed runner, from the suite's folder."""
import json
import re
import signal
import subprocess
import time
import xml.etree.ElementTree as ET
from xml.etree import ElementTree

import pytest

from conftest import (leftover_processes, marked, plugin, run_runner, start_runner,
                      validate_ctrf, validate_junit, validate_tap)
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
        # The other keys are the check's diagnostics: a block under its line, not its text.
        assert "note: fast enough" not in r.stdout.split("loop rate")[1].splitlines()[0]
        assert re.search(r"check ok: ok 3 - loop rate \[\S+points.sh:\d+\]\n +note: fast enough\n",
                         r.stdout), r.stdout
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


# A failing point's YAML block as node-tap and TAP 14's examples write one: message, severity,
# found/wanted, at (a map), data (a list), a key of the program's own (given twice: its last
# value, once).
DIAGNOSED = """#!/bin/sh
echo 'TAP version 14'
echo '1..2'
echo 'not ok 1 - gripper closes'
echo '  ---'
echo '  message: "the gripper is still open"'
echo '  severity: fail'
echo '  found: 3'
echo '  wanted: 4'
echo '  at:'
echo '    file: gripper.c'
echo '    line: 12'
echo '  data:'
echo '    - 1'
echo '    - 2'
echo '  torque: 0.4 Nm'
echo '  torque: 0.5 Nm'
echo '  ...'
echo 'ok 2 - arm moves'
"""
KEYS = {"message": "the gripper is still open", "severity": "fail", "found": "3", "wanted": "4",
        "at": "file: gripper.c\nline: 12", "data": "- 1\n- 2", "torque": "0.5 Nm"}
BLOCK = ["message: the gripper is still open", "severity: fail", "found: 3", "wanted: 4", "at:",
         "  file: gripper.c", "  line: 12", "data:", "  - 1", "  - 2", "torque: 0.5 Nm"]


def block_under(text, line):
    """The lines under the first line of `text` that contains `line`, unindented by the first
    one's indent, as long as they are indented deeper than that line."""
    lines = text.splitlines()
    at = next(i for i, l in enumerate(lines) if line in l)
    depth = len(lines[at]) - len(lines[at].lstrip())
    found = []
    for l in lines[at + 1:]:
        if len(l) - len(l.lstrip()) <= depth:
            break
        found.append(l)
    first = len(found[0]) - len(found[0].lstrip()) if found else 0
    return [l[first:] for l in found]


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_points_yaml_keys_are_diagnostics_in_every_report(tmp_path, jobs):
    """Issue 38, friction 9: the keys of a point's YAML block other than measurements and
    attachments were pasted into the check's one-line text. They are its diagnostics: a block of
    their own under the line on the console and in the text report, the <failure> body and
    <system-out> of JUnit (xmllint with junit-10.xsd, junitparser), a YAML map re-emitted in the
    TAP report (tap-parser), a "diagnostics" object in CTRF (its schema), and a block of its own
    in the HTML report's data; the one-line text is the point's alone everywhere."""
    (tmp_path / "gripper.sh").write_text(DIAGNOSED)
    (tmp_path / "gripper.sh").chmod(0o755)
    (tmp_path / "suite.xml").write_text("""<suite name="robot">
  <test type="exec">gripper.sh</test>
</suite>
""")
    r = run_runner("-s", "suite.xml", "-j", jobs, "-o", "junit:r.xml", "-o", "tap:r.tap",
                   "-o", "json:r.json", "-o", "text:r.txt", "-o", "html:r.html", cwd=tmp_path)
    assert r.returncode == 1, r
    line = "failure: not ok 1 - gripper closes ["
    for text in (r.stdout, (tmp_path / "r.txt").read_text()):
        said = next(l for l in text.splitlines() if line in l)
        assert said.rstrip().endswith("gripper.sh:3]"), text  # nothing pasted after it
        assert block_under(text, line) == BLOCK, text
        assert text.count("the gripper is still open") == 1, text
    # JUnit: message= is the point; the body says the point, then its diagnostics under it.
    validate_junit(tmp_path / "r.xml")
    case = ElementTree.parse(tmp_path / "r.xml").getroot().find(".//testcase")
    failure = case.find("failure")
    assert failure.get("message") == "not ok 1 - gripper closes", failure.attrib
    assert block_under(failure.text, line) == BLOCK, failure.text
    assert block_under(case.find("system-out").text, "check FAILED: not ok 1") == BLOCK
    # TAP: tap-parser reads the keys back from the test's YAML block.
    tap = validate_tap(tmp_path / "r.tap")
    point = next(p for p in tap["points"] if p["name"] == "gripper.sh")
    assert point["diag"]["message"] == "not ok 1 - gripper closes", point
    assert point["diag"]["diagnostics"] == KEYS, point
    failed_check = next(m for m in point["diag"]["messages"]
                        if isinstance(m, dict) and "check FAILED" in m["text"])
    assert failed_check["diagnostics"] == KEYS, point
    # CTRF: the test's message is the point; its trace has the block; its reports the keys.
    report = validate_ctrf(tmp_path / "r.json")
    test = report["results"]["tests"][0]
    assert test["message"] == "not ok 1 - gripper closes", test
    assert block_under(test["trace"], "failure: not ok 1") == BLOCK, test["trace"]
    checks = test["extra"]["robotology.rtf"]["reports"]
    failed = next(c for c in checks if c["kind"] == "check FAILED")
    assert failed["message"] == "not ok 1 - gripper closes", checks
    assert failed["diagnostics"] == KEYS, checks
    assert list(failed["diagnostics"]) == list(KEYS)  # in the program's order
    # HTML: the page's data gives each message its diagnostics apart from its text.
    html = (tmp_path / "r.html").read_text()
    assert '"text":"not ok 1 - gripper closes"' in html, html[:2000]
    assert '"diagnostics":"message: the gripper is still open\\nseverity: fail' in html


# --- A world that fails to start, and tests never run ----------------------------------------

SKIPPED = "skipped: the suite's fixture failed (see the suite's error)"
NOT_RUN = "interrupted: not run: the run was stopped before it started"


def one_line_reason(message):
    """A skipped test's message: the fixture's failure in one line, referring to the suite's
    error for the rest (its log's tail is not repeated)."""
    return (message.startswith("the suite's fixture failed (see the suite's error): fixture ")
            and "exited with status 3" in message and "third-said" not in message
            and "\n" not in message)


def skipped_lines(text):
    """The lines of a console or text report that say a test was skipped for its suite's
    fixture, each in one line that gives the reason's first line."""
    lines = [re.sub(r"^\[[0-9.]+ s\] ", "", l.strip()) for l in text.splitlines()]
    return [l for l in lines if l.startswith(SKIPPED) and one_line_reason(l[len("skipped: "):])]


def failing_world(tmp_path):
    """Two suites of three tests, each with a process fixture (a world) that says three lines
    and exits before it is ready; its reason (the deadline, command, folder, log tail) is 8
    lines."""
    (tmp_path / "world.xml").write_text("""<world name="lab" logdir="logs">
  <process name="robot" command="sh -c 'echo first-said; echo second-said; echo third-said; exit 3'">
    <ready timeout="20s"><output>^ready$</output></ready>
  </process>
</world>
""")
    for name in ("a", "b", "c"):
        (tmp_path / f"{name}.sh").write_text("#!/bin/sh\nexit 0\n")
        (tmp_path / f"{name}.sh").chmod(0o755)
    args = []
    for suite in ("arm", "base"):
        (tmp_path / f"{suite}.xml").write_text(f"""<suite name="{suite}">
  <fixture type="process">world.xml</fixture>
  <test type="exec">a.sh</test>
  <test type="exec">b.sh</test>
  <test type="exec">c.sh</test>
</suite>
""")
        args += ["-s", f"{suite}.xml"]
    return args


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_world_that_fails_to_start_is_said_once_and_each_skipped_test_in_a_line(
        tmp_path, marker, jobs):
    """The whole multi-line reason of a world that did not start was printed again under each
    skipped test (58 console lines for 6 tests, the second trial of the first hour). It is said
    once, by the suite's error; each skipped test has one line referring to it, on the console
    (-j 1 and -j 2) and in every report."""
    args = failing_world(tmp_path)
    r = run_runner(*args, "-j", jobs, "-o", "junit:r.xml", "-o", "text:r.txt", "-o",
                   "html:r.html", "-o", "tap:r.tap", "-o", "json:r.json", cwd=tmp_path,
                   env=marked(marker))
    assert r.returncode == 1, r
    # The reason's last line (the log's tail) once per suite, not once per test.
    assert r.stdout.count("| third-said") == 2, r.stdout
    # In each suite's reason, and in the one line of each of the 6 skipped tests.
    assert r.stdout.count("exited with status 3") == 2 + 6, r.stdout
    assert len(skipped_lines(r.stdout)) == 6, r.stdout
    assert "6 skipped" in r.stdout.splitlines()[-1], r.stdout
    # 2 suites of 3 tests: a line per suite, per test and its skip, the two reasons (8 lines
    # each), the suites' ends and the summary; 58 when each test repeated the reason.
    assert len(r.stdout.splitlines()) <= 42, (len(r.stdout.splitlines()), r.stdout)

    text = (tmp_path / "r.txt").read_text()
    assert len(skipped_lines(text)) == 6, text
    # The fixture's own report of it and the suite's error; none under a test.
    assert text.count("| third-said") <= 4, text
    validate_junit(tmp_path / "r.xml")
    root = ET.parse(tmp_path / "r.xml").getroot()
    skips = [s.get("message") for s in root.iter("skipped")]
    # Each skipped test says why in one line (a Jenkins page of one test case read alone),
    # without the log's tail: that is the suite's error only.
    assert len(skips) == 6 and all(one_line_reason(s) for s in skips), skips
    errors = [e.get("message") for e in root.iter("error")]
    assert len(errors) == 2 and all("third-said" in e for e in errors), errors
    validate_tap(tmp_path / "r.tap")
    tap = (tmp_path / "r.tap").read_text()
    skips = [l.split("# SKIP ", 1)[1] for l in tap.splitlines() if "# SKIP the suite's" in l]
    assert len(skips) == 6 and all(one_line_reason(s) for s in skips), tap
    validate_ctrf(tmp_path / "r.json")
    ctrf = json.loads((tmp_path / "r.json").read_text())
    messages = [t.get("message", "") for t in ctrf["results"]["tests"]
                if t["status"] == "skipped"]
    assert len(messages) == 6 and all(one_line_reason(m) for m in messages), messages
    html = (tmp_path / "r.html").read_text()
    data = json.loads(html.split('id="report-data">', 1)[1].split("</script>", 1)[0])
    for suite in data["suites"]:
        for test in suite["tests"]:
            assert "third-said" not in json.dumps(test), test
    assert not leftover_processes(marker)


def finish(proc, timeout=30):
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        out, err = proc.communicate()
        pytest.fail(f"the runner did not end within {timeout} s\n{out}\n{err}")
    return proc.returncode, out, err


@pytest.mark.parametrize("jobs, isolation", [("1", "none"), ("2", "none"), ("2", "process")])
def test_tests_an_interrupt_stopped_or_never_started_say_what_happened(
        tmp_path, marker, jobs, isolation):
    """Tests never run because of Ctrl-C read "interrupted: interrupted", and in process the
    running one "interrupted: interrupted while running": the message repeated the kind's
    word. It says what happened, in the same words in process and in a worker."""
    (tmp_path / "hold.xml").write_text(f"""<suite name="hold">
  <test name="hung" param="--seconds 60">{plugin("waiting_test")}</test>
  <test name="after">{plugin("passing_test")}</test>
</suite>
""")
    (tmp_path / "later.xml").write_text(f"""<suite name="later">
  <test name="hung2" param="--seconds 60">{plugin("waiting_test")}</test>
  <test name="never">{plugin("passing_test")}</test>
</suite>
""")
    (tmp_path / "last.xml").write_text(f"""<suite name="last">
  <test name="never2">{plugin("passing_test")}</test>
</suite>
""")
    proc = start_runner("-s", "hold.xml", "-s", "later.xml", "-s", "last.xml", "-j", jobs,
                        "--isolation", isolation, "-o", "junit:r.xml", cwd=tmp_path,
                        env=marked(marker))
    time.sleep(1.5)
    proc.send_signal(signal.SIGINT)
    code, out, err = finish(proc)
    assert code == 130, (code, out, err)
    assert "interrupted: interrupted" not in out, out
    assert "interrupted while running" not in out, out
    # The tests running then: in process the suites run one at a time at any -j.
    stopped = out.count("      interrupted: stopped while running")
    assert stopped == (2 if isolation == "process" else 1), out
    assert out.count(f"      {NOT_RUN}\n") == 5 - stopped, out
    validate_junit(tmp_path / "r.xml")
    assert not leftover_processes(marker)
