"""Python test cases through the real runner (SPEC 2 "Script test cases", 3.2)."""
import glob
import os
import shutil
import subprocess

import pytest

from lang_cases import ScriptLanguageCases, run_isolated, ISOLATIONS

SCRIPTS = {
    "passing": """import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testReport("alive")
        robottestingframework.testCheck(True, "holds")
""",
    "failing_check": """import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testCheck(1 == 2, "deliberate failure")  # MARK
        robottestingframework.testReport("after the check")
""",
    "assert_error": """import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.assertError("no robot")
        robottestingframework.testReport("not reached")
""",
    "assert_fail": """import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.assertFail("gave up")  # MARK
        robottestingframework.testReport("not reached")
""",
    "exception": """def helper():
    return {}["missing"]  # MARK
class TestCase:
    def run(self):
        helper()
""",
    "syntax_error": """class TestCase:
    def run(self)
        pass
""",
    "setup_false": """import robottestingframework
class TestCase:
    def setup(self, param):
        return False
    def run(self):
        robottestingframework.testReport("run was called")
""",
    "param_env": """import robottestingframework
class TestCase:
    def setup(self, param):
        robottestingframework.testReport("setup param=" + param)
        return True
    def run(self):
        robottestingframework.testReport("param=" + robottestingframework.getParam())
        robottestingframework.testReport("env=" + robottestingframework.getEnvironment())
""",
    "repeat": """import robottestingframework
class TestCase:
    def __init__(self):
        self.count = 0
    def run(self):
        self.count += 1
        robottestingframework.testReport("run %d" % self.count)
""",
    "globals": """import robottestingframework
seen = False
class TestCase:
    def run(self):
        global seen
        robottestingframework.testCheck(not seen, "fresh globals")
        seen = True
""",
}


class TestPython(ScriptLanguageCases):
    ext = "py"
    scripts = SCRIPTS
    exception_text = "KeyError: 'missing'"

    def syntax_error_location(self, path):
        return f"{path}:2:18"

    def test_exception_shows_the_traceback(self, tmp_path, isolation):
        path = self.write(tmp_path, "exception")
        r = run_isolated(isolation, "--test", path.name, "-v", cwd=tmp_path)
        assert "Traceback (most recent call last)" in r.output, r
        assert f'File "{path}", line 5, in run' in r.output, r
        assert f'File "{path}", line 2, in helper' in r.output, r

    def test_syntax_error_shows_the_offending_line(self, tmp_path, isolation):
        path = self.write(tmp_path, "syntax_error")
        r = run_isolated(isolation, "--test", path.name, cwd=tmp_path)
        assert "    def run(self)\n" in r.output, r
        assert "SyntaxError: expected ':'" in r.output, r


@pytest.fixture(params=ISOLATIONS)
def isolation(request):
    return request.param


def test_imports_a_neighbour_module(tmp_path, isolation):
    (tmp_path / "robotutil.py").write_text("GAIN = 7\n")
    (tmp_path / "uses.py").write_text("""import robottestingframework
import robotutil
class TestCase:
    def run(self):
        robottestingframework.testCheck(robotutil.GAIN == 7, "neighbour imported")
""")
    r = run_isolated(isolation, "--test", "uses.py", cwd=tmp_path)
    assert r.returncode == 0, r


def test_neighbours_stay_with_their_own_test(tmp_path, isolation, suite_file):
    # Two folders with a helper module of the same name: each test gets its own, and a test in
    # a third folder sees neither.
    for name, value in (("a", 1), ("b", 2)):
        folder = tmp_path / name
        folder.mkdir()
        (folder / "helper.py").write_text(f"VALUE = {value}\n")
        (folder / "check.py").write_text(f"""import robottestingframework
import helper
class TestCase:
    def run(self):
        robottestingframework.testCheck(helper.VALUE == {value}, "own helper")
""")
    (tmp_path / "c").mkdir()
    (tmp_path / "c" / "alone.py").write_text("""import robottestingframework
class TestCase:
    def run(self):
        try:
            import helper
            robottestingframework.testCheck(False, "foreign helper importable")
        except ImportError:
            pass
""")
    suite = suite_file("""<suite name="neighbours">
  <test>a/check.py</test>
  <test>b/check.py</test>
  <test>c/alone.py</test>
</suite>""")
    r = run_isolated(isolation, "--suite", suite.name, "-v", cwd=tmp_path)
    assert r.returncode == 0, r
    assert "3 passed, 0 failed" in r.stdout, r


def test_uses_a_package_from_the_active_virtual_environment(tmp_path, isolation):
    python = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else shutil.which("python3")
    venv = tmp_path / "venv"
    subprocess.run([python, "-m", "venv", "--without-pip", str(venv)], check=True, timeout=120)
    site = glob.glob(str(venv / "lib" / "python3*" / "site-packages"))
    assert site, "the virtual environment has no site-packages"
    package = tmp_path / "venv" / site[0] / "robotpkg"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text("ANSWER = 42\n")
    (tmp_path / "venv_test.py").write_text("""import robottestingframework
import robotpkg
class TestCase:
    def run(self):
        robottestingframework.testCheck(robotpkg.ANSWER == 42, "package from the venv")
""")
    r = run_isolated(isolation, "--test", "venv_test.py", cwd=tmp_path,
                     env={"VIRTUAL_ENV": str(venv)})
    assert r.returncode == 0, r
    # Without the environment the package is not there: the test above proved something.
    r = run_isolated(isolation, "--test", "venv_test.py", cwd=tmp_path,
                     env={"VIRTUAL_ENV": ""})
    assert r.returncode == 1, r
    assert "No module named 'robotpkg'" in r.output, r


def test_import_error_is_a_failed_test_with_traceback(tmp_path, isolation):
    (tmp_path / "broken.py").write_text("import robottestingframework\nimport no_such_module\n")
    r = run_isolated(isolation, "--test", "broken.py", cwd=tmp_path)
    assert r.returncode == 1, r
    assert "ModuleNotFoundError: No module named 'no_such_module'" in r.output, r
    assert f'File "{tmp_path / "broken.py"}", line 2, in <module>' in r.output, r
