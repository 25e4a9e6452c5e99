"""An RTF 2.x plug-in, fixture and suite file work unchanged, in both isolation modes: run as
users run them, from their folder and named relatively."""
import pytest

from conftest import PLUGIN_DIR, plugin, run_runner, validate_junit


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_rtf2_plugin_fixture_and_suite_run_unchanged(tmp_path, isolation):
    # The old root spelling, bare plug-in names found through the library path.
    suite = tmp_path / "rtf2.xml"
    suite.write_text("""<?xml version="1.0" encoding="UTF-8"?>
<suit name="rtf2 suite">
    <description>an RTF 2.x suite</description>
    <environment>--robot icubSim</environment>
    <fixture param="--from sim.ini">rtf2_style_fixture</fixture>
    <test type="dll" param="--part left_arm">rtf2_style_test</test>
</suit>
""")
    junit = tmp_path / "r.xml"
    run = run_runner("-v", "--isolation", isolation, "-s", "rtf2.xml", "-o", "junit:r.xml",
                     cwd=tmp_path, env={"LD_LIBRARY_PATH": str(PLUGIN_DIR)})
    assert run.returncode == 0, run
    assert "passed" in run.stdout and "Rtf2StyleTest" in run.stdout, run
    assert "param: --part left_arm" in run.stdout, run
    assert "rtf2 fixture is setting up the world" in run.stdout, run
    assert "suit" in run.stderr, run  # the warning about the old root spelling
    assert run.stdout.rstrip().endswith("1 passed, 0 failed"), run
    validate_junit(junit)


# Written as RTF 2.x's documentation and examples write them.
RTF2_PYTHON_NO_IMPORT = """
class TestCase:
    def setup(self, param):
        robottestingframework.setName("Rtf2PythonTest")
        robottestingframework.testReport("setup with " + param)
        return True

    def run(self):
        robottestingframework.testReport("env: " + robottestingframework.getEnvironment())
        robottestingframework.testCheck(5 > 3, "5 is bigger than 3")
        robottestingframework.testCheck(%s, "the checked condition")

    def tearDown(self):
        robottestingframework.testReport("tearing down")
"""

RTF2_LUA = """
TestCase.setup = function(parameter)
    robottestingframework.setName("Rtf2LuaTest")
    robottestingframework.testReport("setup with " .. parameter)
    return true
end

TestCase.run = function()
    robottestingframework.testReport("env: " .. robottestingframework.getEnvironment())
    robottestingframework.testCheck(5 > 3, "5 is bigger than 3")
    robottestingframework.testFail(%s, "testFail's condition")
end

TestCase.tearDown = function()
    robottestingframework.testReport("tearing down")
end
"""


@pytest.mark.parametrize("isolation", ["process", "none"])
@pytest.mark.parametrize("passing", [True, False], ids=["passing", "failing"])
def test_rtf2_python_test_uses_the_module_without_importing_it(tmp_path, isolation, passing):
    script = tmp_path / "rtf2_test.py"
    script.write_text(RTF2_PYTHON_NO_IMPORT % ("True" if passing else "False"))
    run = run_runner("-v", "--isolation", isolation, "--test", script.name, "--param", "--x 1",
                     "--environment", "sim", "--no-output", cwd=tmp_path)
    assert "NameError" not in run.output, run
    assert run.returncode == (0 if passing else 1), run
    assert "Rtf2PythonTest" in run.stdout, run
    assert "setup with --x 1" in run.stdout and "env: sim" in run.stdout, run
    assert "tearing down" in run.stdout, run


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_python_test_that_imports_the_module_still_works(tmp_path, isolation):
    script = tmp_path / "imports.py"
    script.write_text("import robottestingframework\n" + RTF2_PYTHON_NO_IMPORT % "True")
    run = run_runner("-v", "--isolation", isolation, "--test", script.name, "--no-output",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert "env: " in run.stdout and "tearing down" in run.stdout, run


@pytest.mark.parametrize("isolation", ["process", "none"])
@pytest.mark.parametrize("passing", [True, False], ids=["passing", "failing"])
def test_rtf2_lua_test_fills_the_table_that_already_exists(tmp_path, isolation, passing):
    script = tmp_path / "rtf2_test.lua"
    script.write_text(RTF2_LUA % ("true" if passing else "false"))
    run = run_runner("-v", "--isolation", isolation, "--test", script.name, "--param", "--x 1",
                     "--environment", "sim", "--no-output", cwd=tmp_path)
    assert "attempt to index a nil value" not in run.output, run
    assert run.returncode == (0 if passing else 1), run
    assert "Rtf2LuaTest" in run.stdout, run
    assert "setup with --x 1" in run.stdout and "env: sim" in run.stdout, run
    assert "tearing down" in run.stdout, run
    if not passing:
        assert "testFail's condition" in run.output, run


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_lua_test_that_makes_its_own_table_still_works(tmp_path, isolation):
    script = tmp_path / "own_table.lua"
    script.write_text("TestCase = {}\nfunction TestCase.run()\n"
                      "    robottestingframework.testReport(\"own table ran\")\nend\n")
    run = run_runner("-v", "--isolation", isolation, "--test", script.name, "--no-output",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert "own table ran" in run.stdout, run


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_rtf2_headers_bring_what_they_brought(tmp_path, isolation):
    """Plug-ins that compile only because RTF 2.x's headers include each other
    (tests/plugins/rtf2_collector_test.cpp, rtf2_header_fixture.*) build and run."""
    suite = tmp_path / "headers.xml"
    suite.write_text(f"""<suite name="rtf2 headers">
    <fixture param="--answer 42">{plugin("rtf2_header_fixture")}</fixture>
    <test>{plugin("rtf2_collector_test")}</test>
</suite>
""")
    run = run_runner("-v", "--isolation", isolation, "-s", suite.name, "--no-output",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert "rtf2 collector test ran its inner test" in run.stdout, run
    assert "rtf2 header fixture: setting up with 2 argument(s), first --answer" in run.output, run
    assert "rtf2 header fixture: tearing down" in run.output, run
    assert run.stdout.rstrip().endswith("1 passed, 0 failed"), run


# testFailIf as RTF 2.x documents it: "marks the test as failed ... if condition is false".
FAIL_IF_SCRIPTS = {
    "py": """class TestCase:
    def run(self):
        robottestingframework.testFailIf(%s, "the motor is not homed")
""",
    "lua": """TestCase.run = function()
    robottestingframework.testFailIf(%s, "the motor is not homed")
end
""",
    "rb": """class TestCase
  def run
    RobotTestingFramework::testFailIf(%s, "the motor is not homed")
  end
end
""",
}


@pytest.mark.parametrize("isolation", ["process", "none"])
@pytest.mark.parametrize("language", sorted(FAIL_IF_SCRIPTS))
def test_test_fail_if_fails_when_the_condition_is_false_as_in_rtf2(tmp_path, language,
                                                                   isolation):
    true_word, false_word = ("True", "False") if language == "py" else ("true", "false")
    holds = tmp_path / f"holds.{language}"
    holds.write_text(FAIL_IF_SCRIPTS[language] % true_word)
    run = run_runner("--isolation", isolation, "--test", holds.name, "--no-output",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert "the motor is not homed" not in run.output, run

    broken = tmp_path / f"broken.{language}"
    broken.write_text(FAIL_IF_SCRIPTS[language] % false_word)
    run = run_runner("--isolation", isolation, "--test", broken.name, "--no-output",
                     cwd=tmp_path)
    assert run.returncode == 1, run
    assert "the motor is not homed" in run.output, run


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_a_suite_written_without_tests_runs_as_rtf2_ran_it(tmp_path, isolation):
    # RTF 2.0.1's own test TestRunnerLoadSimpleSuite runs exactly this file and command, and
    # expects exit 0 (it was exit 5, "no test to run"). A selection leaving nothing is still 5.
    (tmp_path / "testsuite.xml").write_text("""<?xml version="1.0" encoding="UTF-8"?>

<suite name="test suite">
    <description> a simple test suite</description>
    <environment></environment>
</suite>
""")
    run = run_runner("-v", "--no-output", "--isolation", isolation, "--suite", "testsuite.xml",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert "the suites given have no test" in run.stdout, run
    assert "0 passed, 0 failed" in run.stdout, run
    run = run_runner("--no-output", "--suite", "testsuite.xml", "--filter", "x/y", cwd=tmp_path)
    assert run.returncode == 0, run
