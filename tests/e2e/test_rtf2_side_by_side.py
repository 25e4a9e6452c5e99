"""RTF 2.x users' files, written as RTF 2.x's documentation and examples write them, run with
RTF 2.0.1's own runner (Debian's binary packages, unpacked into the build tree by
scripts/rtf2-binaries.sh: the CTest fixture e2e.rtf2_binaries) and with this installed runner,
side by side from the same folder: the same tests run, with the same verdicts and exit status.
The C++ plug-ins are built from the same source twice, against each version's headers and
libraries, as a user rebuilding for RTF 3 does."""
import glob
import os
import re
import subprocess
from pathlib import Path

import pytest

from conftest import BUILD_DIR, LIBDIR, RUNNER, run_runner

RTF2 = BUILD_DIR / "rtf2-binary" / "root"

TEST_PLUGIN = """
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class ArmTest : public TestCase {
public:
    ArmTest() : TestCase("ArmTest") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(2 < 3, "two is less than three"); }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(ArmTest)
"""

FIXTURE_PLUGIN = """
#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class RobotFixture : public FixtureManager {
public:
    bool setup(int argc, char** argv) override { return true; }
    void tearDown() override {}
};

ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN(RobotFixture)
"""

# A library a project builds beside its plug-ins (a helper its tests link), no RTF plug-in.
HELPER_LIBRARY = "int robot_helper_answer() { return 42; }\n"


def rtf2_folders():
    """RTF 2.0.1's include folder, library folder and runner."""
    include = glob.glob(str(RTF2 / "usr/include/*/robottestingframework/TestCase.h"))
    libs = glob.glob(str(RTF2 / "usr/lib/*/librobottestingframework.so.2"))
    runner = RTF2 / "usr/bin/robottestingframework-testrunner"
    assert include and libs and runner.exists(), f"RTF 2.0.1 is not unpacked in {RTF2}"
    return str(Path(include[0]).parent.parent), str(Path(libs[0]).parent), str(runner)


def rtf3_folders():
    """This version's installed include and library folders (the runner's prefix)."""
    prefix = Path(RUNNER).parent.parent
    return str(prefix / "include"), str(prefix / LIBDIR)


def build(folder, name, source, version):
    """lib<name>.so in `folder`, built against RTF `version` (2 or 3) as its users build it."""
    include, lib = rtf2_folders()[:2] if version == 2 else rtf3_folders()
    folder.mkdir(parents=True, exist_ok=True)
    source_file = folder.parent / f"{name}-{version}.cpp"
    source_file.write_text(source)
    links = ["-lrobottestingframework", "-lrobottestingframework-dll"] if "robottestingframework" \
        in source else []
    subprocess.run(["g++", "-std=c++17", "-shared", "-fPIC", "-o", str(folder / f"lib{name}.so"),
                    str(source_file), f"-I{include}", f"-L{lib}", f"-Wl,-rpath,{lib}", *links],
                   check=True, timeout=180)


def run_rtf2(*args, cwd):
    """RTF 2.0.1's runner, with its libraries found as Debian installed them."""
    lib = rtf2_folders()[1]
    result = subprocess.run([rtf2_folders()[2], *map(str, args)], cwd=cwd, capture_output=True,
                            text=True, timeout=120, env=dict(os.environ, LD_LIBRARY_PATH=lib))
    return result


def rtf2_count(result, what):
    """A count of RTF 2.0.1's closing summary ('Number of passed test cases  : 1')."""
    found = re.search(rf"{what}\s*:\s*(\d+)", result.stdout)
    assert found, result.stdout + result.stderr
    return int(found.group(1))


def closing_line(run):
    return run.stdout.strip().splitlines()[-1]


def test_a_tests_folder_runs_its_test_plugins_and_passes_over_the_other_libraries(tmp_path):
    """An RTF 2.x project's build folder holds its test plug-ins, its fixture plug-ins and its
    other libraries side by side; `--tests FOLDER` ran the test plug-ins and passed over the
    rest (RTF 2.0.1 says so for a fixture plug-in). RTF 3 once ran all three, as failed tests."""
    for version in (2, 3):
        plugins = tmp_path / f"rtf{version}" / "plugins"
        build(plugins, "arm_test", TEST_PLUGIN, version)
        build(plugins, "robot_fixture", FIXTURE_PLUGIN, version)
        build(plugins, "robot_helper", HELPER_LIBRARY, version)

    old = run_rtf2("--tests", "plugins", cwd=tmp_path / "rtf2")
    assert old.returncode == 0, old
    assert rtf2_count(old, "Total number of test cases") == 1, old.stdout
    assert rtf2_count(old, "Number of passed test cases") == 1, old.stdout

    new = run_runner("--tests", "plugins", cwd=tmp_path / "rtf3")
    assert new.returncode == 0, new
    assert closing_line(new) == "1 passed, 0 failed", new
    assert "libarm_test.so" in new.stdout, new
    assert ("plugins/librobot_fixture.so: warning: a fixture plug-in, not a test: passed over"
            in new.stderr), new
    assert ("plugins/librobot_helper.so: warning: not a test plug-in (no "
            "ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN in it): passed over" in new.stderr), new


def test_a_fixture_plugin_named_as_a_test_still_fails_as_in_rtf2(tmp_path):
    """Named one by one (`-t`), a fixture plug-in is no test: RTF 2.0.1 exits 1, and so does
    RTF 3 (the test fails saying it is a fixture plug-in)."""
    for version in (2, 3):
        build(tmp_path / f"rtf{version}", "robot_fixture", FIXTURE_PLUGIN, version)
    old = run_rtf2("-t", "./librobot_fixture.so", cwd=tmp_path / "rtf2")
    assert old.returncode == 1, old
    assert "it is not a Robot Testing Framework test case plugin" in old.stdout, old
    new = run_runner("-t", "./librobot_fixture.so", cwd=tmp_path / "rtf3")
    assert new.returncode == 1, new
    assert "it is a fixture plug-in" in new.stdout, new


LUA_TEST_FAIL = """
TestCase.run = function()
    local x = 0
    robottestingframework.testFail("x > 0", "x is not positive")
    robottestingframework.testReport("the test goes on")
end
"""


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_lua_test_fail_with_the_condition_as_text_fails_the_test_as_in_rtf2(tmp_path, isolation):
    """RTF 2.0.1's Lua testFail(condition, message) takes the condition as text and always
    marks the test failed, the test going on ("checking (x > 0): x is not positive"). RTF 3
    read the text as a true condition: the test passed."""
    (tmp_path / "motor_test.lua").write_text(LUA_TEST_FAIL)
    old = run_rtf2("-v", "-t", "motor_test.lua", "--no-output", cwd=tmp_path)
    assert old.returncode == 1, old
    assert "checking (x > 0): x is not positive" in old.stdout, old
    assert "the test goes on" in old.stdout, old
    assert rtf2_count(old, "Number of failed test cases") == 1, old.stdout

    new = run_runner("-v", "--isolation", isolation, "-t", "motor_test.lua", "--no-output",
                     cwd=tmp_path)
    assert new.returncode == 1, new
    assert "failure: x is not positive: checking (x > 0)" in new.stdout, new
    assert "the test goes on" in new.stdout, new
    assert closing_line(new) == "0 passed, 1 failed", new


@pytest.mark.parametrize("form", [["--repetition", "0"], ["--repetition=0"]])
def test_repetition_zero_rtf2s_default_runs_the_test_once(tmp_path, form):
    """`--repetition 0` is RTF 2.0.1's default (its --help: `(i [=0])`), which scripts and
    CMake files pass when no repetition is wanted: RTF 2.0.1 runs the test once, and so does
    RTF 3 (it was exit 2: 'not a whole number of runs >= 1')."""
    for version in (2, 3):
        build(tmp_path / f"rtf{version}", "arm_test", TEST_PLUGIN, version)
    old = run_rtf2("-v", "-t", "./libarm_test.so", *form, "--no-output", cwd=tmp_path / "rtf2")
    assert old.returncode == 0, old
    assert old.stdout.count("two is less than three") == 1, old.stdout
    new = run_runner("-v", "-t", "./libarm_test.so", *form, "--no-output", cwd=tmp_path / "rtf3")
    assert new.returncode == 0, new
    assert closing_line(new) == "1 passed, 0 failed", new
    assert "repetition" not in new.stdout, new


ARGV_TEST = """
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/TestCase.h>
#include <robottestingframework/dll/Plugin.h>

#include <string>

using namespace robottestingframework;

class ArgvTest : public TestCase {
public:
    ArgvTest() : TestCase("ArgvTest") {}
    bool setup(int argc, char** argv) override {
        for (int i = 1; i < argc; ++i) {
            ROBOTTESTINGFRAMEWORK_TEST_REPORT("argv[" + std::to_string(i) + "]=<" + argv[i] + ">");
        }
        return true;
    }
    void run() override {}
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(ArgvTest)
"""

# Params as RTF 2.x users wrote them: a Windows path, a regular expression, an apostrophe,
# double quotes around words with spaces, a tab, an empty "".
PARAMS = [r"--config C:\robots\arm\config.ini --pattern a\d+\.log",
          "--label robot's arm --name \"left arm\" --empty \"\"",
          "--joint\t3 --speed 10"]


@pytest.mark.parametrize("isolation", ["process", "none"])
@pytest.mark.parametrize("param", PARAMS, ids=["backslashes", "quotes", "tab"])
def test_a_plugins_argv_is_split_as_rtf2_split_it(tmp_path, param, isolation):
    """A C++ test reads its argv as RTF 2.0.1 gave it: words separated by spaces, double quotes
    grouping words, and backslashes, apostrophes and tabs plain characters. RTF 3 split the
    param like a shell: C:\\robots\\arm became C:robotsarm and robot's swallowed the rest."""
    for version in (2, 3):
        build(tmp_path / f"rtf{version}", "argv_test", ARGV_TEST, version)
    old = run_rtf2("-v", "-t", "./libargv_test.so", "-p", param, "--no-output",
                   cwd=tmp_path / "rtf2")
    assert old.returncode == 0, old
    new = run_runner("-v", "--isolation", isolation, "-t", "./libargv_test.so", "-p", param,
                     "--no-output", cwd=tmp_path / "rtf3")
    assert new.returncode == 0, new
    argv = re.findall(r"argv\[\d+\]=<[^>]*>", old.stdout)
    assert argv, old.stdout
    assert re.findall(r"argv\[\d+\]=<[^>]*>", new.stdout) == argv, (old.stdout, new)


LUA_PASSING = """
TestCase.run = function()
    robottestingframework.testCheck(2 < 3, "two is less than three")
end
"""


def test_a_suites_folder_passes_over_xml_that_is_no_suite_as_rtf2_did(tmp_path):
    """A folder of suites beside a robot's XML configuration (a middleware's, a robot
    interface's): RTF 2.0.1 ran the suites and passed the other XML over. RTF 3 stopped with
    exit 2 at 'the root element is <robot>'; it now passes it over with a warning naming it."""
    suites = tmp_path / "suites"
    suites.mkdir()
    (tmp_path / "tests").mkdir()
    (tmp_path / "tests" / "arm_test.lua").write_text(LUA_PASSING)
    (suites / "arm.xml").write_text('<?xml version="1.0" encoding="UTF-8"?>\n'
                                    '<suite name="arm">\n    <test>tests/arm_test.lua</test>\n'
                                    '</suite>\n')
    (suites / "icub.xml").write_text('<?xml version="1.0" encoding="UTF-8"?>\n'
                                     '<robot name="icub" build="1">\n'
                                     '    <device name="left_arm" type="fakeMotionControl"/>\n'
                                     '</robot>\n')
    old = run_rtf2("--suites", "suites", "--no-output", cwd=tmp_path)
    assert old.returncode == 0, old
    assert rtf2_count(old, "Total number of test suites") == 1, old.stdout
    assert rtf2_count(old, "Number of passed test cases") == 1, old.stdout

    new = run_runner("--suites", "suites", "--no-output", cwd=tmp_path)
    assert new.returncode == 0, new
    assert closing_line(new) == "1 passed, 0 failed", new
    assert ("suites/icub.xml: warning: the root element is <robot>, not <suite>: passed over"
            in new.stderr), new


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_a_script_named_bare_in_a_suite_is_found_in_the_current_folder_as_rtf2_did(
        tmp_path, isolation):
    """A project runs `-s suites/arm.xml` from its root, the suite naming `arm_test.lua`: RTF
    2.0.1 opened the script from the current folder. RTF 3 looked beside the suite and on the
    search paths only: 'arm_test.lua' not found, a failed test."""
    (tmp_path / "suites").mkdir()
    (tmp_path / "arm_test.lua").write_text(LUA_PASSING)
    (tmp_path / "suites" / "arm.xml").write_text(
        '<suite name="arm">\n    <test>arm_test.lua</test>\n</suite>\n')
    old = run_rtf2("-s", "suites/arm.xml", "--no-output", cwd=tmp_path)
    assert old.returncode == 0, old
    assert rtf2_count(old, "Number of passed test cases") == 1, old.stdout
    new = run_runner("--isolation", isolation, "-s", "suites/arm.xml", "--no-output",
                     cwd=tmp_path)
    assert new.returncode == 0, new
    assert closing_line(new) == "1 passed, 0 failed", new
