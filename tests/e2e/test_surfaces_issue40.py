"""Defects of issue 40 found by trying to break the last round's surfaces: the console's time
of a test, a Python thread that reports after its test ended, control characters on the
terminal and in the text reports, attachment names and files, measurement names in JUnit
properties, a TAP measurement too large for a double, and a history file in a folder the user
may not write. The runner starts in the suite's folder and is given relative paths."""
import os
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET

import pytest

from conftest import RUNNER, run_runner


def program(folder, name, text):
    path = folder / name
    path.write_text(text)
    path.chmod(0o755)
    return path


# --- 6. The console's time of a test is the report's -------------------------------------------

def console_times(stdout):
    """{test id: seconds} of the console's test lines ("passed  suite/id  (t)" at every -j)."""
    times = {}
    for line in stdout.splitlines():
        found = re.search(r"passed\s+\w+/(sleep_\w+)\s+\((\d+\.\d{3}) s\)\s*$", line)
        if found:
            times[found.group(1)] = float(found.group(2))
    return times


def junit_times(path):
    return {case.get("name"): float(case.get("time"))
            for case in ET.parse(path).getroot().iter("testcase")}


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_the_console_prints_the_time_the_reports_give(tmp_path, jobs):
    for name in "abcd":
        program(tmp_path, f"sleep_{name}", "#!/bin/sh\nsleep 0.5\n")
    (tmp_path / "one.xml").write_text('<suite name="one">\n  <test type="exec">sleep_a</test>\n'
                                      '  <test type="exec">sleep_b</test>\n</suite>\n')
    (tmp_path / "two.xml").write_text('<suite name="two">\n  <test type="exec">sleep_c</test>\n'
                                      '  <test type="exec">sleep_d</test>\n</suite>\n')
    run = run_runner("-j", jobs, "--suite", "one.xml", "--suite", "two.xml",
                     "-o", "junit:r.xml", cwd=tmp_path)
    assert run.returncode == 0, run
    shown = console_times(run.stdout)
    reported = junit_times(tmp_path / "r.xml")
    assert len(shown) == 4, run
    for test, took in shown.items():
        assert took >= 0.5, f"{test}: the console says {took} s for a test that slept 0.5 s\n{run}"
        # The same time, to the rounding of its last digit.
        assert abs(took - reported[test]) <= 0.0011, (test, took, reported[test], run)


# --- 8. A Python thread that reports after its test ended --------------------------------------

# The first test's thread reports once the second test runs, and the second test waits for it:
# files say when, whatever the machine's load.
LATE_THREAD = """import os
import threading
import time
import robottestingframework

def later():
    for _ in range(1000):
        if os.path.exists("second_running"):
            break
        time.sleep(0.01)
    robottestingframework.testCheck(False, "late check of the first test")
    open("late_done", "w").close()

class TestCase:
    def run(self):
        threading.Thread(target=later, daemon=True).start()
"""

WAITING = """import os
import time
import robottestingframework

class TestCase:
    def run(self):
        open("second_running", "w").close()
        for _ in range(1000):
            if os.path.exists("late_done"):
                break
            time.sleep(0.01)
        robottestingframework.testCheck(os.path.exists("late_done"), "the first test's thread ran")
"""


def test_a_late_python_thread_never_fails_the_next_test(tmp_path):
    (tmp_path / "first.py").write_text(LATE_THREAD)
    (tmp_path / "second.py").write_text(WAITING)
    (tmp_path / "suite.xml").write_text('<suite name="late">\n  <test>first.py</test>\n'
                                        '  <test>second.py</test>\n</suite>\n')
    run = run_runner("--isolation", "none", "--suite", "suite.xml", "-o", "junit:r.xml",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert "2 passed, 0 failed" in run.stdout, run
    report = (tmp_path / "r.xml").read_text()
    root = ET.fromstring(report)
    assert not list(root.iter("failure")), report
    # Dropped with a warning that names the test its thread belongs to.
    assert re.search(r'warning: a thread of test "\S*first\.py\S*" called testCheck\(False\) '
                     r'after that test ended; dropped: late check of the first test',
                     run.output + report), run


# --- 10. Control characters in names and messages are shown escaped -----------------------------

HOSTILE = """import robottestingframework

class TestCase:
    def run(self):
        robottestingframework.setName("arm\\x1b]0;pwned\\x07\\x1b[2J\\r  passed      fake")
        robottestingframework.testCheck(False, "moved\\x1b[31m\\r  passed      s :: fake  (0.001 s)")
"""


def test_control_characters_reach_neither_the_terminal_nor_the_text_report(tmp_path):
    (tmp_path / "hostile.py").write_text(HOSTILE)
    (tmp_path / "suite.xml").write_text('<suite name="s">\n  <test>hostile.py</test>\n'
                                        '</suite>\n')
    for jobs in ("1", "2"):
        run = run_runner("-j", jobs, "--suite", "suite.xml", "-o", "text:r.txt", cwd=tmp_path)
        assert run.returncode == 1, run
        for shown, where in ((run.stdout, "console"),
                             ((tmp_path / "r.txt").read_text(), "text report")):
            assert "\x1b" not in shown and "\x07" not in shown and "\r" not in shown, \
                f"-j {jobs}: a control character reached the {where}:\n{shown!r}"
            assert r"arm\e]0;pwned\x07\e[2J\r  passed      fake" in shown, (where, shown)
            assert r"moved\e[31m\r  passed      s :: fake" in shown, (where, shown)


def imported_report(outcome, day):
    """A JUnit report of one test whose name holds C1 control characters (XML 1.0 allows
    them), passed or failed."""
    failure = '<failure message="no"/>' if outcome == "failed" else ""
    return ('<?xml version="1.0" encoding="UTF-8"?>\n<testsuites>\n'
            f'  <testsuite name="imp" tests="1" failures="{int(bool(failure))}" errors="0" '
            f'skipped="0" time="0.1" timestamp="2024-01-{day:02d}T10:00:00">\n'
            f'    <testcase classname="imp" name="t\u0085x\u009b2J" time="0.1">{failure}'
            '</testcase>\n  </testsuite>\n</testsuites>\n')


FLIPPING = """import os
import robottestingframework

class TestCase:
    def run(self):
        runs = len(os.listdir("runs"))
        open(os.path.join("runs", str(runs)), "w").close()
        robottestingframework.testCheck(runs % 2 == 0, "every other run fails")
"""


def test_names_are_shown_escaped_by_the_history_report(tmp_path):
    (tmp_path / "runs").mkdir()
    script = "esc\x1b[2Jy.py"  # a test id with an escape sequence: its file's name
    (tmp_path / script).write_text(FLIPPING)
    for _ in range(2):
        run_runner("--history", "h.db", "--test", script, cwd=tmp_path)
    for outcome, day in (("passed", 1), ("failed", 2)):
        (tmp_path / f"{outcome}.xml").write_text(imported_report(outcome, day), encoding="utf-8")
        run = run_runner("--history", "h.db", "--history-import", f"{outcome}.xml", cwd=tmp_path)
        assert run.returncode == 0, run
    run = run_runner("--history", "h.db", "--history-report", cwd=tmp_path)
    assert run.returncode == 0, run
    shown = run.stdout
    assert "\x1b" not in shown and "\u009b" not in shown and "\u0085" not in shown, repr(shown)
    assert r"esc\e[2Jy.py" in shown, shown
    assert r"t\u0085x\u009b2J" in shown, shown


# --- 11, 12. Attachment names and files ---------------------------------------------------------

HOSTILE_NAME = """import robottestingframework

class TestCase:
    def run(self):
        with open("bad\\x01\\nname].txt", "w") as f:
            f.write("kept")
        robottestingframework.testAttach("bad\\x01\\nname].txt", "a hostile name")
"""


def junit_system_out(path):
    return "".join(case.findtext("system-out") or ""
                   for case in ET.parse(path).getroot().iter("testcase"))


def test_an_attachment_gets_a_name_every_report_can_link(tmp_path):
    (tmp_path / "attach.py").write_text(HOSTILE_NAME)
    run = run_runner("--test", "attach.py", "-o", "junit:r.xml", cwd=tmp_path)
    assert run.returncode == 0, run
    stored = [p.name for p in (tmp_path / "rtf-attachments").iterdir() if p.name != ".lock"]
    assert stored == ["1-bad__name_.txt"], stored
    assert (tmp_path / "rtf-attachments" / "1-bad__name_.txt").read_text() == "kept"
    # The [[ATTACHMENT|...]] line is whole and names the file that exists.
    out = junit_system_out(tmp_path / "r.xml")
    linked = re.findall(r"^\[\[ATTACHMENT\|(.*)\]\]$", out, re.M)
    assert len(linked) == 1 and os.path.isfile(linked[0]), out


def test_a_file_that_says_it_is_empty_is_attached_whole(tmp_path):
    (tmp_path / "attach.py").write_text(
        "import robottestingframework\n\nclass TestCase:\n    def run(self):\n"
        "        robottestingframework.testAttach('/proc/self/status', 'its size says 0')\n")
    run = run_runner("--test", "attach.py", cwd=tmp_path)
    assert run.returncode == 0, run
    status = (tmp_path / "rtf-attachments" / "1-status").read_text()
    assert status.startswith("Name:") and "Pid:" in status, status


# --- 13. A measurement name cannot make Jenkins' property line ambiguous ------------------------

def test_a_measurement_name_cannot_break_the_jenkins_property_line(tmp_path):
    (tmp_path / "measure.py").write_text(
        "import robottestingframework\n\nclass TestCase:\n    def run(self):\n"
        "        robottestingframework.testMeasure('a=b]]x|y[z', 2, 'ms')\n")
    run = run_runner("--test", "measure.py", "-o", "junit:r.xml", cwd=tmp_path)
    assert run.returncode == 0, run
    out = junit_system_out(tmp_path / "r.xml")
    properties = re.findall(r"^\[\[PROPERTY\|([^=\]|\[]*)=([^\]]*)\]\]$", out, re.M)
    assert properties == [("a_b__x_y_z", "2")], out
    assert "a=b]]x|y[z" in out, "the words above the line keep the name as given"


# --- 17. A TAP measurement too large for a double is quoted as written -----------------------------

def test_a_tap_measurement_too_large_is_refused_as_written(tmp_path):
    program(tmp_path, "huge", """#!/bin/sh
echo 'TAP version 14'
echo '1..1'
echo 'ok 1 - measured'
echo '  ---'
echo '  measurements:'
echo '    - name: force'
echo '      value: 1e400'
echo '  ...'
""")
    run = run_runner("--test", "./huge", "-o", "junit:r.xml", cwd=tmp_path)
    assert run.returncode == 1, run
    assert "value '1e400' is too large" in run.stdout, run
    assert "the value inf" not in run.stdout, run


# --- 4. A history file in a folder the user may not write -------------------------------------

def read_only(folder, *command):
    """Runs `command` (the runner's arguments) in `folder` with `folder` mounted read-only in a
    mount namespace of its own (tests run as root, whom permission bits do not stop)."""
    # The runner starts inside the read-only mount (a cwd taken before it would not be).
    script = 'mount --bind "$1" "$1" && mount -o remount,ro,bind "$1" && cd "$1" && shift && exec "$@"'
    proc = subprocess.run(["unshare", "-m", "sh", "-c", script, "sh", str(folder), RUNNER,
                           *command], cwd=folder, capture_output=True, text=True, timeout=120)
    return proc


def test_a_history_file_in_a_read_only_folder_is_read_and_a_write_says_why_not(tmp_path):
    folder = tmp_path / "ro"
    folder.mkdir()
    (folder / "a.py").write_text("class TestCase:\n    def run(self):\n        pass\n")
    run = run_runner("--test", "a.py", "--history", "h.db", "-o", "junit:r.xml", cwd=folder)
    assert run.returncode == 0, run
    assert not (folder / "h.db-wal").exists() and not (folder / "h.db-shm").exists()
    probe = subprocess.run(["unshare", "-m", "sh", "-c",
                            'mount --bind "$1" "$1" && mount -o remount,ro,bind "$1" && '
                            'touch "$1/x"', "sh", str(folder)], capture_output=True, text=True)
    assert probe.returncode != 0 and "Read-only" in probe.stderr, probe
    report = read_only(folder, "--history", "h.db", "--history-report")
    assert report.returncode == 0, report
    assert "History: 1 tests in the last 1 runs" in report.stdout, report
    durations = read_only(folder, "--test", "a.py", "--durations", "h.db", "-j", "2",
                          "--no-output")
    assert durations.returncode == 0, durations
    assert "not a history file" not in durations.stderr, durations
    again = read_only(folder, "--test", "a.py", "--history", "h.db", "--no-output")
    assert again.returncode == 2, again
    assert "--history h.db: the folder . cannot be written" in again.stderr, again
    assert "passed" not in again.stdout, "the run started although it could not be recorded"


# --- 18. TAP as npm's tap-parser reads it ----------------------------------------------------

@pytest.mark.parametrize("name,lines,passes,said", [
    ("strict", ["TAP version 14", "pragma +strict", "1..1", "warming up", "ok 1"], False,
     "a line that is not TAP, under pragma +strict: 'warming up'"),
    ("offset", ["TAP version 14", "ok 8", "ok 9", "8..9"], True, None),
    ("twice", ["TAP version 14", "1..3", "ok 1", "ok 2", "ok 2"], False,
     "test number 2 is given more than once"),
    ("below", ["TAP version 14", "1..2", "ok 0", "ok 2"], False,
     "test number 0 is before the plan 1..2"),
    ("spaced", ["TAP version 14", "1..1 ", "ok 1"], False, "malformed plan '1..1 '"),
])
def test_tap_follows_the_reference_parser(tmp_path, name, lines, passes, said):
    program(tmp_path, name, "#!/bin/sh\n" + "".join(f"echo '{line}'\n" for line in lines))
    run = run_runner("--test", f"./{name}", cwd=tmp_path)
    assert run.returncode == (0 if passes else 1), run
    if said:
        assert said in run.stdout, run
