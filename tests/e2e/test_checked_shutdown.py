"""Checked shutdowns of the process fixture through the installed runner (docs/reference/world-file.md,
"Checked shutdowns"): a world process that exits otherwise than its <stop exit="..."> says, crashes
or outlives its grace when stopped fails the suite with a record of its own in every report,
named "world 'NAME': stop of 'PROCESS'", with the last lines of its log; an expected ending
passes; an unreadable expectation is a configuration error. Each test runs in both isolation
modes, from the suite's folder with relative paths; nothing is left behind (each run marks its
processes with an environment variable)."""
import json
import os
import signal
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from conftest import plugin, run_runner, validate_junit

STOPPER = Path(__file__).parent / "world" / "stopper.py"
PYTHON = "/usr/bin/python3"
MARK = "RTF_E2E_CHECKED_SHUTDOWN"
RECORD = "world 'lab': stop of 'server'"
ISOLATIONS = ["none", "process"]


def marked(mark):
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/environ", "rb") as f:
                if f"{MARK}={mark}".encode() in f.read().split(b"\0"):
                    found.append(int(entry))
        except OSError:
            continue
    return found


@pytest.fixture
def mark(request):
    value = f"{os.getpid()}-{time.monotonic_ns()}"
    yield value
    end = time.monotonic() + 3
    while marked(value) and time.monotonic() < end:
        time.sleep(0.02)
    left = marked(value)
    for pid in left:
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass
    assert not left, f"processes left behind: {left}"


def lab(folder, server_args, stop, test=None):
    """world.xml with the process 'server' (stopper.py SERVER_ARGS) stopped by `stop`, a clean
    'client' beside it, and suite.xml that starts it for a passing test; both in `folder`."""
    (folder / "world.xml").write_text(f"""<world name="lab" logdir="logs">
  <process name="client" command="{PYTHON} -u {STOPPER} default">
    <ready timeout="10s"><output>^ready$</output></ready>
  </process>
  <process name="server" command="{PYTHON} -u {STOPPER} {server_args}">
    <ready timeout="10s"><output>^ready$</output></ready>
    {stop}
  </process>
</world>
""")
    (folder / "suite.xml").write_text(f"""<suite name="lab suite">
  <fixture type="process">world.xml</fixture>
  {test or f"<test>{plugin('passing_test')}</test>"}
</suite>
""")


def run(folder, mark, isolation, *more):
    return run_runner("--isolation", isolation, "-s", "suite.xml", "-o", "junit:r.xml",
                      "-o", "tap:r.tap", "-o", "json:r.json", "-o", "text:r.txt",
                      "-o", "html:r.html", *more, cwd=folder, env={MARK: mark}, timeout=90)


def junit_cases(folder):
    validate_junit(folder / "r.xml")
    root = ET.parse(folder / "r.xml").getroot()
    return {case.get("name"): case for case in root.iter("testcase")}


def json_tests(folder):
    return {test["name"]: test for test in json.loads((folder / "r.json").read_text())
            ["results"]["tests"]}


def expect_stop_record(folder, r, words):
    """The run failed with RECORD, a failed record of its own saying `words`, in every report;
    the test passed; the clean client has no record; the suite has no tear-down error."""
    assert r.returncode == 1, r
    cases = junit_cases(folder)
    assert len(cases) == 2 and RECORD in cases, cases.keys()
    failure = cases[RECORD].find("failure")
    assert failure is not None, ET.tostring(cases[RECORD])
    text = (failure.get("message") or "") + (failure.text or "")
    for w in words:
        assert w in text, text
    others = [name for name in cases if name != RECORD]
    assert len(others) == 1 and cases[others[0]].find("failure") is None, cases.keys()
    assert cases[others[0]].find("error") is None, ET.tostring(cases[others[0]])
    assert "stop of 'client'" not in (folder / "r.xml").read_text()
    assert "tearDown failed" not in (folder / "r.xml").read_text()
    # TAP: a test point of its own.
    tap = (folder / "r.tap").read_text()
    assert f"not ok 2 - {RECORD}" in tap, tap
    assert "ok 1 - " in tap, tap
    # CTRF JSON: a failed test of its own, its log attached to it.
    tests = json_tests(folder)
    assert tests[RECORD]["status"] == "failed", tests[RECORD]
    for w in words:
        assert w in tests[RECORD]["message"], tests[RECORD]
    attachments = json.dumps(tests[RECORD].get("attachments", []))
    assert "server.log" in attachments, tests[RECORD]
    # HTML: a row of its own, failed.
    html = (folder / "r.html").read_text()
    assert f'"name":"{RECORD}","state":"failed"' in html, html[:2000]
    # Text output and console.
    txt = (folder / "r.txt").read_text()
    assert RECORD in txt and words[0] in txt, txt
    assert RECORD in r.output, r


@pytest.mark.parametrize("isolation", ISOLATIONS)
def test_a_process_that_exits_1_on_sigint_fails_the_suite_with_a_record_of_its_own(
        tmp_path, mark, isolation):
    lab(tmp_path, "exit 1", '<stop signal="SIGINT" grace="3s"/>')
    r = run(tmp_path, mark, isolation)
    expect_stop_record(tmp_path, r, [
        "'server' exited with status 1 after SIGINT; a clean stop is: status 0 or SIGINT, "
        "within 3 s",
        "| got SIGINT: saving the map", "| cannot save the map: exiting with status 1",
        "logs/server.log"])
    # --rerun-failed runs the whole suite again, its world with it.
    again = run_runner("--isolation", isolation, "-s", "suite.xml", "--rerun-failed", "r.xml",
                       "-o", "junit:again.xml", cwd=tmp_path, env={MARK: mark}, timeout=90)
    assert again.returncode == 1, again
    assert "none of its" not in again.output, again
    rerun = (tmp_path / "again.xml").read_text()
    assert "passing_test" in rerun and RECORD in rerun, rerun


@pytest.mark.parametrize("isolation", ISOLATIONS)
def test_a_process_that_aborts_when_stopped_is_a_crash_on_stop(tmp_path, mark, isolation):
    lab(tmp_path, "abort", "")
    r = run(tmp_path, mark, isolation)
    expect_stop_record(tmp_path, r, [
        "SIGABRT", "after SIGTERM; a clean stop is: status 0 or SIGTERM, within 5 s",
        "| aborting"])


@pytest.mark.parametrize("isolation", ISOLATIONS)
def test_a_process_that_ignores_sigterm_beyond_its_grace_fails(tmp_path, mark, isolation):
    lab(tmp_path, "ignore", '<stop grace="300ms"/>')
    began = time.monotonic()
    r = run(tmp_path, mark, isolation)
    assert time.monotonic() - began < 30, r
    # What it was doing when its grace ended, read before it was killed: where it waited, and
    # that it ignores the stop signal.
    expect_stop_record(tmp_path, r, [
        "'server' did not stop within 300 ms of SIGTERM: killed with SIGKILL; a clean stop is: "
        "status 0 or SIGTERM, within 300 ms", "| ready",
        "when its grace ended it was sleeping in 1 thread: ", "; SIGTERM ignored"])


@pytest.mark.parametrize("isolation", ISOLATIONS)
def test_an_expected_exit_status_is_a_clean_stop(tmp_path, mark, isolation):
    lab(tmp_path, "exit 1", '<stop signal="SIGINT" grace="3s" exit="1"/>')
    r = run(tmp_path, mark, isolation, "-v")
    assert r.returncode == 0, r
    assert "'server' stopped after" in r.output, r
    assert "it exited with status 1 (clean)" in r.output, r
    # The client ends by its stop signal's default action: clean by default.
    assert "it was killed by signal SIGTERM (clean)" in r.output, r
    cases = junit_cases(tmp_path)
    assert len(cases) == 1, cases.keys()  # clean stops add nothing to the reports
    assert "stop of" not in (tmp_path / "r.tap").read_text()
    assert list(json_tests(tmp_path)) == list(cases), json_tests(tmp_path).keys()


@pytest.mark.parametrize("isolation", ISOLATIONS)
def test_an_unreadable_expectation_is_a_configuration_error(tmp_path, mark, isolation):
    lab(tmp_path, "default", '<stop signal="SIGINT"\n        exit="zero"/>')
    r = run(tmp_path, mark, isolation)
    assert r.returncode == 2, r
    assert ("world.xml:7: <stop exit=\"zero\">: expected a comma-separated list of exit "
            "statuses (0-255) and signal names (SIGINT, TERM), or 'any'; 'zero' is neither"
            in r.output), r
    assert not (tmp_path / "logs").exists()  # nothing was started


@pytest.mark.parametrize("isolation", ISOLATIONS)
def test_a_process_that_dies_while_the_suite_runs_collapses_it_and_has_no_stop_record(
        tmp_path, mark, isolation):
    waiting = f'<test param="--seconds 5">{plugin("waiting_test")}</test>'
    lab(tmp_path, "die 0.3 1", '<stop signal="SIGINT" grace="3s"/>', test=waiting)
    r = run(tmp_path, mark, isolation)
    assert r.returncode == 1, r
    assert "collapsed" in r.output and "giving up: exiting with status 1" in r.output, r
    for report in ("r.xml", "r.tap", "r.json", "r.txt"):
        assert "stop of" not in (tmp_path / report).read_text(), report
    validate_junit(tmp_path / "r.xml")
