"""The project's own JUnit schema (schemas/junit.xsd): the runner's reports validate against
it, and it is strict — each way a CI tool would misread a report is rejected, and so is each
thing the strictest readers refuse (Jenkins' xUnit plug-in validates against its junit-10.xsd;
Maven Surefire's XSD orders a test's elements). The reports are read by junitparser and
xunitparser too (conftest.read_junit), with the runner's counts."""
import os
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from conftest import SCHEMA, SOURCE_DIR, junit_state, plugin, run_runner, validate_junit

# The tests below edit reports on purpose (conftest.every_junit_report_is_read).
pytestmark = pytest.mark.edited_reports


def xmllint(path):
    return subprocess.run(["xmllint", "--noout", "--schema", str(SCHEMA), str(path)],
                          capture_output=True, text=True, timeout=60)


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    """A runner report with a passed, a failed, an errored and a skipped test, and output."""
    folder = tmp_path_factory.mktemp("report")
    suite = folder / "suite.xml"
    suite.write_text(f"""<suite name="schema">
  <test>{plugin("passing_test")}</test>
  <test>{plugin("failing_test")}</test>
  <test>{plugin("throw_runtime")}</test>
  <test depends="failing_test">{plugin("printing_test")}</test>
</suite>
""")
    out = folder / "report.xml"
    run = run_runner("-s", suite.name, "-o", f"junit:{out.name}", "-v", cwd=folder)
    assert run.returncode == 1, run
    return out


def test_schema_lies_in_the_repository():
    assert SCHEMA.is_file(), SCHEMA
    assert SCHEMA.resolve().is_relative_to(SOURCE_DIR.resolve()), SCHEMA


def test_runner_report_with_every_state_validates(report, tmp_path):
    read = validate_junit(report)
    assert read[0]["totals"] == {"tests": 4, "failures": 1, "errors": 1, "skipped": 1}, read
    # The optional parts the runner does not write today are accepted too.
    tree = ET.parse(report)
    _add_properties(tree.getroot(), {"name": "robot", "value": "icubSim"})
    with_properties = tmp_path / "properties.xml"
    tree.write(with_properties, encoding="UTF-8", xml_declaration=True)
    validate_junit(with_properties)
    root = ET.parse(report).getroot()
    cases = list(root.iter("testcase"))
    assert any(case.find("failure") is not None for case in cases), ET.tostring(root)
    assert any(case.find("error") is not None for case in cases), ET.tostring(root)
    assert any(case.find("skipped") is not None for case in cases), ET.tostring(root)


def _first(root, tag):
    return next(root.iter(tag))


# Each mutation makes the runner's valid report into one a CI tool would misread.
MUTATIONS = {
    "unknown element": lambda r: ET.SubElement(_first(r, "testcase"), "flaky"),
    "unknown attribute": lambda r: _first(r, "testsuite").set("colour", "red"),
    "testcase without name": lambda r: _first(r, "testcase").attrib.pop("name"),
    "testcase without classname": lambda r: _first(r, "testcase").attrib.pop("classname"),
    "empty testcase name": lambda r: _first(r, "testcase").set("name", ""),
    "testsuite without name": lambda r: _first(r, "testsuite").attrib.pop("name"),
    "testsuite without tests": lambda r: _first(r, "testsuite").attrib.pop("tests"),
    "count not a number": lambda r: _first(r, "testsuite").set("failures", "one"),
    "negative count": lambda r: _first(r, "testsuite").set("errors", "-1"),
    "time not a number": lambda r: _first(r, "testcase").set("time", "1s"),
    "negative time": lambda r: _first(r, "testcase").set("time", "-0.5"),
    "timestamp not a date": lambda r: _first(r, "testsuite").set("timestamp", "yesterday"),
    "skipped and failed": lambda r: ET.SubElement(
        next(c for c in r.iter("testcase") if c.find("failure") is not None), "skipped"),
    "system-out before failure": lambda r: _move_output_first(r),
    "property without value": lambda r: _add_properties(r, {"name": "x"}),
    "flakyFailure beside a failure": lambda r: _after_failure(r, "flakyFailure"),
    "rerunFailure without a failure": lambda r: _first_passing(r).insert(
        0, _attempt("rerunFailure")),
    "rerunError after a failure": lambda r: _after_failure(r, "rerunError"),
    "unknown element in flakyFailure": lambda r: ET.SubElement(
        _flaky(_first_passing(r)), "screenshot"),
    "unknown attribute on flakyFailure": lambda r: _flaky(_first_passing(r)).set("when", "1"),
    # What junit-10.xsd (Jenkins' xUnit plug-in) refuses.
    "status on a testcase": lambda r: _first(r, "testcase").set("status", "passed"),
    "properties under testsuites": lambda r: r.insert(0, _properties({"name": "a", "value": "1"})),
    "properties in a testcase": lambda r: _first(r, "testcase").insert(
        0, _properties({"name": "a", "value": "1"})),
    "testsuite without failures": lambda r: _first(r, "testsuite").attrib.pop("failures"),
    "testsuite without errors": lambda r: _first(r, "testsuite").attrib.pop("errors"),
    "assertions on a testcase": lambda r: _first(r, "testcase").set("assertions", "1"),
    "skipped on testsuites": lambda r: r.set("skipped", "0"),
    # What Surefire's XSD refuses.
    "testsuite without skipped": lambda r: _first(r, "testsuite").attrib.pop("skipped"),
    "failure without type": lambda r: next(r.iter("failure")).attrib.pop("type"),
    "error without type": lambda r: next(r.iter("error")).attrib.pop("type"),
    "attempt without type": lambda r: _flaky(_first_passing(r)).attrib.pop("type"),
    "attempt without stackTrace": lambda r: _bare_attempt(r),
    "attempt text outside stackTrace": lambda r: _set_text(_flaky(_first_passing(r)), "trace"),
    "testcase without time": lambda r: _first(r, "testcase").attrib.pop("time"),
    "time with four decimals": lambda r: _first(r, "testcase").set("time", "0.1234"),
    "two errors": lambda r: _after_failure(r, "error"),
}


def _attempt(tag):
    attempt = ET.Element(tag, {"message": "m", "type": "failed"})
    ET.SubElement(attempt, "stackTrace").text = "trace"
    return attempt


def _bare_attempt(root):
    case = _first_passing(root)
    case.insert(0, ET.Element("flakyFailure", {"message": "m", "type": "failed"}))


def _set_text(element, text):
    element.text = text


def _first_passing(root):
    return next(c for c in root.iter("testcase") if junit_state(c) == "passed")


def _flaky(case):
    attempt = case.find("flakyFailure")
    if attempt is None:
        attempt = _attempt("flakyFailure")
        case.insert(0, attempt)
    return attempt


def _after_failure(root, tag):
    case = next(c for c in root.iter("testcase") if c.find("failure") is not None)
    element = _attempt(tag) if tag != "error" else ET.Element(tag, {"type": "error"})
    case.insert(list(case).index(case.find("failure")) + 1, element)


def test_surefire_attempt_children_validate(report, tmp_path):
    tree = ET.parse(report)
    attempt = _flaky(_first_passing(tree.getroot()))
    for child in ("system-out", "system-err"):
        ET.SubElement(attempt, child).text = child
    case = next(c for c in tree.getroot().iter("testcase") if c.find("failure") is not None)
    case.insert(list(case).index(case.find("failure")) + 1, _attempt("rerunFailure"))
    case = next(c for c in tree.getroot().iter("testcase") if c.find("error") is not None)
    case.insert(list(case).index(case.find("error")) + 1, _attempt("rerunError"))
    good = tmp_path / "surefire.xml"
    tree.write(good, encoding="UTF-8", xml_declaration=True)
    validate_junit(good)


def _properties(attributes):
    properties = ET.Element("properties")
    ET.SubElement(properties, "property", attributes)
    return properties


def _add_properties(root, attributes):
    """One more property on the first suite: into its <properties> (the display names of its
    tests, "rtf.name.S.T", are there already), else a new <properties> first."""
    suite = _first(root, "testsuite")
    properties = suite.find("properties")
    if properties is None:
        suite.insert(0, _properties(attributes))
    else:
        ET.SubElement(properties, "property", attributes)


def _move_output_first(root):
    case = next(c for c in root.iter("testcase") if c.find("failure") is not None)
    out = ET.Element("system-out")
    out.text = "printed"
    case.insert(0, out)


@pytest.mark.parametrize("mutation", sorted(MUTATIONS))
def test_schema_rejects(report, tmp_path, mutation):
    tree = ET.parse(report)
    MUTATIONS[mutation](tree.getroot())
    bad = tmp_path / "bad.xml"
    tree.write(bad, encoding="UTF-8", xml_declaration=True)
    result = xmllint(bad)
    assert result.returncode != 0, f"{mutation}: accepted\n{bad.read_text()}"
    assert "fails to validate" in result.stderr, result.stderr


def test_no_test_or_build_file_reads_outside_the_repository():
    """A bare clone (nothing beside it) must pass: no file names the old schema folder above
    the root. Build trees (a CMakeCache.txt) and .git are not the repository's files."""
    needles = ("../" + "shared", '"shared" / ' + '"schemas"')
    offenders = []
    for folder, subfolders, files in os.walk(SOURCE_DIR):
        subfolders[:] = [d for d in subfolders if d != ".git" and
                         not (Path(folder) / d / "CMakeCache.txt").exists()]
        for name in files:
            path = Path(folder) / name
            if path.suffix not in {".py", ".txt", ".cmake", ".in", ".sh", ".cpp", ".h", ".xml"}:
                continue
            text = path.read_text(errors="replace")
            if any(needle in text for needle in needles):
                offenders.append(str(path.relative_to(SOURCE_DIR)))
    assert not offenders, offenders
