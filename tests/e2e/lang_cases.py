"""What every script language must do through the real runner, written once.

A test file subclasses ScriptLanguageCases with its file extension and its scripts (SCRIPTS
below names them); the word MARK in a script marks the line a message must point at. The runner
starts in the scripts' folder and is given each by its name, as users run it."""
import pytest

from conftest import run_runner

ISOLATIONS = ["none", "process"]


def run_isolated(isolation, *args, cwd, **kwargs):
    """Runs the runner in `isolation` mode in the folder `cwd`, without a result file. Skips the
    test when the build leaves the language out."""
    result = run_runner("--isolation", isolation, "--no-output", *args, cwd=cwd, **kwargs)
    if "is not supported by this build" in result.output:
        pytest.skip("this build leaves the language out (its development files were missing)")
    return result


def marked_line(text):
    """1-based number of the line holding MARK."""
    for number, line in enumerate(text.splitlines(), 1):
        if "MARK" in line:
            return number
    raise AssertionError("no MARK in script")


# The scripts each language provides:
#   passing        reports "alive" and passes a check
#   failing_check  a failed check (MARK), then reports "after the check"
#   assert_error   assertError("no robot"), then would report "not reached"
#   assert_fail    assertFail("gave up") (MARK), then would report "not reached"
#   exception      a runtime error raised in a helper (MARK on the raising line)
#   syntax_error   does not parse
#   setup_false    setup returns false; run would report "run was called"
#   param_env      setup reports "setup param=<param>"; run reports "param=<getParam()>"
#                  and "env=<getEnvironment()>"
#   repeat         run reports "run N" with N counting the runs of one loaded test
#   globals        checks a global is unset, then sets it ("fresh globals")
class ScriptLanguageCases:
    ext = ""
    scripts = {}
    exception_text = ""  # how the language names the runtime error of `exception`

    @pytest.fixture(params=ISOLATIONS)
    def isolation(self, request):
        return request.param

    def write(self, folder, key, name=None):
        path = folder / f"{name or key}.{self.ext}"
        path.write_text(self.scripts[key])
        return path

    def test_passing(self, tmp_path, isolation):
        path = self.write(tmp_path, "passing")
        r = run_isolated(isolation, "--test", path.name, "-v", cwd=tmp_path)
        assert r.returncode == 0, r
        assert "alive" in r.output, r
        assert "1 passed, 0 failed" in r.stdout, r

    def test_failing_check_names_its_line_and_goes_on(self, tmp_path, isolation):
        path = self.write(tmp_path, "failing_check")
        line = marked_line(self.scripts["failing_check"])
        r = run_isolated(isolation, "--test", path.name, "-v", cwd=tmp_path)
        assert r.returncode == 1, r
        assert "deliberate failure" in r.output, r
        assert f"{path}:{line}" in r.output, r
        assert "after the check" in r.output, r

    def test_assert_error_stops_the_test(self, tmp_path, isolation):
        path = self.write(tmp_path, "assert_error")
        r = run_isolated(isolation, "--test", path.name, "-v", cwd=tmp_path)
        assert r.returncode == 1, r
        assert "no robot" in r.output, r
        assert "not reached" not in r.output, r

    def test_assert_fail_stops_the_test(self, tmp_path, isolation):
        path = self.write(tmp_path, "assert_fail")
        line = marked_line(self.scripts["assert_fail"])
        r = run_isolated(isolation, "--test", path.name, "-v", cwd=tmp_path)
        assert r.returncode == 1, r
        assert "gave up" in r.output and f"{path}:{line}" in r.output, r
        assert "not reached" not in r.output, r

    def test_runtime_exception_shows_where(self, tmp_path, isolation):
        path = self.write(tmp_path, "exception")
        line = marked_line(self.scripts["exception"])
        r = run_isolated(isolation, "--test", path.name, "-v", cwd=tmp_path)
        assert r.returncode == 1, r
        assert self.exception_text in r.output, r
        assert f"{path}:{line}" in r.output, r

    def test_syntax_error_fails_the_test_with_its_location(self, tmp_path, isolation):
        path = self.write(tmp_path, "syntax_error")
        r = run_isolated(isolation, "--test", path.name, cwd=tmp_path)
        assert r.returncode == 1, r
        assert self.syntax_error_location(path) in r.output, r

    def syntax_error_location(self, path):
        raise NotImplementedError

    def test_setup_returning_false_fails_without_running(self, tmp_path, isolation):
        path = self.write(tmp_path, "setup_false")
        r = run_isolated(isolation, "--test", path.name, "-v", cwd=tmp_path)
        assert r.returncode == 1, r
        assert "setup failed" in r.output, r
        assert "run was called" not in r.output, r

    def test_param_and_environment_from_a_suite(self, tmp_path, isolation, suite_file):
        self.write(tmp_path, "param_env", "probe")
        suite = suite_file(f"""<suite name="lang">
  <environment>--robot sim</environment>
  <test param="--speed 3">probe.{self.ext}</test>
</suite>""")
        r = run_isolated(isolation, "--suite", suite.name, "-v", cwd=tmp_path)
        assert r.returncode == 0, r
        assert "setup param=--speed 3" in r.output, r
        assert "param=--speed 3" in r.output, r
        assert "env=--robot sim" in r.output, r

    def test_param_and_environment_from_the_command_line(self, tmp_path, isolation):
        path = self.write(tmp_path, "param_env")
        r = run_isolated(isolation, "--test", path.name, "-p", "--part head", "-e", "--robot real",
                         "-v", cwd=tmp_path)
        assert r.returncode == 0, r
        assert "param=--part head" in r.output, r
        assert "env=--robot real" in r.output, r

    def test_repetition_runs_the_same_test_again(self, tmp_path, isolation, suite_file):
        self.write(tmp_path, "repeat")
        suite = suite_file(f"""<suite name="lang">
  <test repetition="3">repeat.{self.ext}</test>
</suite>""")
        r = run_isolated(isolation, "--suite", suite.name, "-v", cwd=tmp_path)
        assert r.returncode == 0, r
        assert "run 3" in r.output and "run 4" not in r.output, r

    def test_two_scripts_do_not_see_each_others_globals(self, tmp_path, isolation, suite_file):
        self.write(tmp_path, "globals", "first")
        self.write(tmp_path, "globals", "second")
        suite = suite_file(f"""<suite name="lang">
  <test>first.{self.ext}</test>
  <test>second.{self.ext}</test>
  <test>first.{self.ext}</test>
</suite>""")
        r = run_isolated(isolation, "--suite", suite.name, "-v", cwd=tmp_path)
        assert r.returncode == 0, r
        assert "3 passed, 0 failed" in r.stdout, r
