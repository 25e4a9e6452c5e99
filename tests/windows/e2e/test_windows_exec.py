"""Exec tests on Windows: an .exe run directly and a .bat file through `cmd /c`, each printing
TAP that becomes checks, under the default isolation (a worker per test) and in the runner's
process, from the suite's folder with relative paths."""
import xml.etree.ElementTree as ET

import pytest

from conftest import copy_plugins, run_runner, validate_junit

BATCH = "\r\n".join([
    "@echo off",
    "echo 1..2",
    "echo ok 1 - the batch file ran",
    "echo not ok 2 - a batch check fails",
    "",
])

SUITE = """<?xml version="1.0" encoding="UTF-8"?>
<suite name="Exec">
    <test name="program" param="first second">../programs/tap_printer.exe</test>
    <test name="program_fails" param="one fail">../programs/tap_printer.exe</test>
    <test name="batch">tap.bat</test>
</suite>
"""


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_exe_and_bat_print_tap_that_becomes_checks(tmp_path, isolation):
    copy_plugins(tmp_path / "programs", "tap_printer.exe")
    suites = tmp_path / "suites"
    suites.mkdir()
    (suites / "tap.bat").write_bytes(BATCH.encode())
    (suites / "exec.xml").write_text(SUITE)
    run = run_runner("-s", "exec.xml", "--isolation", isolation, "-o", "junit:r.xml",
                     "-o", "text:r.txt", cwd=suites, timeout=180)
    assert run.returncode == 1, run
    assert "1 passed, 2 failed" in run.stdout.splitlines()[-1], run
    validate_junit(suites / "r.xml")
    cases = {case.get("name"): case for case in ET.parse(suites / "r.xml").getroot().iter("testcase")}
    assert set(cases) == {"program", "program_fails", "batch"}, cases
    assert cases["program"].find("failure") is None and cases["program"].find("error") is None
    failure = cases["program_fails"].find("failure")
    assert failure is not None and "fail" in failure.get("message", ""), ET.tostring(
        cases["program_fails"]).decode()
    failure = cases["batch"].find("failure")
    assert failure is not None and "a batch check fails" in failure.get("message", ""), (
        ET.tostring(cases["batch"]).decode())
    text = (suites / "r.txt").read_text()
    # The TAP points became checks: the passing ones are listed too.
    assert "the batch file ran" in text and "second" in text, text


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_a_crashing_program_is_named_as_a_crashing_worker(tmp_path, isolation):
    # The same words as a C++ plug-in's crash in a worker (test_windows_isolation.py).
    copy_plugins(tmp_path, "tap_printer.exe")
    run = run_runner("-t", "tap_printer.exe", "-p", "first crash", "--isolation", isolation,
                     "-o", "junit:r.xml", cwd=tmp_path, timeout=180)
    assert run.returncode == 1, run
    validate_junit(tmp_path / "r.xml")
    error = ET.parse(tmp_path / "r.xml").getroot().find(".//testcase/error")
    assert error is not None and error.get("type") == "crash", run
    assert error.get("message") == "crashed: 0xC0000005 (access violation)", error.attrib
    assert "killed by" not in run.output, run
