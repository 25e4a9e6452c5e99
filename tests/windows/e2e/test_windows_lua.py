"""Lua test cases on Windows: the runner loads robottestingframework-lua.dll (Lua 5.4 from
Debian's source, built by MinGW-w64) and runs .lua files written as RTF 2.x users write them
(the TestCase table already made, `TestCase.setup = function(param) ... end`), in its own
process (--isolation none), from the suite's folder with relative paths; passing and failing
tests, errors with their file and line, and measurements, read back from every report."""
import re
import xml.etree.ElementTree as ET

from conftest import run_runner, validate_ctrf, validate_junit, validate_tap

# A neighbour module, found by require() beside the test (the folder is a Windows path here).
LIMITS = """return { tracking = 0.05 }
"""

ARM = """local limits = require("limits")

TestCase.setup = function(param)
    robottestingframework.testReport("setting up with " .. param)
    return true
end

TestCase.run = function()
    robottestingframework.testCheck(5 > 3, "5 is bigger than 3")
    robottestingframework.testMeasure("tracking error", 0.012, "rad", 0, limits.tracking)
    robottestingframework.testMeasure("loop rate", 99.5, "Hz")
end

TestCase.tearDown = function()
    robottestingframework.testReport("tearing down")
end
"""

GRIPPER = """TestCase.run = function()
    robottestingframework.testMeasure("grip force", 12.5, "N", 0, 10)
    robottestingframework.testCheck(5 < 3, "5 is not smaller than 3")
end
"""

BROKEN = """local function helper()
    return nil .. "text"
end

TestCase.run = function()
    helper()
end
"""

SUITE = """<?xml version="1.0" encoding="UTF-8"?>
<suite name="Lua on Windows">
    <test name="arm" param="--speed 2">../tests/arm.lua</test>
    <test name="gripper">../tests/gripper.lua</test>
    <test name="broken" type="lua">../tests/broken.lua</test>
</suite>
"""


def write_project(tmp_path):
    tests = tmp_path / "tests"
    tests.mkdir()
    for name, text in (("limits.lua", LIMITS), ("arm.lua", ARM), ("gripper.lua", GRIPPER),
                       ("broken.lua", BROKEN)):
        (tests / name).write_text(text)
    suites = tmp_path / "suites"
    suites.mkdir()
    (suites / "suite.xml").write_text(SUITE)
    (suites / "out").mkdir()
    return suites


def test_lua_suite_passes_fails_and_measures_in_every_report(tmp_path):
    suites = write_project(tmp_path)
    run = run_runner("-s", "suite.xml", "--isolation", "none", "-o", "junit:out/r.xml",
                     "-o", "text:out/r.txt", "-o", "tap:out/r.tap", "-o", "json:out/r.json",
                     cwd=suites)
    assert run.returncode == 1, run  # tests failed
    assert "1 passed, 2 failed" in run.stdout, run
    out = suites / "out"

    ctrf = validate_ctrf(out / "r.json")
    tests = {test["name"]: test for test in ctrf["results"]["tests"]}
    assert tests["arm"]["status"] == "passed", tests["arm"]
    measured = tests["arm"]["extra"]["robotology.rtf"]["measurements"]
    assert [(m["name"], m["value"], m["unit"]) for m in measured] == [
        ("tracking error", 0.012, "rad"), ("loop rate", 99.5, "Hz")], measured
    assert measured[0]["low"] == 0 and measured[0]["high"] == 0.05 and measured[0]["passed"]

    gripper = tests["gripper"]
    assert gripper["status"] == "failed", gripper
    assert "measurement 'grip force' = 12.5 N, outside its limits [0, 10] N" in gripper[
        "message"], gripper
    assert gripper["extra"]["robotology.rtf"]["measurements"][0]["passed"] is False, gripper

    broken = tests["broken"]
    assert broken["extra"]["robotology.rtf"]["state"] == "error", broken
    assert "attempt to concatenate a nil value" in broken["message"], broken

    validate_junit(out / "r.xml")
    cases = {case.get("name"): case for case in ET.parse(out / "r.xml").getroot().iter(
        "testcase")}
    assert cases["arm"].find("failure") is None and cases["arm"].find("error") is None
    arm_out = cases["arm"].find("system-out").text
    assert "[[PROPERTY|tracking error=0.012]]" in arm_out.splitlines(), arm_out
    # setup got the suite's param; tearDown ran.
    assert "setting up with --speed 2" in arm_out and "tearing down" in arm_out, arm_out
    failure = cases["gripper"].find("failure")
    assert failure is not None and "5 is not smaller than 3" in ET.tostring(
        cases["gripper"]).decode(), ET.tostring(cases["gripper"]).decode()

    tap = validate_tap(out / "r.tap")
    assert tap["ok"] is False and tap["fail"] == 1, tap  # the suite, its tests as subtests
    tap_text = (out / "r.tap").read_text()
    assert re.search(r"^ +ok 1 - arm$", tap_text, re.M), tap_text
    assert re.search(r"^ +not ok 2 - gripper$", tap_text, re.M), tap_text
    assert re.search(r"^ +not ok 3 - broken$", tap_text, re.M), tap_text
    assert re.search(r'- name: "tracking error"\n\s+value: 0\.012\n\s+unit: "rad"', tap_text), \
        tap_text

    # Where the failing check and the error are, as on Linux: the script's file and line.
    text = (out / "r.txt").read_text()
    assert re.search(r"gripper\.lua:3\b", text), text
    assert re.search(r"broken\.lua:2\b", text) and "stack traceback" in text, text


def test_a_lua_syntax_error_names_the_file_and_line(tmp_path):
    (tmp_path / "bad.lua").write_text("TestCase.run = function(\nend\n")
    run = run_runner("-t", "bad.lua", "--isolation", "none", "--no-output", cwd=tmp_path)
    assert run.returncode != 0, run
    assert re.search(r"bad\.lua:2:", run.output), run
    assert "not built for Windows" not in run.output, run
