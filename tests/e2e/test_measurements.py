"""Measurements (issue 22, item 2) through the real runner, in every language and every
report: a measurement inside its limits is recorded, one outside fails its test with a message
naming value, limits and unit, and a value that is not a finite number (or an empty name, or a
unit over 64 bytes) is an error of its test. In-process and isolated, one suite at a time and
two at once (-j 2); every report read back by its own readers."""
import json
import re
import xml.etree.ElementTree as ET

import pytest

from conftest import plugin, run_runner, validate_ctrf, validate_junit, validate_tap

PYTHON = {
    "in": """class TestCase:
    def run(self):
        robottestingframework.testMeasure("tracking error", 0.012, "rad", 0, 0.05)
        robottestingframework.testMeasure("loop rate", 99.5, unit="Hz")
        robottestingframework.testMeasure("steps", 3)
""",
    "out": """class TestCase:
    def run(self):
        robottestingframework.testMeasure("tracking error", 0.12, "rad", low=0, high=0.05)
        robottestingframework.testReport("went on after the measurement")
""",
    "bad": """class TestCase:
    def run(self):
        robottestingframework.testMeasure("tracking error", float("nan"), "rad")
""",
}
LUA = {
    "in": """TestCase.run = function()
  robottestingframework.testMeasure("tracking error", 0.012, "rad", 0, 0.05)
  robottestingframework.testMeasure("loop rate", 99.5, "Hz")
  robottestingframework.testMeasure("steps", 3)
end
""",
    "out": """TestCase.run = function()
  robottestingframework.testMeasure("tracking error", 0.12, "rad", 0, 0.05)
  robottestingframework.testReport("went on after the measurement")
end
""",
    "bad": """TestCase.run = function()
  robottestingframework.testMeasure("", 1.0, "rad")
end
""",
}
RUBY = {
    "in": """class TestCase
  def run
    RobotTestingFramework::testMeasure("tracking error", 0.012, "rad", 0, 0.05)
    RobotTestingFramework::testMeasure("loop rate", 99.5, "Hz")
    RobotTestingFramework::testMeasure("steps", 3)
  end
end
""",
    "out": """class TestCase
  def run
    RobotTestingFramework::testMeasure("tracking error", 0.12, "rad", 0, 0.05)
    RobotTestingFramework::testReport("went on after the measurement")
  end
end
""",
    "bad": """class TestCase
  def run
    RobotTestingFramework::testMeasure("tracking error", 1.0, "u" * 65)
  end
end
""",
}
EXEC = {
    "in": """#!/bin/sh
echo 'TAP version 14'
echo '1..1'
echo 'ok 1 - arm tracks'
echo '  ---'
echo '  measurements:'
echo '    - name: tracking error'
echo '      value: 0.012'
echo '      unit: rad'
echo '      low: 0'
echo '      high: 0.05'
echo '    - name: loop rate'
echo '      value: 99.5'
echo '      unit: Hz'
echo '    - name: steps'
echo '      value: 3'
echo '  ...'
""",
    "out": """#!/bin/sh
echo 'TAP version 14'
echo '1..1'
echo 'ok 1 - arm tracks'
echo '  ---'
echo '  measurements:'
echo '    - name: tracking error'
echo '      value: 0.12'
echo '      unit: rad'
echo '      low: 0'
echo '      high: 0.05'
echo '  ...'
""",
    "bad": """#!/bin/sh
echo 'TAP version 14'
echo '1..1'
echo 'ok 1 - arm tracks'
echo '  ---'
echo '  measurements:'
echo '    - name: tracking error'
echo '      value: .nan'
echo '  ...'
""",
}
LANGUAGES = {"py": ("py", PYTHON), "lua": ("lua", LUA), "rb": ("rb", RUBY),
             "exec": ("sh", EXEC)}
OUTSIDE = "measurement 'tracking error' = 0.12 rad, outside its limits [0, 0.05] rad"
BAD = {"cpp": "not a finite number", "py": "not a finite number", "exec": "not a finite number",
       "lua": "empty", "rb": "65 bytes"}


def write_suites(tmp_path):
    """Two suites (so -j 2 runs them at once): C++, Python and exec; Lua and Ruby. Each test is
    named <language>-<case>; the files are relative to the suites' folder."""
    first = [f'  <test name="cpp-{case}" param="{case}">{plugin("measuring_test")}</test>'
             for case in ("in", "out", "nan")]
    second = []
    for language, (ext, scripts) in LANGUAGES.items():
        for case, text in scripts.items():
            path = tmp_path / f"{language}_{case}.{ext}"
            path.write_text(text)
            path.chmod(0o755)
            line = f'  <test name="{language}-{case}">{path.name}</test>'
            (first if language in ("py", "exec") else second).append(line)
    for name, lines in (("first", first), ("second", second)):
        (tmp_path / f"{name}.xml").write_text(
            f'<suite name="{name}">\n' + "\n".join(lines) + "\n</suite>\n")
    return ["--suite", "first.xml", "--suite", "second.xml"]


def ctrf_tests(report):
    return {t["name"]: t for t in report["results"]["tests"]}


@pytest.mark.parametrize("isolation,jobs", [("none", "1"), ("process", "1"), ("process", "2")])
def test_measurements_reach_every_report_in_every_language(tmp_path, isolation, jobs):
    args = write_suites(tmp_path)
    r = run_runner("--isolation", isolation, "-j", jobs, *args, "-o", "text:r.txt",
                   "-o", "junit:r.xml", "-o", "tap:r.tap", "-o", "json:r.json",
                   "-o", "html:r.html", cwd=tmp_path, timeout=150)
    if "is not supported by this build" in r.output:
        pytest.fail("every language must be built for this test\n" + r.output)
    assert r.returncode == 1, r
    languages = ["cpp", *LANGUAGES]

    # CTRF: schema-valid; each measurement under extra["robotology.rtf"].measurements.
    tests = ctrf_tests(validate_ctrf(tmp_path / "r.json"))
    for language in languages:
        inside = tests[f"{language}-in"]
        assert inside["status"] == "passed", inside
        measured = inside["extra"]["robotology.rtf"]["measurements"]
        assert [(m["name"], m["value"], m["unit"]) for m in measured] == [
            ("tracking error", 0.012, "rad"), ("loop rate", 99.5, "Hz"), ("steps", 3, "")], inside
        assert measured[0]["low"] == 0 and measured[0]["high"] == 0.05 and measured[0]["passed"]
        assert "low" not in measured[1] and "high" not in measured[1]

        outside = tests[f"{language}-out"]
        assert outside["status"] == "failed", outside
        assert outside["extra"]["robotology.rtf"]["state"] == "failed", outside
        assert OUTSIDE in outside["message"], outside
        assert outside["extra"]["robotology.rtf"]["measurements"][0]["passed"] is False
        bad = tests[f"{language}-{'nan' if language == 'cpp' else 'bad'}"]
        assert bad["extra"]["robotology.rtf"]["state"] == "error", bad
        assert BAD[language] in bad["message"], bad
        assert "measurements" not in bad["extra"]["robotology.rtf"], bad
    # The test goes on after a measurement outside its limits (scripts and C++ alike).
    text = (tmp_path / "r.txt").read_text()
    assert "measurement: tracking error = 0.012 rad (limits [0, 0.05] rad)" in text, text

    # JUnit: strict-valid (the readers recount it), measurements as Jenkins reads them from
    # <system-out>, the failure naming the limits.
    validate_junit(tmp_path / "r.xml")
    cases = {c.get("name"): c for c in ET.parse(tmp_path / "r.xml").getroot().iter("testcase")}
    for language in languages:
        out = cases[f"{language}-in"].find("system-out")
        assert out is not None, ET.tostring(cases[f"{language}-in"])
        lines = out.text.splitlines()
        assert "[[PROPERTY|tracking error=0.012]]" in lines, out.text
        assert "[[PROPERTY|loop rate=99.5]]" in lines, out.text
        failure = cases[f"{language}-out"].find("failure")
        assert failure is not None and OUTSIDE in failure.get("message"), language

    # TAP: strict-valid, the measurements in each point's YAML block.
    parsed = validate_tap(tmp_path / "r.tap")
    assert parsed["fail"] >= 1, parsed
    tap = (tmp_path / "r.tap").read_text()
    assert tap.count("measurements:") >= 2 * len(languages), tap
    assert re.search(r'- name: "tracking error"\n\s+value: 0\.012\n\s+unit: "rad"\n'
                     r'\s+low: 0\n\s+high: 0\.05\n\s+passed: true', tap), tap

    # HTML: the page's data holds each test's measurement table.
    html = (tmp_path / "r.html").read_text()
    assert '"measurements":[{"name":"tracking error","value":0.012,"unit":"rad","low":0,' \
           '"high":0.05,"passed":true' in html


def test_the_console_shows_a_measurement_outside_its_limits(tmp_path):
    r = run_runner("--isolation", "process", "--no-output", "--test", plugin("measuring_test"),
                   "--param", "out", cwd=tmp_path)
    assert r.returncode == 1, r
    assert OUTSIDE in r.output, r


def test_a_measurement_of_a_repeated_test_is_kept_per_repetition(tmp_path):
    (tmp_path / "rep.py").write_text(PYTHON["in"])
    (tmp_path / "s.xml").write_text('<suite name="s">\n  <test name="rep" repetition="3">'
                                    'rep.py</test>\n</suite>\n')
    r = run_runner("--suite", "s.xml", "-o", "json:r.json", cwd=tmp_path)
    assert r.returncode == 0, r
    test = ctrf_tests(validate_ctrf(tmp_path / "r.json"))["rep"]
    measured = test["extra"]["robotology.rtf"]["measurements"]
    assert [m["repetition"] for m in measured if m["name"] == "loop rate"] == [1, 2, 3], test
