"""RTF 2.x's C++ loaders used by a program of the user's own (loader_program/): built with
find_package(RobotTestingFramework) against the build tree and against an installed tree, it
loads RTF 2.x-style Python, Lua and Ruby tests with PythonPluginLoader & co (each program linking
only its language's library), and a fixture with DllFixturePluginLoader and a test with shlibpp."""
import os
import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import BUILD_DIR, LIBDIR

PROGRAM = Path(__file__).parent / "loader_program"


MODULES = BUILD_DIR / LIBDIR / "robottestingframework"
LANGUAGES = [language for language in ("python", "lua", "ruby")
             if (MODULES / f"robottestingframework-{language}.so").is_file()]

# RTF 2.x-style scripts: no import, a TestCase table that already exists, the RTF 2.x API.
SCRIPTS = {
    "python": ("mytest.py", """
class TestCase:
    def setup(self, param):
        robottestingframework.testReport("setup with " + param)
        return True

    def run(self):
        robottestingframework.testReport("env: " + robottestingframework.getEnvironment())
        robottestingframework.testCheck(robottestingframework.getParam() != "--fail",
                                        "param is not --fail")

    def tearDown(self):
        robottestingframework.testReport("tearing down")
""", "class TestCase:\n    def run(self)\n        pass\n", 2),
    "lua": ("mytest.lua", """
TestCase.setup = function(parameter)
    robottestingframework.testReport("setup with " .. parameter)
    return true
end

TestCase.run = function()
    robottestingframework.testReport("env: " .. robottestingframework.getEnvironment())
    robottestingframework.testCheck(robottestingframework.getParam() ~= "--fail",
                                    "param is not --fail")
end

TestCase.tearDown = function()
    robottestingframework.testReport("tearing down")
end
""", "TestCase.run = function()\n    if then\nend\n", 2),
    "ruby": ("mytest.rb", """
class TestCase
  def setup(param)
    RobotTestingFramework::testReport("setup with " + param)
    return true
  end

  def run
    RobotTestingFramework::testReport("env: " + RobotTestingFramework::getEnvironment())
    RobotTestingFramework::testCheck(RobotTestingFramework::getParam() != "--fail",
                                     "param is not --fail")
  end

  def tearDown
    RobotTestingFramework::testReport("tearing down")
  end
end
""", "class TestCase\n  def run(\nend\n", 3),
}


def clean_env():
    """The environment without anything that would point the programs at the build tree."""
    return {key: value for key, value in os.environ.items()
            if key not in ("RTF_LANGUAGE_DIR", "LD_LIBRARY_PATH")}


def run(args, timeout=300, cwd=None):
    result = subprocess.run([str(a) for a in args], capture_output=True, text=True,
                            timeout=timeout, env=clean_env(), cwd=cwd)
    return result


def check(args, timeout=300):
    result = run(args, timeout)
    assert result.returncode == 0, f"{args}\n{result.stdout}\n{result.stderr}"
    return result


def build_program(build, package_option):
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    check(["cmake", "-S", PROGRAM, "-B", build, *generator, package_option,
           "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON"], timeout=180)
    check(["cmake", "--build", build], timeout=600)
    return build


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    prefix = tmp_path_factory.mktemp("prefix")
    check(["cmake", "--install", BUILD_DIR, "--prefix", prefix], timeout=300)
    return prefix


@pytest.fixture(scope="module", params=["build-tree", "install-tree"])
def tree(request, tmp_path_factory):
    """(built program folder, lib folder the program should use)."""
    build = tmp_path_factory.mktemp(f"loader-program-{request.param}")
    if request.param == "build-tree":
        return build_program(build, f"-DRobotTestingFramework_DIR={BUILD_DIR}"), BUILD_DIR / LIBDIR
    prefix = request.getfixturevalue("prefix")
    return build_program(build, f"-DCMAKE_PREFIX_PATH={prefix}"), prefix / LIBDIR


def linked(program):
    return check(["ldd", program], timeout=30).stdout


def test_every_built_language_has_its_loader_library(tree):
    build, _ = tree
    built = (build / "built.txt").read_text().split(";")
    assert sorted(b.strip() for b in built if b.strip()) == sorted(LANGUAGES)


@pytest.mark.parametrize("language", LANGUAGES)
def test_program_runs_an_rtf2_script_through_its_loader(tree, tmp_path, language):
    build, lib = tree
    name, text, _, _ = SCRIPTS[language]
    script = tmp_path / name
    script.write_text(text)
    program = build / f"run_{language}"

    passing = run([program, script, "--speed 3"], timeout=120)
    assert passing.returncode == 0, passing.stdout + passing.stderr
    assert "passed 2 of 2" in passing.stdout, passing.stdout
    assert "setup with --speed 3" in passing.stdout, passing.stdout
    assert "env: --robot demo" in passing.stdout, passing.stdout
    assert "tearing down" in passing.stdout, passing.stdout

    failing = run([program, script, "--fail"], timeout=120)
    assert failing.returncode == 1, failing.stdout + failing.stderr
    assert "passed 0 of 2" in failing.stdout, failing.stdout

    # The program links its own language's library, from the tree it was built against, and
    # no interpreter and no other language's library.
    libraries = linked(program)
    title = language.capitalize()
    line = next(l for l in libraries.splitlines() if f"libRobotTestingFramework{title}.so" in l)
    assert Path(line.split("=>")[1].split("(")[0].strip()).resolve().parent == lib.resolve(), line
    others = [l for l in libraries.splitlines()
              if any(x in l for x in ("libpython", "libruby", "liblua"))
              or any(f"libRobotTestingFramework{o.capitalize()}.so" in l
                     for o in ("python", "lua", "ruby") if o != language)]
    assert not others, others


@pytest.mark.parametrize("language", LANGUAGES)
def test_program_gets_the_loaders_error_for_bad_files(tree, tmp_path, language):
    build, _ = tree
    name, _, broken, line = SCRIPTS[language]
    program = build / f"run_{language}"

    missing = run([program, tmp_path / name], timeout=60)
    assert missing.returncode == 2, missing.stdout + missing.stderr
    assert str(tmp_path / name) in missing.stderr and "No such file" in missing.stderr, missing

    syntax = tmp_path / name
    syntax.write_text(broken)
    refused = run([program, syntax], timeout=60)
    assert refused.returncode == 2, refused.stdout + refused.stderr
    assert refused.stdout == "", refused.stdout
    assert str(syntax) in refused.stderr and str(line) in refused.stderr, refused.stderr

    other = tmp_path / ("other.lua" if language != "lua" else "other.py")
    other.write_text("x = 1\n")
    wrong = run([program, other], timeout=60)
    assert wrong.returncode == 2, wrong.stdout + wrong.stderr
    assert str(other) in wrong.stderr and "file, not a" in wrong.stderr, wrong.stderr


def test_program_loads_a_fixture_and_a_shlibpp_test(tree):
    build, _ = tree
    fixture = build / "libdemo_fixture.so"
    test = build / "libdemo_test.so"
    ready = run([build / "run_fixture", fixture, "--ready", test], timeout=60)
    assert ready.returncode == 0, ready.stdout + ready.stderr
    assert "demo fixture: setup with 1 argument(s)" in ready.stdout, ready.stdout
    assert "demo fixture: tear down" in ready.stdout, ready.stdout
    assert "class DemoTest, passed 1 of 1, suites failed 0" in ready.stdout, ready.stdout

    refused = run([build / "run_fixture", fixture, "--not-ready", test], timeout=60)
    assert refused.returncode == 1, refused.stdout + refused.stderr
    assert "suites failed 1" in refused.stdout, refused.stdout

    # A library without the factories: the loaders name the file, nothing crashes.
    no_fixture = run([build / "run_fixture", test, "--ready", test], timeout=60)
    assert no_fixture.returncode == 2, no_fixture.stdout + no_fixture.stderr
    assert str(test) in no_fixture.stderr and "fixture" in no_fixture.stderr, no_fixture.stderr
    no_test = run([build / "run_fixture", fixture, "--ready", fixture], timeout=60)
    assert no_test.returncode == 2, no_test.stdout + no_test.stderr
    assert str(fixture) in no_test.stderr and "fact" in no_test.stderr, no_test.stderr
