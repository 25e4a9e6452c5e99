"""Tests run as a user runs them: an empty environment (`env -i PATH=$PATH`: no
PYTHONUNBUFFERED, no locale, no HOME, no TERM, no TMPDIR), from the tests' own folder with
relative paths, in both isolation modes. Everything a test of each language writes, flushed or
not, is in the JUnit and the CTRF reports (issue 25: a Python test's print() was lost on every
machine without PYTHONUNBUFFERED=1)."""
import json
import shutil

import pytest

from conftest import empty_environment, plugin, run_runner

ISOLATIONS = ["none", "process"]


@pytest.fixture(params=ISOLATIONS)
def isolation(request):
    return request.param


def run_as_a_user(folder, isolation, *args, **more):
    """Runs the runner in `folder` with an environment of PATH alone (plus `more`), writing
    report.xml (JUnit) and report.json (CTRF) there; returns the run and both reports' text."""
    r = run_runner("--isolation", isolation, *args, "-o", "junit:report.xml",
                   "-o", "json:report.json", cwd=folder, env=empty_environment(**more),
                   inherit=False)
    if "is not supported by this build" in r.output:
        pytest.skip("this build leaves the language out (its development files were missing)")
    junit = (folder / "report.xml").read_text()
    # What the tests printed, as CTRF holds it (a list of lines per test, and the fixtures').
    ctrf = json.dumps(json.loads((folder / "report.json").read_text()))
    return r, junit, ctrf


def assert_reported(words, r, junit, ctrf):
    for word in words:
        assert word in junit, f"{word} missing from the JUnit report\n{junit}\n{r}"
        assert word in ctrf, f"{word} missing from the CTRF report\n{ctrf}\n{r}"


def write(folder, name, text):
    path = folder / name
    path.write_text(text)
    return path


# --- Python ---------------------------------------------------------------------------------

PYTHON_TESTS = {
    "passes.py": """import sys
import threading


class TestCase:
    def run(self):
        print("PY-PASS-PRINT")
        sys.stdout.write("PY-PASS-WRITE\\n")
        print("PY-PASS-STDERR", file=sys.stderr)
        worker = threading.Thread(target=lambda: print("PY-PASS-THREAD"))
        worker.start()
        worker.join()
        robottestingframework.testCheck(True, "fine")
        print("PY-PASS-UNENDED", end="")
""",
    "fails.py": """class TestCase:
    def run(self):
        print("PY-FAIL-PRINT")
        robottestingframework.testCheck(False, "deliberate failure")
        print("PY-FAIL-AFTER")
""",
    "raises.py": """class TestCase:
    def setup(self, param):
        print("PY-RAISE-SETUP")
        return True

    def run(self):
        print("PY-RAISE-PRINT")
        raise RuntimeError("deliberate error")

    def tearDown(self):
        print("PY-RAISE-TEARDOWN")
""",
    "exits.py": """import os


class TestCase:
    def run(self):
        print("PY-EXIT-FLUSHED", flush=True)
        os._exit(3)
""",
}

PYTHON_FIXTURE = """class FixtureManager:
    def setup(self, param):
        print("PY-FIXTURE-SETUP")
        return True

    def tearDown(self):
        print("PY-FIXTURE-TEARDOWN")
"""

PYTHON_WORDS = ["PY-PASS-PRINT", "PY-PASS-WRITE", "PY-PASS-STDERR", "PY-PASS-THREAD",
                "PY-PASS-UNENDED", "PY-FAIL-PRINT", "PY-FAIL-AFTER", "PY-RAISE-SETUP",
                "PY-RAISE-PRINT", "PY-RAISE-TEARDOWN", "PY-EXIT-FLUSHED"]
# CTRF keeps the fixtures' output of a suite whose fixture failed only (docs/reference/ctrf.md): these
# are looked for in the JUnit report (the suite's <system-out>).
PYTHON_FIXTURE_WORDS = ["PY-FIXTURE-SETUP", "PY-FIXTURE-TEARDOWN"]


def python_suite(folder):
    for name, text in PYTHON_TESTS.items():
        write(folder, name, text)
    write(folder, "world.py", PYTHON_FIXTURE)
    tests = "\n".join(f"  <test>{name}</test>" for name in PYTHON_TESTS)
    return write(folder, "python.xml", f"""<suite name="python">
  <fixture>world.py</fixture>
{tests}
</suite>
""")


# RTF_PRESTART=0: every worker starts its own interpreter instead of a fork of a pre-started one.
@pytest.mark.parametrize("prestart", ["1", "0"], ids=["prestarted", "started-per-test"])
def test_python_output_flushed_or_not_reaches_the_reports(tmp_path, isolation, prestart):
    python_suite(tmp_path)
    r, junit, ctrf = run_as_a_user(tmp_path, isolation, "--suite", "python.xml",
                                   RTF_PRESTART=prestart)
    assert "1 passed, 3 failed" in r.stdout, r
    assert_reported(PYTHON_WORDS, r, junit, ctrf)
    for word in PYTHON_FIXTURE_WORDS:
        assert word in junit, f"{word} missing from the JUnit report\n{junit}\n{r}"


def test_a_failing_python_fixtures_output_reaches_the_reports(tmp_path, isolation):
    write(tmp_path, "passes.py", PYTHON_TESTS["passes.py"])
    write(tmp_path, "broken.py", """class FixtureManager:
    def setup(self, param):
        print("PY-BROKEN-FIXTURE-SETUP")
        return False
""")
    write(tmp_path, "broken.xml", """<suite name="broken">
  <fixture>broken.py</fixture>
  <test>passes.py</test>
</suite>
""")
    r, junit, ctrf = run_as_a_user(tmp_path, isolation, "--suite", "broken.xml")
    assert r.returncode == 1, r
    assert_reported(["PY-BROKEN-FIXTURE-SETUP"], r, junit, ctrf)


def test_a_python_test_stopped_by_its_timeout_keeps_what_it_printed(tmp_path, isolation):
    write(tmp_path, "sleeps.py", """import time


class TestCase:
    def run(self):
        print("PY-BEFORE-THE-SLEEP")
        time.sleep(60)
""")
    r, junit, ctrf = run_as_a_user(tmp_path, isolation, "--test", "sleeps.py", "--timeout", "2")
    assert r.returncode == 1 and "timed out" in r.output, r
    assert_reported(["PY-BEFORE-THE-SLEEP"], r, junit, ctrf)


# --- Lua, Ruby, exec, C++ -------------------------------------------------------------------

def test_lua_output_reaches_the_reports(tmp_path, isolation):
    write(tmp_path, "prints.lua", """TestCase = {}
function TestCase.run()
    print("LUA-PRINT")
    io.write("LUA-WRITE\\n")
    io.stderr:write("LUA-STDERR\\n")
    robottestingframework.testCheck(true, "fine")
    io.write("LUA-UNENDED")
end
""")
    r, junit, ctrf = run_as_a_user(tmp_path, isolation, "--test", "prints.lua")
    assert r.returncode == 0, r
    assert_reported(["LUA-PRINT", "LUA-WRITE", "LUA-STDERR", "LUA-UNENDED"], r, junit, ctrf)


def test_ruby_output_reaches_the_reports(tmp_path, isolation):
    write(tmp_path, "prints.rb", """class TestCase
  def run
    puts "RUBY-PUTS"
    $stdout.write("RUBY-WRITE\\n")
    $stderr.puts "RUBY-STDERR"
    RobotTestingFramework::testCheck(true, "fine")
    print "RUBY-UNENDED"
  end
end
""")
    r, junit, ctrf = run_as_a_user(tmp_path, isolation, "--test", "prints.rb")
    assert r.returncode == 0, r
    assert_reported(["RUBY-PUTS", "RUBY-WRITE", "RUBY-STDERR", "RUBY-UNENDED"], r, junit, ctrf)


def test_an_exec_scripts_output_reaches_the_reports(tmp_path, isolation):
    script = write(tmp_path, "prints.sh", """#!/bin/sh
echo EXEC-STDOUT
echo EXEC-STDERR >&2
printf EXEC-UNENDED
""")
    script.chmod(0o755)
    r, junit, ctrf = run_as_a_user(tmp_path, isolation, "--test", "prints.sh")
    assert r.returncode == 0, r
    assert_reported(["EXEC-STDOUT", "EXEC-STDERR", "EXEC-UNENDED"], r, junit, ctrf)


def test_a_cpp_plugins_unflushed_printf_and_cout_reach_the_reports(tmp_path, isolation):
    shutil.copy(plugin("unflushed_printing_test"), tmp_path)
    write(tmp_path, "cpp.xml", """<suite name="cpp">
  <test>unflushed_printing_test</test>
</suite>
""")
    r, junit, ctrf = run_as_a_user(tmp_path, isolation, "--suite", "cpp.xml")
    assert r.returncode == 0, r
    assert_reported(["CPP-PRINTF-LINE", "CPP-COUT-LINE", "CPP-STDERR-LINE", "CPP-COUT-UNENDED",
                     "CPP-PRINTF-UNENDED"], r, junit, ctrf)


def test_the_callers_terminal_and_ci_engine_do_not_reach_the_tests():
    # Issue 40: with TERM=dumb (as many CI runners have it) a pseudo-terminal test kept the
    # caller's TERM and failed. The harness removes what the runner reads of the caller's
    # terminal and CI engine (conftest.CALLER_VARIABLES, tests/user-environment.cmake.in);
    # ./run.sh test passes the same with TERM=dumb, TERM unset, or CI=true.
    import os
    from conftest import CALLER_VARIABLES
    for name in ("TERM", "COLUMNS", "NO_COLOR", "CI", "CI_NODE_INDEX", "GTEST_SHARD_INDEX"):
        assert name in CALLER_VARIABLES, name
        assert name not in os.environ, name
