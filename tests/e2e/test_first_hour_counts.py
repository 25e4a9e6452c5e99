"""Issue 38, friction 6: one count of failures everywhere. The summary said "2 failed" while
the closing line said "3 failed" (a fixture failure counted in one only)."""
import re
import shutil
import signal
import subprocess
import time
from pathlib import Path
from xml.etree import ElementTree

from conftest import (RUNNER, marked, run_runner, start_runner, validate_ctrf, validate_junit,
                      validate_tap)


def test_the_summary_and_the_closing_line_count_the_same_failures(tmp_path):
    (tmp_path / "broken.xml").write_text("""<world name="broken" logdir="logs">
  <process name="broken" command="sh -c 'exit 3'">
    <ready timeout="20s"><output>ready</output></ready>
  </process>
</world>
""")
    for name in ("fail1.sh", "fail2.sh", "pass.sh"):
        (tmp_path / name).write_text("#!/bin/sh\nexit %d\n" % (0 if name == "pass.sh" else 1))
        (tmp_path / name).chmod(0o755)
    (tmp_path / "arm.xml").write_text("""<suite name="arm">
  <test type="exec">fail1.sh</test>
  <test type="exec">fail2.sh</test>
  <test type="exec">pass.sh</test>
</suite>""")
    (tmp_path / "base.xml").write_text("""<suite name="base">
  <fixture type="process">broken.xml</fixture>
  <test type="exec">pass.sh</test>
</suite>""")
    r = run_runner("-s", "arm.xml", "-s", "base.xml", cwd=tmp_path)
    assert r.returncode == 1, r
    closing = r.stdout.strip().splitlines()[-1]
    found = re.fullmatch(r"(\d+) passed, (\d+) failed.*", closing)
    assert found, r.stdout
    assert found.group(2) == "3", r.stdout  # two tests and base's fixture
    assert "  failed: 3 (2 tests, 1 fixture)" in r.stdout, r.stdout


def test_interrupted_tests_are_counted_the_same_in_the_summary_and_the_closing_line(
        tmp_path, marker):
    """Through ctest (one runner per test, stopped by SIGTERM) the summary said "1 interrupted"
    and the closing line "0 passed, 2 failed". An interrupted test fails its run (CTest's test
    fails: the exit status is not 0) and the closing line says how many of its failures were
    interrupted, as the summary does."""
    (tmp_path / "started").unlink(missing_ok=True)
    (tmp_path / "slow.sh").write_text("#!/bin/sh\ntouch started\nsleep 30\n")
    (tmp_path / "fast.sh").write_text("#!/bin/sh\nexit 0\n")
    for name in ("slow.sh", "fast.sh"):
        (tmp_path / name).chmod(0o755)
    (tmp_path / "arm.xml").write_text("""<suite name="arm">
  <test type="exec">slow.sh</test>
  <test type="exec">fast.sh</test>
</suite>""")
    proc = start_runner("-s", "arm.xml", env=marked(marker), cwd=tmp_path)
    deadline = time.monotonic() + 20
    while not (tmp_path / "started").exists() and time.monotonic() < deadline:
        time.sleep(0.05)
    proc.send_signal(signal.SIGTERM)
    out, err = proc.communicate(timeout=30)
    assert proc.returncode != 0, (out, err)
    assert "  tests:  2 (2 interrupted)" in out, out
    closing = out.strip().splitlines()[-1]
    assert closing == "0 passed, 2 failed (2 interrupted)", out


# A test that stops the runner running it with SIGTERM, as a CI engine cancelling a job (or
# CTest 3.27's TIMEOUT_SIGNAL_NAME) does: the runner is the nearest process up the tree whose
# program is the runner.
STOP_THE_RUNNER = """#!/usr/bin/env python3
import os, signal, time
pid = os.getppid()
while pid > 1:
    with open(f"/proc/{pid}/cmdline", "rb") as f:
        program = f.read().split(b"\\0")[0]
    if program.endswith(b"robottestingframework-testrunner"):
        os.kill(pid, signal.SIGTERM)
        break
    with open(f"/proc/{pid}/stat") as f:
        pid = int(f.read().rsplit(")", 1)[1].split()[1])
time.sleep(30)
"""

CTEST_PROJECT = """cmake_minimum_required(VERSION 3.19)
project(counts LANGUAGES CXX)
find_package(RobotTestingFramework 3 REQUIRED)
enable_testing()
robottestingframework_discover_tests(SUITE arm.xml TIMEOUT 60)
robottestingframework_discover_tests(SUITE base.xml TIMEOUT 60)
"""


def write_counts_suites(folder):
    """arm: a failing test, a passing one, one that gets interrupted (stop.py); base: a world
    that cannot start and a test in it."""
    (folder / "broken.xml").write_text("""<world name="broken">
  <process name="broken" command="sh -c 'echo no licence; exit 3'">
    <ready timeout="20s"><output>ready</output></ready>
  </process>
</world>
""")
    (folder / "fail.sh").write_text("#!/bin/sh\nexit 1\n")
    (folder / "pass.sh").write_text("#!/bin/sh\nexit 0\n")
    (folder / "stop.py").write_text(STOP_THE_RUNNER)
    for name in ("fail.sh", "pass.sh", "stop.py"):
        (folder / name).chmod(0o755)
    (folder / "arm.xml").write_text("""<suite name="arm">
  <test type="exec">fail.sh</test>
  <test type="exec">pass.sh</test>
  <test type="exec">stop.py</test>
</suite>""")
    (folder / "base.xml").write_text("""<suite name="base">
  <fixture type="process">broken.xml</fixture>
  <test type="exec">pass.sh</test>
</suite>""")


def test_ctest_counts_each_test_as_its_runner_does(tmp_path):
    """Through robottestingframework_discover_tests (the installed tree's CMake package): each
    CTest test's verdict is its runner's closing line, an interrupted test included ("0 passed,
    1 failed (1 interrupted)": CTest's Failed); a world that cannot start is one failure, its
    world:up test's: its world:down test is skipped (nothing to stop), and the test in it is
    CTest's "Not Run" (CTest's word for a test whose fixture failed; the runner says skipped)."""
    write_counts_suites(tmp_path)
    (tmp_path / "CMakeLists.txt").write_text(CTEST_PROJECT)
    prefix = Path(RUNNER).resolve().parent.parent
    build = tmp_path / "build"
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    configured = subprocess.run(
        ["cmake", "-S", str(tmp_path), "-B", str(build), *generator,
         f"-DCMAKE_PREFIX_PATH={prefix}", "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON"],
        capture_output=True, text=True, timeout=120)
    assert configured.returncode == 0, configured.stdout + configured.stderr
    result = subprocess.run(["ctest", "--test-dir", str(build), "-V"], capture_output=True,
                            text=True, timeout=180)
    out = result.stdout
    assert result.returncode != 0, out
    verdicts = dict(re.findall(r"Test +#\d+: (\S+) \.+ *\**(\w+(?: \w+)?)", out))
    assert verdicts == {"arm/fail.sh": "Failed", "arm/pass.sh": "Passed",
                        "arm/stop.py": "Failed", "base/world:up": "Failed",
                        "base/pass.sh": "Not Run", "base/world:down": "Skipped"}, out
    # Each test's runner closes with the count CTest gives it.
    closing = {}
    number = {name: n for n, name in re.findall(r"Test +#(\d+): (\S+)", out)}
    for name in ("arm/fail.sh", "arm/pass.sh", "arm/stop.py"):
        lines = re.findall(rf"^{number[name]}: (\d+ passed, \d+ failed.*)$", out, re.MULTILINE)
        closing[name] = lines[-1] if lines else None
    assert closing == {"arm/fail.sh": "0 passed, 1 failed", "arm/pass.sh": "1 passed, 0 failed",
                       "arm/stop.py": "0 passed, 1 failed (1 interrupted)"}, out
    assert re.search(rf"^{number['arm/stop.py']}:   tests:  1 \(1 interrupted\)$", out,
                     re.MULTILINE), out
    assert "the world never started" in out, out
    # CTest: the two failed tests, the world's one failure, and the test it did not run.
    assert "4 tests failed out of 6" in out, out
    # The runner over the same suites (without the test that stops it): the same failures,
    # the test of the broken world skipped.
    r = run_runner("-s", "arm.xml", "-s", "base.xml", "-k", "not stop", cwd=tmp_path)
    assert r.returncode == 1, r
    assert "  failed: 2 (1 test, 1 fixture)" in r.stdout, r.stdout
    assert r.stdout.strip().splitlines()[-1] == "1 passed, 2 failed, 1 skipped", r.stdout


def test_every_report_counts_a_fixture_a_failure_and_an_interruption_as_the_console(tmp_path):
    """One run: a world that cannot start (base), a failing test, a passing one and one that
    gets interrupted (arm). The console, the text, JUnit, TAP and CTRF reports give the same
    counts: 3 failures (2 tests, 1 of them interrupted, and 1 fixture), 1 passed, 1 skipped."""
    write_counts_suites(tmp_path)
    r = run_runner("-s", "base.xml", "-s", "arm.xml", "-o", "junit:r.xml", "-o", "tap:r.tap",
                   "-o", "json:r.json", "-o", "text:r.txt", cwd=tmp_path)
    assert r.returncode == 143, r  # stopped by SIGTERM
    summary = ["  tests:  4 (1 passed, 1 skipped, 1 failed, 1 interrupted)",
               "  failed: 3 (2 tests, 1 fixture)"]
    closing = "1 passed, 3 failed (1 interrupted), 1 skipped"
    for said in (r.stdout, (tmp_path / "r.txt").read_text()):
        for line in summary:
            assert line in said.splitlines(), said
        assert said.strip().splitlines()[-1] == closing, said
    # JUnit: a fixtures testcase holds the fixture's failure (an error), the interrupted test an
    # error of type "interrupted"; the readers read the same totals.
    read = validate_junit(tmp_path / "r.xml")
    root = ElementTree.parse(tmp_path / "r.xml").getroot()
    assert (int(root.get("failures")), int(root.get("errors"))) == (1, 2), read
    errors = sorted(e.get("type") for e in root.iter("error"))
    assert errors == ["fixture", "interrupted"], errors
    assert sum(int(s.get("skipped")) for s in root.iter("testsuite")) == 1
    # TAP (tap-parser): the failing points are the two tests; the fixture fails its suite.
    tap = validate_tap(tmp_path / "r.tap")
    tests = [p for p in tap["points"] if p["depth"] == 1]
    assert sorted((p["name"], p["ok"], bool(p["skip"])) for p in tests) == [
        ("fail.sh", False, False), ("pass.sh", True, False), ("pass.sh", True, True),
        ("stop.py", False, False)], tap
    suites = {p["name"]: p for p in tap["points"] if p["depth"] == 0}
    assert suites["base"]["diag"]["message"].startswith("fixture broken.xml failed"), suites
    # CTRF: failed + other (interrupted) + the fixtures that failed.
    ctrf = validate_ctrf(tmp_path / "r.json")["results"]["summary"]
    rtf = ctrf["extra"]["robotology.rtf"]
    assert (ctrf["tests"], ctrf["passed"], ctrf["failed"], ctrf["other"], ctrf["skipped"]) == \
        (4, 1, 1, 1, 1), ctrf
    assert (rtf["interrupted"], rtf["fixturesFailed"]) == (1, 1), rtf
    assert ctrf["failed"] + ctrf["other"] + rtf["fixturesFailed"] == 3
