"""Tags and selection (issue 10, item 3): --tag / --exclude-tag expressions, --filter patterns;
a test not selected is neither run nor reported, a selected test depending on one not selected
is skipped with that reason, and a suite with no selected test sets up no fixture."""
import re
import sys
from pathlib import Path

import pytest

from conftest import marked, plugin, run_runner, validate_junit

PASSING = plugin("passing_test")
ACTOR = Path(__file__).parent / "world" / "actor.py"


@pytest.fixture(params=["process", "none"])
def isolation(request):
    return request.param


def suites(tmp_path):
    """arm (tags robot): left [arm, slow], right [arm], head [head]; legs: knee [leg, slow]
    and a process fixture that would touch world.touched."""
    world = tmp_path / "world.xml"
    world.write_text(f"""<world name="w" logdir="logs">
  <process name="p" command="{sys.executable} {ACTOR} --touch {tmp_path / 'world.touched'}">
    <ready timeout="10s"><file>{tmp_path / 'world.touched'}</file></ready>
  </process>
</world>
""")
    arm = tmp_path / "arm.xml"
    arm.write_text(f"""<suite name="arm" tags="robot">
  <test name="left" tags="arm,slow">{PASSING}</test>
  <test name="right" tags="arm">{PASSING}</test>
  <test name="head" tags="Head,Camera Front" depends="left">{PASSING}</test>
</suite>
""")
    legs = tmp_path / "legs.xml"
    legs.write_text(f"""<suite name="legs">
  <fixture type="process">{world.name}</fixture>
  <test name="knee" tags="leg,slow">{PASSING}</test>
</suite>
""")
    return ["--suite", arm.name, "--suite", legs.name]


def ran(run):
    """The names of the tests the console reports, passed or skipped."""
    return sorted(re.findall(r"^\s+(?:passed|skipped)\s+.+?/(\S+)\s+\(", run.stdout, re.MULTILINE))


@pytest.mark.parametrize("args, expected", [
    (["--tag", "arm"], ["left", "right"]),
    (["--tag", "armANDslow"], ["left"]),
    (["--tag", "arm & slow"], ["left"]),
    (["--tag", "head OR leg"], ["head", "knee"]),
    (["--tag", "slow NOT leg"], ["left"]),
    (["--tag", "NOT robot"], ["knee"]),
    (["--tag", "*cam*"], ["head"]),
    (["--tag", "l?g"], ["knee"]),
    (["--tag", "ROBOT", "--exclude-tag", "slow"], ["head", "right"]),
    (["--tag", "arm", "--tag", "leg"], ["knee", "left", "right"]),
    (["--exclude-tag", "a*"], ["head", "knee"]),
    (["--filter", "arm/*"], ["head", "left", "right"]),
    (["--filter", "*/?ight:legs/*"], ["knee", "right"]),
    (["--filter", "-arm/*"], ["knee"]),
    (["--filter", "arm/*-arm/head:*/r*"], ["left"]),
])
def test_selection_by_tags_and_names(tmp_path, args, expected):
    run = run_runner(*suites(tmp_path), *args, "--list", cwd=tmp_path)
    assert run.returncode == 0, run
    listed = sorted(re.findall(r"^  \w+/(\w+)$", run.stdout, re.MULTILINE))
    assert listed == expected, run


def test_not_selected_is_not_run_nor_reported(tmp_path, isolation, marker):
    junit = tmp_path / "junit.xml"
    run = run_runner(*suites(tmp_path), "--isolation", isolation, "--tag", "arm",
                     "--output", f"junit:{junit.name}", cwd=tmp_path, env=marked(marker),
                     timeout=60)
    assert run.returncode == 0, run
    assert ran(run) == ["left", "right"], run
    assert "legs" not in run.stdout and "head" not in run.stdout, run
    assert re.search(r"^2 passed, 0 failed$", run.stdout, re.MULTILINE), run
    validate_junit(junit)
    xml = junit.read_text()
    assert xml.count("<testcase") == 2 and "<skipped" not in xml, xml
    # The legs suite has no selected test: its world was never started.
    assert not (tmp_path / "world.touched").exists()
    assert not (tmp_path / "logs").exists()


def test_a_selected_test_depending_on_one_not_selected_is_skipped(tmp_path, isolation):
    run = run_runner(*suites(tmp_path), "--isolation", isolation, "--filter", "arm/head",
                     "--no-output", cwd=tmp_path)
    assert run.returncode == 0, run
    assert re.search(r"^\s+skipped\s+.+/head\s+\(", run.stdout, re.MULTILINE), run
    assert "skipped: depends on left, which is not selected" in run.stdout, run
    assert "skipped: skipped" not in run.stdout, run
    assert re.search(r"^0 passed, 0 failed, 1 skipped$", run.stdout, re.MULTILINE), run


def test_the_suite_of_a_selected_test_sets_its_fixtures_up(tmp_path, marker):
    run = run_runner(*suites(tmp_path), "--tag", "leg", "--no-output", cwd=tmp_path,
                     env=marked(marker), timeout=60)
    assert run.returncode == 0, run
    assert ran(run) == ["knee"], run
    assert (tmp_path / "world.touched").exists()


def test_nothing_selected_is_said(tmp_path):
    # An empty selection is an error of its own (exit 5, issue 20), unless --allow-empty.
    run = run_runner(*suites(tmp_path), "--tag", "nothing", "--no-output", cwd=tmp_path)
    assert run.returncode == 5, run
    assert "no test is selected" in run.stderr, run
    assert ran(run) == [], run
    run = run_runner(*suites(tmp_path), "--tag", "nothing", "--no-output", "--allow-empty",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert "warning: no test is selected" in run.stderr, run


@pytest.mark.parametrize("args, expected", [
    (["--tag", "armAND"], "--tag armAND: no tag after AND at column 4 of 'armAND'"),
    (["--tag", "OR leg"], "--tag OR leg: no tag before OR at column 1 of 'OR leg'"),
    (["--exclude-tag", "a NOT"], "--exclude-tag a NOT: no tag after NOT at column 3"),
    (["--tag", "a AND OR b"], "no tag after AND at column 3 of 'a AND OR b'"),
    (["--tag", "  "], "--tag   : an empty tag expression"),
    (["--filter", "arm/*::leg"], "--filter arm/*::leg: an empty pattern at column 7"),
    (["--filter", "arm/*-"], "--filter arm/*-: an empty pattern at column 7"),
    (["--filter", ""], "--filter: the value is empty"),
])
def test_a_malformed_expression_or_filter_is_a_usage_error(tmp_path, args, expected):
    run = run_runner(*suites(tmp_path), *args, "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert expected in run.stderr, run
