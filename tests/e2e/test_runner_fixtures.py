"""Fixture plug-ins: set up in order, torn down in reverse, a failing one skips the suite."""
import re

from conftest import plugin, run_runner


def fixture(log, name, extra=""):
    return f'<fixture param="--log {log} --name {name}{extra}">{plugin("order_fixture")}</fixture>'


def test_fixtures_set_up_in_order_and_torn_down_in_reverse(tmp_path, suite_file):
    log = tmp_path / "fixtures.log"
    suite = suite_file(f"""<suite name="with fixtures">
  {fixture(log, "A")}
  {fixture(log, "B")}
  <test>{plugin("passing_test")}</test>
</suite>""")
    run = run_runner("-s", suite.name, cwd=tmp_path)
    assert run.returncode == 0, run
    lines = log.read_text().splitlines()
    assert lines[:2] == ["setup A", "setup B"], lines
    assert lines[-2:] == ["teardown B", "teardown A"], lines
    assert "check A" in lines, lines   # checked before the test


def test_failing_fixture_skips_the_tests_with_the_reason_and_fails_the_run(tmp_path, suite_file):
    log = tmp_path / "fixtures.log"
    suite = suite_file(f"""<suite name="broken world">
  {fixture(log, "A")}
  {fixture(log, "B", " --fail-setup")}
  {fixture(log, "C")}
  <test>{plugin("passing_test")}</test>
  <test>{plugin("passing_test")}</test>
</suite>""")
    run = run_runner("-s", suite.name, cwd=tmp_path)
    assert run.returncode == 1, run
    lines = log.read_text().splitlines()
    # A was up and is torn down; C was never started.
    assert lines == ["setup A", "setup B", "teardown A"], lines
    skipped = re.findall(r"^\s*skipped\s+\S*passing_test", run.stdout, re.M)
    assert len(skipped) == 2, run
    assert "setup returned false" in run.stdout, run
    # The failed fixture counts once as failed, so the line agrees with the exit status.
    assert "0 passed, 1 failed, 2 skipped" in run.stdout, run


def test_fixture_that_cannot_be_loaded_fails_the_suite_with_the_reason(tmp_path, suite_file):
    suite = suite_file(f"""<suite name="s">
  <fixture>no_such_fixture</fixture>
  <test>{plugin("passing_test")}</test>
</suite>""")
    run = run_runner("-s", suite.name, cwd=tmp_path)
    assert run.returncode == 1, run
    assert "cannot load no_such_fixture" in run.stdout, run
    assert "libno_such_fixture.so" in run.stdout, run
    assert re.search(r"^\s*skipped\s+\S*passing_test", run.stdout, re.M), run
