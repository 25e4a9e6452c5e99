"""TAP 14 as exec tests print it, read by the runner as the specification says, each case
compared with the reference parser's verdict (tap-parser): a failing SKIP point, text and
comments inside a subtest or a YAML block, numbers out of order, "bail out!" in any case and
its escaped reason, a stray "# Subtest:" comment. Run from the test's folder, as users do."""
import xml.etree.ElementTree as ET

import pytest

from conftest import run_runner, tap_verdict, validate_junit


def run_tap(folder, name, tap):
    """Writes an exec test printing `tap`, runs it with a JUnit report; returns the run, the
    report's only <testcase> and tap-parser's verdict on the same stream."""
    (folder / f"{name}.tap").write_text(tap)
    script = folder / name
    script.write_text(f"#!/bin/sh\ncat '{name}.tap'\n")
    script.chmod(0o755)
    r = run_runner("--test", f"./{name}", "-o", "junit:report.xml", "-v", cwd=folder)
    validate_junit(folder / "report.xml")
    (case,) = ET.parse(folder / "report.xml").getroot().iter("testcase")
    return r, case, tap_verdict(folder / f"{name}.tap")


def passed(run, case):
    assert run.returncode in (0, 1), run
    verdict = run.returncode == 0
    assert verdict == (case.find("failure") is None and case.find("error") is None), run
    return verdict


def test_a_failing_skip_point_is_no_failure(tmp_path):
    r, case, reference = run_tap(tmp_path, "skipped", """TAP version 14
1..2
ok 1 - opens the gripper
not ok 2 - closes the gripper # SKIP no gripper on this robot
""")
    assert passed(r, case) is True and reference["ok"] is True, (r, reference)
    assert "not ok 2 - closes the gripper # SKIP no gripper on this robot" in r.output, r


def test_text_inside_a_subtest_does_not_end_it(tmp_path):
    r, case, reference = run_tap(tmp_path, "chatty", """TAP version 14
1..1
# Subtest: arm
    1..2
    ok 1 - reaches
calibrating the wrist
# a comment of the program
    ok 2 - grips
ok 1 - arm
""")
    assert passed(r, case) is True and reference["ok"] is True, (r, reference)
    assert "calibrating the wrist" in r.output, r
    # Both points are the subtest's checks (the report's output lists checks with -v).
    assert "arm > ok 2 - grips" in case.find("system-out").text, ET.tostring(case)
    assert "no plan" not in r.output and "planned" not in r.output, r


def test_numbers_out_of_order_are_valid(tmp_path):
    r, case, reference = run_tap(tmp_path, "unordered", """TAP version 14
1..4
ok 1 - first
ok 3 - third
ok 2 - second
ok 4 - fourth
""")
    assert passed(r, case) is True and reference["ok"] is True, (r, reference)
    assert "out of sequence" not in r.output, r


def test_a_number_beyond_the_plan_still_fails(tmp_path):
    r, case, reference = run_tap(tmp_path, "beyond", "TAP version 14\n1..2\nok 1\nok 3\n")
    assert passed(r, case) is False and reference["ok"] is False, (r, reference)
    assert "test number 3 is beyond the plan 1..2" in r.output, r


def test_text_inside_a_yaml_block_does_not_fail(tmp_path):
    r, case, reference = run_tap(tmp_path, "yaml", """TAP version 14
1..2
ok 1 - reaches
  ---
  duration_ms: 12
a line the program printed meanwhile
  reached: true
  ...
ok 2 - grips
""")
    assert passed(r, case) is True and reference["ok"] is True, (r, reference)
    assert "YAML" not in r.output, r
    assert "a line the program printed meanwhile" in r.output, r


@pytest.mark.parametrize("words", ["bail out!", "BAIL OUT!", "Bail Out!"])
def test_bail_out_in_any_case_bails_out(tmp_path, words):
    r, case, reference = run_tap(tmp_path, "bails", f"""TAP version 14
1..2
ok 1 - connects
{words} the robot is gone
ok 2 - never read
""")
    assert passed(r, case) is False and reference["bailout"], (r, reference)
    assert "Bail out! the robot is gone" in r.output, r
    assert "ok 2 - never read" in r.output, r  # output after a bail out, not a check


def test_the_bail_out_reason_is_unescaped(tmp_path):
    r, case, reference = run_tap(tmp_path, "escaped", "TAP version 14\n1..1\n"
                                 "Bail out! fuse \\# 3 blown \\\\ replace it\n")
    assert passed(r, case) is False, r
    assert reference["bailout"] == "fuse # 3 blown \\ replace it", reference
    assert "Bail out! fuse # 3 blown \\ replace it" in r.output, r


def test_a_stray_subtest_comment_names_no_subtest(tmp_path):
    r, case, reference = run_tap(tmp_path, "stray", """TAP version 14
1..2
# Subtest: leftover
ok 1 - first
# Subtest: camera
    1..2
    ok 1 - opens
# Subtest: stray
    not ok 2 - grabs
not ok 2 - camera
""")
    assert passed(r, case) is False and reference["ok"] is False, (r, reference)
    assert "camera > not ok 2 - grabs" in r.output, r
    assert "leftover >" not in r.output and "stray >" not in r.output, r
    assert "planned" not in r.output and "no plan" not in r.output, r
