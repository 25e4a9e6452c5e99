"""The Windows runner's default isolation (--isolation process): each test in a worker process
in a job object. The chaos suite, from its folder with relative paths: a passing and a failing
test, an access violation named by its exception code, a test spinning past its timeout (killed,
the run goes on), a test that exits, and a test that leaves a child process which must be gone
after it; every report format read back on Linux, and the runner's exit codes; Ctrl-C."""
import os
import signal
import subprocess
import time
import xml.etree.ElementTree as ET

from conftest import (RUNNER, WINE, copy_plugins, run_runner, validate_ctrf, validate_junit,
                      validate_tap)

CHAOS = """<?xml version="1.0" encoding="UTF-8"?>
<suite name="Chaos">
    <test name="first">../plugins/passing_test.dll</test>
    <test name="fails">failing_test</test>
    <test name="segv">../plugins/crash_segv.dll</test>
    <test name="spins" timeout="2">../plugins/hang_spin.dll</test>
    <test name="exits">../plugins/exit3.dll</test>
    <test name="leaves" param="--child ..\\plugins\\sleeper.exe --pid-file child.pid">../plugins/leaves_child.dll</test>
    <test name="gone" param="--pid-file child.pid">../plugins/child_gone.dll</test>
    <test name="last">../plugins/passing_test.dll</test>
</suite>
"""

# name: (JUnit state, the element's type, what its message says)
EXPECTED = {
    "first": ("passed", None, None),
    "fails": ("failure", "failure", "two and two make five"),
    "segv": ("error", "crash", "crashed: 0xC0000005 (access violation)"),
    "spins": ("failure", "timeout", "timed out after 2 s"),
    "exits": ("error", "error", "exited with status 3 before the test ended"),
    "leaves": ("passed", None, None),
    "gone": ("passed", None, None),
    "last": ("passed", None, None),
}


def write_chaos(tmp_path):
    copy_plugins(tmp_path / "plugins", "passing_test.dll", "crash_segv.dll", "hang_spin.dll",
                 "exit3.dll", "leaves_child.dll", "child_gone.dll", "sleeper.exe")
    copy_plugins(tmp_path / "suites", "libfailing_test.dll")
    (tmp_path / "suites" / "chaos.xml").write_text(CHAOS)
    return tmp_path / "suites"


def junit_cases(path):
    """{test name: (state, the <failure>/<error> element or None)}."""
    cases = {}
    for case in ET.parse(path).getroot().iter("testcase"):
        problem = case.find("failure")
        if problem is None:
            problem = case.find("error")
        state = "passed" if problem is None else problem.tag
        cases[case.get("name")] = (state, problem)
    return cases


def test_nothing_a_test_does_takes_the_run_down(tmp_path):
    suites = write_chaos(tmp_path)
    (suites / "out").mkdir()
    run = run_runner("-s", "chaos.xml", "-o", "junit:out/r.xml", "-o", "text:out/r.txt",
                     "-o", "tap:out/r.tap", "-o", "json:out/r.json", "-o", "html:out/r.html",
                     cwd=suites, timeout=180)
    assert run.returncode == 1, run  # tests failed; the run itself went through
    assert "4 passed, 4 failed" in run.stdout.splitlines()[-1], run
    assert "--isolation none" not in run.stderr, run  # no warning: the default isolation ran

    out = suites / "out"
    validate_junit(out / "r.xml")
    cases = junit_cases(out / "r.xml")
    assert set(cases) == set(EXPECTED), cases
    for name, (state, kind, says) in EXPECTED.items():
        got, problem = cases[name]
        assert got == state, (name, got, run)
        if kind is not None:
            assert problem.get("type") == kind, (name, problem.attrib)
            assert says in problem.get("message", "") + (problem.text or ""), (
                name, problem.attrib, problem.text)

    tap = validate_tap(out / "r.tap")  # the suite is one subtest, which failed
    assert (tap["ok"], tap["count"], tap["fail"]) == (False, 1, 1), tap
    tap_text = (out / "r.tap").read_text()
    assert "not ok 3 - segv" in tap_text and "severity: crash" in tap_text, tap_text
    assert "ok 8 - last" in tap_text, tap_text
    summary = validate_ctrf(out / "r.json")["results"]["summary"]
    assert (summary["tests"], summary["passed"], summary["failed"]) == (8, 4, 4), summary
    text = (out / "r.txt").read_text()
    assert "0xC0000005 (access violation)" in text and "timed out after 2 s" in text, text
    # What the crashing test said before it died is kept.
    assert "about to dereference a null pointer" in text, text
    html = (out / "r.html").read_text()
    assert html.lstrip().lower().startswith("<!doctype html") and "0xC0000005" in html

    # The child was started (its pid written), and ended with its test's job object.
    assert (suites / "child.pid").read_text().strip().isdigit()


def test_exit_codes(tmp_path):
    suites = write_chaos(tmp_path)
    (suites / "pass.xml").write_text(
        '<suite name="ok"><test>../plugins/passing_test.dll</test></suite>\n')
    passed = run_runner("-s", "pass.xml", "--no-output", cwd=suites)
    assert passed.returncode == 0 and "1 passed, 0 failed" in passed.stdout, passed
    crashed = run_runner("-t", "../plugins/crash_segv.dll", "--no-output", cwd=suites)
    assert crashed.returncode == 1, crashed
    assert "0xC0000005 (access violation)" in crashed.stdout, crashed
    # A timeout on the command line bounds every test, and the run goes on after it.
    timed = run_runner("-t", "../plugins/hang_spin.dll", "-t", "../plugins/passing_test.dll",
                       "--timeout", "1", "--no-output", cwd=suites)
    assert timed.returncode == 1, timed
    assert "timed out after 1 s" in timed.stdout and "1 passed, 1 failed" in timed.stdout, timed
    usage = run_runner("--no-such-option", cwd=suites)
    assert usage.returncode == 2, usage


def test_ctrl_c_stops_the_run_with_reports_written(tmp_path):
    copy_plugins(tmp_path, "leaves_child.dll", "hang_spin.dll", "passing_test.dll", "sleeper.exe")
    env = {**os.environ, "WINEDEBUG": "-all"}
    proc = subprocess.Popen([WINE, str(RUNNER), "-t", "leaves_child.dll", "-p",
                             "--child sleeper.exe --pid-file child.pid", "-t", "hang_spin.dll",
                             "-t", "passing_test.dll", "-o", "junit:r.xml"],
                            cwd=tmp_path, env=env, text=True, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, stdin=subprocess.DEVNULL)
    try:
        # Ctrl-C once the first test ran (its file written): the spinning test runs next.
        # Wine turns SIGINT into CTRL_C_EVENT.
        deadline = time.monotonic() + 60
        while not (tmp_path / "child.pid").exists() and time.monotonic() < deadline:
            time.sleep(0.2)
        assert (tmp_path / "child.pid").exists(), "the first test did not run"
        time.sleep(1)
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    assert proc.returncode == 130, (proc.returncode, out, err)
    assert "interrupted; stopping the running test" in out + err, (out, err)
    assert "1 passed, 2 failed" in out and "2 interrupted" in out, (out, err)
    validate_junit(tmp_path / "r.xml")
    assert "interrupted" in (tmp_path / "r.xml").read_text()


def test_abort_is_named_sigabrt_as_on_posix(tmp_path):
    # MinGW's abort() ends a program with status 3, as exit(3) does (exit3.dll, next door): the
    # worker tells the two apart, and the reports name the abort as POSIX does.
    copy_plugins(tmp_path, "crash_abort.dll", "exit3.dll")
    run = run_runner("-t", "crash_abort.dll", "-t", "exit3.dll", "-o", "junit:r.xml",
                     "-o", "text:r.txt", cwd=tmp_path)
    assert run.returncode == 1, run
    assert "crashed: SIGABRT (aborted)" in run.stdout, run
    validate_junit(tmp_path / "r.xml")
    cases = junit_cases(tmp_path / "r.xml")
    state, problem = cases["crash_abort.dll"]
    assert (state, problem.get("type")) == ("error", "crash"), (state, problem.attrib)
    # The message is the short name; the details keep the whole reason.
    assert problem.get("message") == "SIGABRT", problem.attrib
    assert "crashed: SIGABRT (aborted)" in problem.text, problem.text
    # What it said before it aborted is kept, as for any crash.
    assert "about to abort" in (tmp_path / "r.txt").read_text()
    state, problem = cases["exit3.dll"]
    assert "exited with status 3 before the test ended" in problem.get("message", ""), (
        problem.attrib)
    assert "SIGABRT" not in problem.get("message", ""), problem.attrib
