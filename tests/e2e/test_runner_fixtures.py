"""Fixture plug-ins: set up in order, torn down in reverse, a failing one skips the suite."""
import re
import xml.etree.ElementTree as ET

from conftest import SOURCE_DIR, plugin, run_runner, validate_junit


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
    skipped = re.findall(r"^\s*skipped\s+.*?passing_test", run.stdout, re.M)
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
    assert re.search(r"^\s*skipped\s+.*?passing_test", run.stdout, re.M), run


def test_a_failed_fixture_counts_in_junit_as_the_readers_count_and_as_the_readme_says(
        tmp_path, suite_file):
    # Issue 39, 14: one test whose fixture fails is tests="2" (the test skipped, the
    # "fixtures" testcase an error), as junitparser and xunitparser recount it; the README
    # said so in one place and the opposite in another.
    log = tmp_path / "fixtures.log"
    suite = suite_file(f"""<suite name="broken world">
  {fixture(log, "A", " --fail-setup")}
  <test>{plugin("passing_test")}</test>
</suite>""")
    run = run_runner("-s", suite.name, "-o", "out.xml", "--output-type", "junit", cwd=tmp_path)
    assert run.returncode == 1, run
    read = validate_junit(tmp_path / "out.xml")    # the readers' counts equal the report's
    assert read[0]["totals"] == {"tests": 2, "failures": 0, "errors": 1, "skipped": 1}, read
    cases = ET.parse(tmp_path / "out.xml").getroot().findall("testsuite/testcase")
    assert [c.get("name") for c in cases][-1] == "fixtures", [c.get("name") for c in cases]

    # Every sentence of the README and docs/ about the fixtures testcase and tests= says it is
    # counted.
    pages = [SOURCE_DIR / "README.md"] + sorted((SOURCE_DIR / "docs").rglob("*.md"))
    readme = re.sub(r"\s+", " ", " ".join(page.read_text() for page in pages))
    sentences = [s for s in re.split(r"(?<=[.|])\s", readme)
                 if "fixtures" in s and "tests=" in s]
    assert sentences, "the docs say nothing of the fixtures testcase in tests="
    for sentence in sentences:
        assert "not one more test" not in sentence and "not counted" not in sentence, sentence
        assert "counted in `tests=`" in sentence, sentence
