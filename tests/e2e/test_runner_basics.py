"""The runner on passing and failing C++ plug-ins: exit status, console lines, closing line."""
import re

from conftest import plugin, run_runner


def closing_line(run):
    lines = [line for line in run.stdout.splitlines() if line.strip()]
    assert lines, run
    return lines[-1]


def test_passing_plugin_exits_zero(tmp_path):
    run = run_runner("--test", plugin("passing_test"), cwd=tmp_path)
    assert run.returncode == 0, run
    assert re.search(r"^\s*passed\s+(?:.+/)?passing_test.so \(PassingTest\)", run.stdout, re.M), run
    assert closing_line(run) == "1 passed, 0 failed", run


def test_failing_plugin_exits_one_and_shows_the_failure(tmp_path):
    run = run_runner("-t", plugin("passing_test"), "-t", plugin("failing_test"), cwd=tmp_path)
    assert run.returncode == 1, run
    assert re.search(r"^\s*FAILED\s+(?:.+/)?failing_test.so \(FailingTest\)", run.stdout, re.M), run
    assert "two and two make five" in run.stdout, run
    assert closing_line(run) == "1 passed, 1 failed", run


def test_suite_runs_tests_in_document_order(tmp_path, suite_file):
    suite = suite_file(f"""<suite name="ordered">
  <test>{plugin("failing_test")}</test>
  <test>{plugin("passing_test")}</test>
  <test>{plugin("failing_test")}</test>
</suite>""")
    run = run_runner("-s", suite.name, cwd=tmp_path)
    assert run.returncode == 1, run
    # "passed  ID (NAME)": the name each test gives itself, beside its id.
    names = re.findall(r"^\s*(?:passed|FAILED)\s+\S+ \((\w+)\)", run.stdout, re.M)
    assert names == ["FailingTest", "PassingTest", "FailingTest"], run
    assert "suite ordered" in run.stdout, run
    assert closing_line(run) == "1 passed, 2 failed", run


def test_several_suites_and_a_suites_folder(tmp_path):
    folder = tmp_path / "suites"
    (folder / "deeper").mkdir(parents=True)
    (folder / "a.xml").write_text(f'<suite name="first"><test>{plugin("passing_test")}</test></suite>')
    (folder / "b.xml").write_text(f'<suite name="second"><test>{plugin("passing_test")}</test></suite>')
    (folder / "deeper" / "c.xml").write_text(
        f'<suite name="third"><test>{plugin("passing_test")}</test></suite>')
    (folder / "notes.txt").write_text("not a suite")

    run = run_runner("--suites", folder.name, cwd=tmp_path)
    assert run.returncode == 0, run
    assert re.findall(r"^suite (\w+)", run.stdout, re.M) == ["first", "second"], run

    run = run_runner("--suites", folder.name, "-r", cwd=tmp_path)
    assert run.returncode == 0, run
    assert re.findall(r"^suite (\w+)", run.stdout, re.M) == ["first", "second", "third"], run
    assert closing_line(run) == "3 passed, 0 failed", run


def test_tests_folder_runs_every_plugin_in_it(tmp_path):
    folder = tmp_path / "plugins"
    folder.mkdir()
    for name in ("passing_test", "failing_test"):
        (folder / f"{name}.so").symlink_to(plugin(name))
    (folder / "readme.txt").write_text("not a test")
    run = run_runner("--tests", folder.name, cwd=tmp_path)
    assert run.returncode == 1, run
    assert closing_line(run) == "1 passed, 1 failed", run


def test_missing_folder_is_a_usage_error(tmp_path):
    run = run_runner("--suites", "nope", cwd=tmp_path)
    assert run.returncode == 2, run
    assert "nope: not a folder" in run.stderr, run
