"""-k EXPR (issue 38, friction 2), as pytest's: names matched without case as substrings of a
test's id (suite/test) or of its tags, with and, or, not and parentheses; a malformed expression
is exit 2 naming the column and what was expected. Through the installed runner, from the
suite's folder, every file named relatively."""
import json

import pytest

from conftest import run_runner


def project(folder):
    """robot: arm-fast [nightly], arm-slow, leg-fast [Nightly]; gripper: close [grip]."""
    script = folder / "ok.sh"
    script.write_text("#!/bin/sh\nexit 0\n")
    script.chmod(0o755)
    (folder / "robot.xml").write_text("""<suite name="robot">
  <test type="exec" name="arm-fast" tags="nightly">./ok.sh</test>
  <test type="exec" name="arm-slow">./ok.sh</test>
  <test type="exec" name="leg-fast" tags="Nightly">./ok.sh</test>
</suite>
""")
    (folder / "gripper.xml").write_text("""<suite name="gripper">
  <test type="exec" name="close" tags="grip">./ok.sh</test>
</suite>
""")
    return ["--suite", "robot.xml", "--suite", "gripper.xml"]


def ran(folder):
    report = json.loads((folder / "r.json").read_text())
    return sorted(t["name"] for t in report["results"]["tests"])


@pytest.mark.parametrize("expression, expected", [
    ("fast", ["arm-fast", "leg-fast"]),
    ("ARM", ["arm-fast", "arm-slow"]),                      # without case
    ("robot/arm-f", ["arm-fast"]),                          # the id, suite and all
    ("gripper", ["close"]),                                 # the suite's name
    ("nightly", ["arm-fast", "leg-fast"]),                  # a tag, without case
    ("arm and not slow", ["arm-fast"]),
    ("(arm or leg) and not fast", ["arm-slow"]),
    ("not robot", ["close"]),
    ("grip or slow", ["arm-slow", "close"]),
])
def test_k_selects_as_pytest_does(tmp_path, expression, expected):
    suites = project(tmp_path)
    run = run_runner(*suites, "-k", expression, "-o", "json:r.json", cwd=tmp_path)
    assert run.returncode == 0, run
    assert ran(tmp_path) == expected, run


def test_k_and_filter_and_tag_must_all_match(tmp_path):
    suites = project(tmp_path)
    run = run_runner(*suites, "-k", "fast", "--filter", "robot/*", "--tag", "nightly",
                     "--exclude-tag", "Nightly", "-o", "json:r.json", "--allow-empty",
                     cwd=tmp_path)
    assert run.returncode == 0 and "no test is selected" in run.stderr, run
    run = run_runner(*suites, "-k", "fast", "--filter", "robot/arm*", "-o", "json:r.json",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert ran(tmp_path) == ["arm-fast"], run


def test_k_selecting_nothing_is_exit_5_naming_it(tmp_path):
    suites = project(tmp_path)
    run = run_runner(*suites, "-k", "knee", cwd=tmp_path)
    assert run.returncode == 5, run
    assert "no test is selected (by -k," in run.stderr, run


@pytest.mark.parametrize("expression, message", [
    ("arm and", "-k 'arm and': at column 8: expected a name, 'not' or '('; got the end"),
    ("(arm or leg", "-k '(arm or leg': at column 12: expected ')' (for the '(' at column 1)"),
    ("arm leg", "-k 'arm leg': at column 5: expected 'and', 'or' or the end; got the name 'leg'"),
    ("or arm", "-k 'or arm': at column 1: expected a name, 'not' or '('; got 'or'"),
])
def test_a_malformed_k_is_exit_2_naming_the_column_and_what_was_expected(
        tmp_path, expression, message):
    suites = project(tmp_path)
    run = run_runner(*suites, "-k", expression, cwd=tmp_path)
    assert run.returncode == 2, run
    assert message in run.stderr, run
    assert not (tmp_path / "result.txt").exists()


def test_k_with_list_shows_the_selection(tmp_path):
    suites = project(tmp_path)
    run = run_runner(*suites, "-k", "leg or close", "--list", cwd=tmp_path)
    assert run.returncode == 0, run
    assert "leg-fast" in run.stdout and "close" in run.stdout, run
    assert "arm-fast" not in run.stdout and "arm-slow" not in run.stdout, run
