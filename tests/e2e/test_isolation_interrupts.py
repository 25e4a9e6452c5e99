"""Ctrl-C and SIGTERM: the running test is stopped, tear-downs run, the outputs are written with
what finished and the rest interrupted, the exit status says so (130 SIGINT, 143 SIGTERM); a
second Ctrl-C ends at once; nothing the run started survives it, even a SIGKILL of the runner."""
import json
import signal
import time
import xml.etree.ElementTree as ET

import pytest

from conftest import (_marked_processes, finish_runner, wait_for, junit_state, leftover_processes, marked, plugin,
                      start_runner, validate_junit)


def statuses(junit):
    return {case.get("name"): junit_state(case)
            for case in ET.parse(junit).getroot().iter("testcase")}


def lines(path):
    return path.read_text().splitlines() if path.exists() else []


# A test that blocks until stopped: hang_block ignores everything but a signal, so in-process
# mode uses waiting_test, which listens to TestCase::interrupt.
BLOCKER = {"process": ("hang_block", ""), "none": ("waiting_test", "--seconds 60")}


@pytest.mark.parametrize("isolation", ["process", "none"])
@pytest.mark.parametrize("signum, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_interrupt_tears_down_writes_outputs_and_exits_non_zero(tmp_path, marker, isolation,
                                                                 signum, status):
    log = tmp_path / "fixture.log"
    blocker, param = BLOCKER[isolation]
    suite = tmp_path / "suite.xml"
    suite.write_text(f'''<suite name="interrupted">
  <fixture param="--log {log} --name world">{plugin("order_fixture")}</fixture>
  <test name="done">{plugin("passing_test")}</test>
  <test name="hung" param="{param}">{plugin(blocker)}</test>
  <test name="after">{plugin("passing_test")}</test>
</suite>''')
    later = tmp_path / "later.xml"
    later.write_text(f'<suite name="later"><test name="never">{plugin("passing_test")}</test></suite>')
    junit = tmp_path / "out.xml"
    text = tmp_path / "out.txt"
    proc = start_runner("--isolation", isolation, "--suite", suite.name, "--suite", later.name,
                        "--output", f"junit:{junit.name}", "--output", f"text:{text.name}",
                        env=marked(marker), cwd=tmp_path)
    # The fixture is checked before each test: the second check comes before "hung".
    wait_for(lambda: lines(log).count("check world") >= 2, what="the blocking test")
    time.sleep(0.5)
    proc.send_signal(signum)
    code, out, err = finish_runner(proc)
    assert code == status, (code, out, err)
    assert lines(log)[-1] == "teardown world", lines(log)
    validate_junit(junit)
    assert statuses(junit) == {"done": "passed", "hung": "interrupted",
                               "after": "interrupted", "never": "interrupted"}, out
    assert "INTERRUPTED" in text.read_text()
    assert "interrupted" in out.splitlines()[-1] or "failed" in out.splitlines()[-1], out
    # The console puts the kind's word before the message, which does not say it again (it
    # did: "interrupted: interrupted: last reported: ...", in process "interrupted: interrupted
    # while running", and "interrupted: interrupted" for each test never started). The same
    # words in process and in a worker (issue 38, friction 9).
    assert "      interrupted: stopped while running" in out, out
    assert "interrupted: interrupted" not in out, out
    assert "interrupted while running" not in out, out
    # "after" (its suite stopped) and "never" (a later suite): one line each, saying why.
    assert out.count("      interrupted: not run: the run was stopped before it started\n") == 2, out
    assert leftover_processes(marker) == []


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_a_second_ctrl_c_ends_at_once_and_leaves_nothing(tmp_path, marker, isolation):
    # fork_sleeper --hang leaves a child and blocks; in-process nothing can stop it politely,
    # so only the second Ctrl-C ends the run.
    suite = tmp_path / "suite.xml"
    suite.write_text(f'''<suite name="stubborn">
  <test name="stubborn" param="--hang">{plugin("fork_sleeper")}</test>
</suite>''')
    junit = tmp_path / "out.xml"
    proc = start_runner("--isolation", isolation, "--suite", suite.name, "--output",
                        f"junit:{junit.name}", env=marked(marker), cwd=tmp_path)
    # The runner (and server), the test's process and its child: wait for the child.
    expected = 4 if isolation == "process" else 2
    wait_for(lambda: len(_marked_processes(marker)) >= expected, what="the sleeping child")
    proc.send_signal(signal.SIGINT)
    time.sleep(0.3)
    proc.send_signal(signal.SIGINT)
    begin = time.monotonic()
    code, out, err = finish_runner(proc, timeout=10)
    assert time.monotonic() - begin < 5
    assert code == 130, (code, out, err)
    assert leftover_processes(marker) == []


def test_sigkill_of_the_runner_leaves_no_process(tmp_path, marker):
    suite = tmp_path / "suite.xml"
    suite.write_text(f'''<suite name="killed">
  <test name="stubborn" param="--hang">{plugin("fork_sleeper")}</test>
</suite>''')
    proc = start_runner("--suite", suite.name, "--no-output", env=marked(marker), cwd=tmp_path)
    # Runner, fork server, worker, the worker's child.
    wait_for(lambda: len(_marked_processes(marker)) >= 4, what="the sleeping child")
    proc.kill()
    finish_runner(proc)
    assert leftover_processes(marker, grace=5) == []


def test_an_interrupted_exec_test_leaves_no_child_in_process(tmp_path, marker):
    started = tmp_path / "started"
    script = tmp_path / "sleepy.sh"
    script.write_text(f"#!/bin/sh\nsleep 60 &\ntouch {started}\nsleep 60\n")
    script.chmod(0o755)
    proc = start_runner("--isolation", "none", "--test", script.name, "--no-output",
                        env=marked(marker), cwd=tmp_path)
    wait_for(started.exists, what="the script")
    proc.send_signal(signal.SIGINT)
    code, out, err = finish_runner(proc)
    assert code == 130, (code, out, err)
    assert "INTERRUPTED" in out, out
    assert leftover_processes(marker) == []


def test_an_exec_test_that_leaves_a_child_behind_leaves_nothing_in_process(tmp_path, marker):
    script = tmp_path / "leaver.sh"
    script.write_text("#!/bin/sh\nsleep 60 >/dev/null 2>&1 &\nexit 0\n")
    script.chmod(0o755)
    proc = start_runner("--isolation", "none", "--test", script.name, "--no-output",
                        env=marked(marker), cwd=tmp_path)
    code, out, err = finish_runner(proc)
    assert code == 0, (code, out, err)
    assert leftover_processes(marker) == []


HANGING_TEARDOWN = """import time


class FixtureManager:
    def setup(self, param):
        self.flag = param.strip()
        return True

    def check(self):
        return True

    def tearDown(self):
        with open(self.flag, "w") as out:
            out.write("tearing down")
        time.sleep(120)
"""


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_a_hung_teardown_interrupted_twice_is_reported_interrupted(tmp_path, marker, isolation):
    # Issue 39, 5: exit 143, yet the text report said "Suite s: passed", JSON suitesFailed 0
    # and JUnit had no <error>.
    (tmp_path / "hang.py").write_text(HANGING_TEARDOWN)
    (tmp_path / "suite.xml").write_text(f'''<suite name="s">
  <fixture type="python" param="tearing.flag">hang.py</fixture>
  <test name="done">{plugin("passing_test")}</test>
</suite>''')
    proc = start_runner("--isolation", isolation, "--suite", "suite.xml", "-o", "text:out.txt",
                        "-o", "json:out.json", "-o", "junit:out.xml", env=marked(marker),
                        cwd=tmp_path)
    wait_for(lambda: (tmp_path / "tearing.flag").exists(), what="the hanging tearDown")
    proc.send_signal(signal.SIGTERM)
    time.sleep(0.5)
    proc.send_signal(signal.SIGTERM)
    code, out, err = finish_runner(proc, timeout=20)
    assert code == 143, (code, out, err)
    said = "interrupted: the runner quit: the tearDown of the suite's fixtures did not finish"
    text = (tmp_path / "out.txt").read_text()
    assert "Suite s: FAILED" in text and said in text, text
    report = json.loads((tmp_path / "out.json").read_text())
    assert report["results"]["summary"]["extra"]["robotology.rtf"]["suitesFailed"] == 1, report
    validate_junit(tmp_path / "out.xml")
    (suite,) = ET.parse(tmp_path / "out.xml").getroot().iter("testsuite")
    errors = [error for case in suite.iter("testcase") for error in case.iter("error")]
    assert any(said in (error.text or "") + (error.get("message") or "") for error in errors), \
        ET.tostring(suite)
    assert statuses(tmp_path / "out.xml")["done"] == "passed"
    assert leftover_processes(marker) == []
