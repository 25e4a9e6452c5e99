"""The files the runner reads and the ids it gives (issue 40): every file it reads is checked
for its type and bounded in size (a device is refused, a pipe is read once), --history never
names a device, an output's missing folder is made before the run, ids are unique within a run
(two suite files of one name), an exact id wins over --filter's pattern syntax, '?' is one
UTF-8 character, and --history-import refuses a time far in the future and adds a report once."""
import re
import sqlite3
import subprocess
import xml.etree.ElementTree as ET

import pytest

from conftest import RUNNER, run_runner, runner_environment


def exec_suite(folder, name, tests, suite_name=None, file=None):
    """A suite file `file` (NAME.xml) of exec tests: tests is [(test path, exit status)]; each
    test is a shell script written beside it (folders made as needed)."""
    folder.mkdir(parents=True, exist_ok=True)
    body = []
    for path, status in tests:
        script = folder / path
        script.parent.mkdir(parents=True, exist_ok=True)
        script.write_text(f"#!/bin/sh\nexit {status}\n")
        script.chmod(0o755)
        body.append(f'  <test type="exec">{path}</test>')
    suite = folder / (file or f"{name}.xml")
    suite.write_text(f'<suite name="{suite_name or name}">\n' + "\n".join(body) + "\n</suite>\n")
    return suite


def junit_ids(path):
    """{test id: state} of a JUnit report of this runner (classname/name)."""
    ids = {}
    for case in ET.parse(path).getroot().iter("testcase"):
        failed = case.find("failure") is not None or case.find("error") is not None
        ids[case.get("classname") + "/" + case.get("name")] = "failed" if failed else "passed"
    return ids


def listed(run):
    """The test ids --list prints (indented two spaces; their details four)."""
    return re.findall(r"^  (\S.*)$", run.stdout, re.MULTILINE)


# --- defect 1: two tests get one id ---------------------------------------------------------

def test_two_suite_files_of_one_name_give_their_tests_distinct_ids(tmp_path):
    exec_suite(tmp_path / "left", "arm", [("t.sh", 1)])
    exec_suite(tmp_path / "right", "arm", [("t.sh", 0)])
    args = ["--suite", "left/arm.xml", "--suite", "right/arm.xml"]
    r = run_runner(*args, "--list", cwd=tmp_path)
    assert r.returncode == 0, r
    assert "arm[left/arm.xml]/t.sh" in r.stdout and "arm[right/arm.xml]/t.sh" in r.stdout, r
    r = run_runner(*args, "-o", "junit:r.xml", "--history", "h.db", cwd=tmp_path)
    assert r.returncode == 1, r
    assert junit_ids(tmp_path / "r.xml") == {"arm[left/arm.xml]/t.sh": "failed",
                                             "arm[right/arm.xml]/t.sh": "passed"}
    # --rerun-failed reruns the failed one alone, not the one that passed too.
    r = run_runner(*args, "--rerun-failed", "r.xml", "-o", "junit:again.xml", "--history",
                   "h.db", cwd=tmp_path)
    assert r.returncode == 1, r
    assert junit_ids(tmp_path / "again.xml") == {"arm[left/arm.xml]/t.sh": "failed"}, r
    r = run_runner(*args, "--history", "h.db", cwd=tmp_path)
    assert r.returncode == 1, r
    # The history keeps two tests, neither flaky (one always failed, one always passed).
    r = run_runner("--history", "h.db", "--history-report", cwd=tmp_path)
    assert r.returncode == 0, r
    assert "History: 2 tests in the last 3 runs" in r.stdout, r
    assert "Flakiest tests (runs flaky or changing outcome):\n  none\n" in r.stdout, r
    with sqlite3.connect(tmp_path / "h.db") as db:
        names = sorted(n for (n,) in db.execute("SELECT name FROM tests"))
    assert names == ["arm[left/arm.xml]/t.sh", "arm[right/arm.xml]/t.sh"], names


def test_a_suite_and_a_test_path_that_join_to_one_id_are_told_apart(tmp_path):
    # Suite "a" with the test b/c.sh beside suite "a/b" with the test c.sh: both "a/b/c.sh".
    exec_suite(tmp_path, "x", [("b/c.sh", 0)], suite_name="a")
    exec_suite(tmp_path, "y", [("c.sh", 1)], suite_name="a/b")
    r = run_runner("--suite", "x.xml", "--suite", "y.xml", "--list", cwd=tmp_path)
    assert r.returncode == 0, r
    assert "a[x.xml]/b/c.sh" in r.stdout and "a/b[y.xml]/c.sh" in r.stdout, r
    r = run_runner("--suite", "x.xml", "--suite", "y.xml", "-o", "junit:r.xml", cwd=tmp_path)
    assert junit_ids(tmp_path / "r.xml") == {"a[x.xml]/b/c.sh": "passed",
                                             "a/b[y.xml]/c.sh": "failed"}, r


def test_the_copies_of_one_suite_file_given_twice_are_numbered(tmp_path):
    exec_suite(tmp_path, "arm", [("t.sh", 0)])
    r = run_runner("--suite", "arm.xml", "--suite", "./arm.xml", "-o", "junit:r.xml",
                   cwd=tmp_path)
    assert r.returncode == 0, r
    assert junit_ids(tmp_path / "r.xml") == {"arm/t.sh": "passed", "arm[2]/t.sh": "passed"}


# --- defect 2 and 14: --filter --------------------------------------------------------------

@pytest.mark.parametrize("name", ["arm::left/grip", "arm:-grip", "grip-"])
def test_an_exact_id_holding_pattern_syntax_selects_that_test(tmp_path, name):
    (tmp_path / "ok.sh").write_text("#!/bin/sh\nexit 0\n")
    (tmp_path / "ok.sh").chmod(0o755)
    (tmp_path / "s.xml").write_text(
        f'<suite name="s"><test type="exec" name="{name}">ok.sh</test>'
        '<test type="exec" name="other">ok.sh</test></suite>\n')
    r = run_runner("--suite", "s.xml", "--filter", f"s/{name}", "--list", cwd=tmp_path)
    assert r.returncode == 0, r
    assert listed(r) == [f"s/{name}"], r
    # Not an id of the run: still the pattern's error, exit 2.
    r = run_runner("--suite", "s.xml", "--filter", f"t/{name}", "--no-output", cwd=tmp_path)
    assert r.returncode == 2, r
    assert "an empty pattern at column" in r.stderr, r
    assert "nor is it the id of a test of this run" in r.stderr, r


def test_a_question_mark_matches_one_utf8_character(tmp_path):
    (tmp_path / "ok.sh").write_text("#!/bin/sh\nexit 0\n")
    (tmp_path / "ok.sh").chmod(0o755)
    (tmp_path / "u.xml").write_text(
        '<suite name="u"><test type="exec" name="ü">ok.sh</test>'
        '<test type="exec" name="ab">ok.sh</test></suite>\n', encoding="utf-8")
    r = run_runner("--suite", "u.xml", "--filter", "u/?", "--list", cwd=tmp_path)
    assert r.returncode == 0, r
    assert listed(r) == ["u/ü"], r
    r = run_runner("--suite", "u.xml", "--filter", "u/??", "--list", cwd=tmp_path)
    assert listed(r) == ["u/ab"], r


# --- defect 5: every file read is checked and bounded ---------------------------------------

@pytest.mark.parametrize("option, what", [
    ("--rerun-failed", "report"), ("--durations", "report"),
    ("--resources", "resource file"), ("--var-file", "variable file")])
def test_a_device_given_as_an_input_file_is_refused_before_reading(tmp_path, option, what):
    exec_suite(tmp_path, "s", [("t.sh", 0)])
    args = ["--suite", "s.xml", option, "/dev/zero", "--no-output"]
    if option == "--durations":
        args += ["--shard-index", "0", "--shard-count", "2"]
    r = run_runner(*args, cwd=tmp_path, timeout=30)
    assert r.returncode == 2, r
    assert f"/dev/zero: is a character device, not a {what}" in r.stderr, r


def test_history_import_of_a_device_is_refused(tmp_path):
    r = run_runner("--history", "h.db", "--history-import", "/dev/zero", cwd=tmp_path,
                   timeout=30)
    assert r.returncode == 2, r
    assert "/dev/zero: is a character device, not a report" in r.stderr, r


def test_an_oversized_variable_file_is_refused(tmp_path):
    exec_suite(tmp_path, "s", [("t.sh", 0)])
    with open(tmp_path / "big.env", "wb") as big:
        big.truncate(16 * 1024 * 1024 + 1)  # sparse: no disk used
    r = run_runner("--suite", "s.xml", "--var-file", "big.env", "--no-output", cwd=tmp_path,
                   timeout=30)
    assert r.returncode == 2, r
    assert "big.env: the variable file is larger than 16 MiB" in r.stderr, r


# --- defect 9: a pipe is read once ----------------------------------------------------------

def run_in_bash(command, cwd):
    """Runs `command` by bash in `cwd` (for its <(...)), the runner as "$RUNNER"."""
    env = runner_environment([], {"RUNNER": str(RUNNER)}, cwd=cwd)
    return subprocess.run(["bash", "-c", command], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=120)


def test_durations_from_a_pipe_are_read_once(tmp_path):
    for name in "ab":
        exec_suite(tmp_path, name, [("t.sh", 0)])
    r = run_runner("--suite", "a.xml", "--suite", "b.xml", "-o", "junit:report.xml",
                   cwd=tmp_path)
    assert r.returncode == 0, r
    r = run_in_bash('"$RUNNER" --suite a.xml --suite b.xml --shard-index 0 --shard-count 2 '
                    '--durations <(cat report.xml) --no-output', tmp_path)
    assert r.returncode == 0, r
    assert "not a JUnit" not in r.stderr, r
    assert "balanced by /dev/fd/" in r.stdout + r.stderr, r


# --- defect 7: --history never names a device -----------------------------------------------

@pytest.mark.parametrize("device", ["/dev/null", "/dev/full"])
def test_history_on_a_device_is_refused_before_the_run(tmp_path, device):
    exec_suite(tmp_path, "s", [("t.sh", 0)])
    (tmp_path / "ran").unlink(missing_ok=True)
    (tmp_path / "t.sh").write_text("#!/bin/sh\ntouch ran\n")
    r = run_runner("--suite", "s.xml", "--history", device, "--no-output", cwd=tmp_path)
    assert r.returncode == 2, r
    assert f"--history {device}: is a character device, not a history file" in r.stderr, r
    assert not (tmp_path / "ran").exists(), "the run started"
    r = run_runner("--history", device, "--history-report", cwd=tmp_path)
    assert r.returncode == 2, r
    assert "is a character device" in r.stderr, r


# --- defect 15: an output's missing folder --------------------------------------------------

def test_an_outputs_missing_folder_is_made_before_the_run(tmp_path):
    exec_suite(tmp_path, "s", [("t.sh", 0)])
    r = run_runner("--suite", "s.xml", "-o", "junit:out/deep/r.xml", cwd=tmp_path)
    assert r.returncode == 0, r
    assert junit_ids(tmp_path / "out" / "deep" / "r.xml") == {"s/t.sh": "passed"}
    # A file where the folder should be: refused before the run, naming it.
    (tmp_path / "t.sh").write_text("#!/bin/sh\ntouch ran\n")
    (tmp_path / "plain").write_text("")
    r = run_runner("--suite", "s.xml", "-o", "junit:plain/r.xml", cwd=tmp_path)
    assert r.returncode == 2, r
    assert "--output junit:plain/r.xml: cannot create the folder plain" in r.stderr, r
    assert not (tmp_path / "ran").exists(), "the run started"


# --- defect 16: --history-import ------------------------------------------------------------

def junit_at(timestamp):
    return ('<?xml version="1.0"?><testsuites><testsuite name="py" '
            f'timestamp="{timestamp}"><testcase classname="m" name="a" time="0.5"/>'
            '</testsuite></testsuites>')


def test_history_import_refuses_a_time_far_in_the_future(tmp_path):
    (tmp_path / "far.xml").write_text(junit_at("9999-12-31T23:59:59"))
    r = run_runner("--history", "h.db", "--history-import", "far.xml", cwd=tmp_path)
    assert r.returncode == 2, r
    assert "far.xml: its time, 9999-12-31T23:59:59Z, is in the future" in r.stderr, r


def test_importing_one_report_twice_adds_it_once(tmp_path):
    (tmp_path / "r.xml").write_text(junit_at("2024-01-02T03:04:05"))
    (tmp_path / "copy").mkdir()
    (tmp_path / "copy" / "r.xml").write_text(junit_at("2024-01-02T03:04:05"))
    for path in ["r.xml", "r.xml", "copy/r.xml"]:
        r = run_runner("--history", "h.db", "--history-import", path, cwd=tmp_path)
        assert r.returncode == 0, r
    assert "already in h.db, not loaded again" in r.stdout, r
    with sqlite3.connect(tmp_path / "h.db") as db:
        assert db.execute("SELECT count(*) FROM runs").fetchone() == (1,)
        assert db.execute("SELECT count(*) FROM results").fetchone() == (1,)


def test_a_suites_folder_passes_over_world_files_and_reports(tmp_path):
    """Issue 38's second trial: the tutorial's folder (suite.xml beside world.xml) after a run
    with -o junit:lab.xml: `--suites .` stopped at "./lab.xml:2: the root element is
    <testsuites>" (and at world.xml's <world>), exit 2. World files and JUnit reports in a
    --suites folder are passed over; a root element that is no known format is passed over with
    a warning that names it (RTF 2.x passed it over), a malformed file is exit 2."""
    (tmp_path / "world.xml").write_text(
        '<world name="lab">\n  <process name="p" command="/bin/sh -c \'echo up; exec sleep 30\'">'
        '\n    <ready timeout="20s"><output>^up$</output></ready>\n  </process>\n</world>\n')
    (tmp_path / "ok.sh").write_text("#!/bin/sh\nexit 0\n")
    (tmp_path / "ok.sh").chmod(0o755)
    (tmp_path / "suite.xml").write_text(
        '<suite name="lab">\n  <fixture type="process">world.xml</fixture>\n'
        '  <test>ok.sh</test>\n</suite>\n')
    for round in (1, 2):  # the second run finds the first one's report in the folder
        r = run_runner("--suites", ".", "-o", "junit:lab.xml", cwd=tmp_path)
        assert r.returncode == 0, (round, r)
        assert "1 passed, 0 failed" in r.stdout, r
    r = run_runner("--suites", ".", "--list", cwd=tmp_path)
    assert r.returncode == 0 and "1 test in 1 suite" in r.stdout, r
    (tmp_path / "typo.xml").write_text("<suiet name='x'/>\n")
    r = run_runner("--suites", ".", "--list", cwd=tmp_path)
    assert r.returncode == 0 and "1 test in 1 suite" in r.stdout, r
    assert "typo.xml: warning: the root element is <suiet>, not <suite>" in r.stderr, r
    (tmp_path / "broken.xml").write_text("<suite name='x'>\n  <test>ok.sh</test>\n")
    r = run_runner("--suites", ".", "--list", cwd=tmp_path)
    assert r.returncode == 2 and "broken.xml" in r.stderr, r
