"""The CMake package and pkg-config file, used the way another project uses them: install the
build tree into a prefix, check the layout, then build and run an external project
(external_project/, with rtf2/ written as for RTF 2.x) against the install tree and against the
build tree; bad calls of the CMake functions stop CMake with a message naming the argument."""
import os
import re
import shutil
import socket
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from conftest import BUILD_DIR, LIBDIR, SOURCE_DIR, validate_junit

EXTERNAL = Path(__file__).parent / "external_project"


def run(args, timeout, env=None, cwd=None):
    full_env = dict(os.environ)
    full_env.update(env or {})
    result = subprocess.run([str(a) for a in args], capture_output=True, text=True,
                            timeout=timeout, env=full_env, cwd=cwd)
    return result


def check(args, timeout=300, **kwargs):
    result = run(args, timeout, **kwargs)
    assert result.returncode == 0, f"{args}\n{result.stdout}\n{result.stderr}"
    return result


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    """The build tree installed into a fresh prefix (under the build tree)."""
    prefix = tmp_path_factory.mktemp("prefix")
    check(["cmake", "--install", BUILD_DIR, "--prefix", prefix])
    return prefix


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def configure_and_build(build, package_option):
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    configured = check(["cmake", "-S", EXTERNAL, "-B", build, *generator, "-Wdev", package_option,
                        "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON",
                        f"-DWEB_PORT={free_port()}"], timeout=120)
    assert "CMake Warning" not in configured.stdout + configured.stderr, configured.stderr
    check(["cmake", "--build", build], timeout=300)
    values = dict(line.split("=", 1) for line in
                  (build / "package.txt").read_text().splitlines() if "=" in line)
    return values


def plugin_file(build):
    return build / "libanswer_test.so"


def run_external(build, runner):
    """Runs what configure_and_build built: through `runner`, on its own, and by its ctest."""
    right = run([runner, "--test", plugin_file(build), "--param", "--answer 42", "--no-output"],
                60)
    assert right.returncode == 0, right.stdout + right.stderr
    wrong = run([runner, "--test", plugin_file(build), "--param", "--answer 41", "--no-output"],
                60)
    assert wrong.returncode == 1, wrong.stdout + wrong.stderr

    own = run([build / "own_main"], 60)
    assert own.returncode == 0, own.stdout + own.stderr
    web = run([build / "web_main"], 60)
    assert web.returncode == 0, web.stdout + web.stderr
    assert web.stdout.count("http://127.0.0.1:") == 2, web.stdout

    tests = check(["ctest", "--test-dir", build, "--output-on-failure", "--timeout", "120",
                   "-C", "Debug"], timeout=300)
    assert "100% tests passed" in tests.stdout, tests.stdout
    assert "answer.right" in tests.stdout and "answer.wrong" in tests.stdout
    assert (build / "answer-junit.xml").is_file(), "the JUNIT option wrote no report"
    check_rtf2_part(build / "rtf2", tests.stdout)
    runners = [Path(line).resolve() for line in (build / "runners.txt").read_text().split()]
    assert runners == [Path(runner).resolve()] * 2, runners
    # CONFIGURATIONS: the Release-only suite ran in neither configuration above; it is there
    # for Release.
    assert "rtf2.release_only" not in tests.stdout, tests.stdout
    release = check(["ctest", "--test-dir", build, "-N", "-C", "Release"], timeout=60)
    assert "rtf2.release_only" in release.stdout, release.stdout


def check_rtf2_part(build, ctest_output):
    """What external_project/rtf2/ (RTF 2.x's functions and variables) built and ran."""
    # The suites ran through CTest: the passing one (with WEB_REPORTER, which must neither
    # hang nor fail the test) and the failing one (WILL_FAIL).
    assert "rtf2.suite " in ctest_output and "rtf2.suite_fails" in ctest_output, ctest_output

    # robottestingframework_add_plugin: modules without the lib prefix, OUTPUT_NAME honoured.
    assert (build / "rtf2_answer.so").is_file(), sorted(p.name for p in build.iterdir())
    assert (build / "world_fixture.so").is_file(), sorted(p.name for p in build.iterdir())
    assert not list(build.glob("lib*.so")), sorted(p.name for p in build.iterdir())

    # The generated suite: the fixture with its param words, one <test> per ARGS value.
    suite = ET.parse(build / "rtf2.suite.xml").getroot()
    assert suite.tag == "suite" and suite.get("name") == "rtf2.suite", ET.tostring(suite)
    fixtures = suite.findall("fixture")
    assert [f.get("param") for f in fixtures] == ["--world ready"], ET.tostring(suite)
    assert Path(fixtures[0].text) == (build / "world_fixture.so"), ET.tostring(suite)
    tests = suite.findall("test")
    assert [(t.get("type"), t.get("param")) for t in tests] == [("dll", "--answer 42")] * 2
    assert all(Path(t.text) == build / "rtf2_answer.so" for t in tests), ET.tostring(suite)

    # OUTPUT / OUTPUT_TYPE: a JUnit report of both tests; without OUTPUT the report is named
    # after the suite, in the build folder.
    report = build / "rtf2-suite.xml"
    validate_junit(report)
    cases = list(ET.parse(report).getroot().iter("testcase"))
    assert len(cases) == 2 and all(c.find("failure") is None for c in cases), report.read_text()
    failing = build / "rtf2.suite_fails-result.xml"
    validate_junit(failing)
    cases = list(ET.parse(failing).getroot().iter("testcase"))
    assert [c.find("failure") is not None for c in cases] == [False, True], failing.read_text()

    # The package's RTF 2.x variables.
    values = dict(line.split("=", 1) for line in
                  (build / "package.txt").read_text().splitlines() if "=" in line)
    includes = [Path(d) for d in values["include_dirs"].split(";") if d]
    assert any((d / "robottestingframework" / "TestCase.h").is_file() for d in includes), values
    assert len(includes) == len(set(includes)), values
    libraries = values["libraries"].split(";")
    assert {"RobotTestingFramework::RTF", "RobotTestingFramework::RTF_dll"} <= set(libraries)
    assert values["dll_found"] == "TRUE", values
    assert values["runner_target"] == "YES", values
    assert Path(values["runner"]).is_file(), values


def test_install_layout(prefix):
    expected = [
        "include/robottestingframework/TestCase.h",
        "include/robottestingframework/TestAssert.h",
        "include/robottestingframework/dll/Plugin.h",
        f"{LIBDIR}/libRobotTestingFramework.so",
        f"{LIBDIR}/libRobotTestingFrameworkDll.so",
        "bin/robottestingframework-testrunner",
        f"{LIBDIR}/cmake/RobotTestingFramework/RobotTestingFrameworkConfig.cmake",
        f"{LIBDIR}/cmake/RobotTestingFramework/RobotTestingFrameworkConfigVersion.cmake",
        f"{LIBDIR}/cmake/RobotTestingFramework/RobotTestingFrameworkTargets.cmake",
        f"{LIBDIR}/cmake/RobotTestingFramework/RobotTestingFrameworkCTest.cmake",
        f"{LIBDIR}/cmake/RobotTestingFramework/RobotTestingFrameworkDiscoverTests.cmake",
        f"{LIBDIR}/cmake/RobotTestingFramework/RobotTestingFrameworkBracket.cmake",
        f"{LIBDIR}/pkgconfig/robottestingframework.pc",
        "share/doc/RobotTestingFramework/README.md",
        "share/doc/RobotTestingFramework/docs/index.md",   # what the README links to
        "share/doc/RobotTestingFramework/examples/suites/example.xml",
    ]
    missing = [path for path in expected if not (prefix / path).exists()]
    assert not missing, f"missing from the install tree: {missing}"
    # Every public header of the source tree is installed.
    headers = SOURCE_DIR / "include" / "robottestingframework"
    for header in headers.rglob("*.h"):
        assert (prefix / "include" / "robottestingframework" /
                header.relative_to(headers)).is_file(), header


# The script language modules this build made (lib/robottestingframework/ of the build tree).
BUILT_MODULES = sorted(p.name for p in (BUILD_DIR / LIBDIR / "robottestingframework")
                       .glob("robottestingframework-*.so"))


def test_language_modules_installed_with_their_rpath(prefix):
    installed = prefix / LIBDIR / "robottestingframework"
    missing = [name for name in BUILT_MODULES if not (installed / name).is_file()]
    assert not missing, f"language modules missing from the install tree: {missing}"
    for name in BUILT_MODULES:
        module = installed / name
        dynamic = check(["readelf", "-d", module], timeout=30).stdout
        assert "[$ORIGIN/..]" in dynamic, dynamic
        ldd = check(["ldd", module], timeout=30).stdout
        assert "not found" not in ldd, ldd
        line = next(l for l in ldd.splitlines() if "libRobotTestingFramework.so" in l)
        found = Path(line.split("=>")[1].split("(")[0].strip())
        assert found.resolve().parent == (prefix / LIBDIR).resolve(), line


PYTHON_TEST = {
    "passing": """import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testReport("installed python works")
""",
    "failing": """import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testCheck(False, "installed python fails")
""",
}


@pytest.mark.skipif("robottestingframework-python.so" not in BUILT_MODULES,
                    reason="Python test cases are not built")
@pytest.mark.parametrize("isolation", ["none", "process"])
def test_installed_runner_runs_python_tests(prefix, tmp_path, isolation):
    """The installed runner (and its installed worker) load the installed Python module."""
    runner = prefix / "bin" / "robottestingframework-testrunner"
    env = {key: value for key, value in os.environ.items() if key != "RTF_LANGUAGE_DIR"}
    for name, status in (("passing", 0), ("failing", 1)):
        script = tmp_path / f"{name}.py"
        script.write_text(PYTHON_TEST[name])
        result = subprocess.run([str(runner), "--isolation", isolation, "--test", str(script),
                                 "--no-output", "-v"], capture_output=True, text=True,
                                timeout=60, env=env)
        output = result.stdout + result.stderr
        assert result.returncode == status, output
        assert f"installed python {'works' if status == 0 else 'fails'}" in output, output


def test_installed_runner_uses_installed_libraries(prefix):
    runner = prefix / "bin" / "robottestingframework-testrunner"
    ldd = check(["ldd", runner], timeout=30).stdout
    assert "not found" not in ldd, ldd
    line = next(l for l in ldd.splitlines() if "libRobotTestingFramework.so" in l)
    found = Path(line.split("=>")[1].split("(")[0].strip())
    assert found.resolve().parent == (prefix / LIBDIR).resolve(), line
    version = check([runner, "--version"], timeout=30)
    assert re.search(r"\b3\.\d+\.\d+", version.stdout + version.stderr), version.stdout


@pytest.fixture(scope="module")
def external_install(prefix, tmp_path_factory):
    """external_project/ configured and built against the install tree."""
    build = tmp_path_factory.mktemp("external-install")
    return build, configure_and_build(build, f"-DCMAKE_PREFIX_PATH={prefix}")


def test_external_project_against_install_tree(prefix, external_install):
    build, values = external_install
    package_dir = prefix / LIBDIR / "cmake" / "RobotTestingFramework"
    assert Path(values["dir"]).resolve() == package_dir.resolve(), values
    runner = prefix / "bin" / "robottestingframework-testrunner"
    assert Path(values["runner"]).resolve() == runner.resolve(), values
    assert values["version"].startswith("3."), values
    run_external(build, runner)


def test_installed_runner_isolates_tests(prefix, external_install):
    """The installed runner finds its installed worker: tests isolated in processes run."""
    build, _ = external_install
    runner = prefix / "bin" / "robottestingframework-testrunner"
    for answer, status in (("42", 0), ("41", 1)):
        isolated = run([runner, "--isolation", "process", "--test", plugin_file(build),
                        "--param", f"--answer {answer}", "--no-output"], 60)
        assert isolated.returncode == status, isolated.stdout + isolated.stderr


def test_external_project_against_build_tree(tmp_path):
    build = tmp_path / "external"
    values = configure_and_build(build, f"-DRobotTestingFramework_DIR={BUILD_DIR}")
    assert Path(values["dir"]).resolve() == BUILD_DIR.resolve(), values
    runner = Path(values["runner"])
    assert runner.resolve() == (BUILD_DIR / "bin" / "robottestingframework-testrunner").resolve()
    run_external(build, runner)


def test_pkg_config(prefix, tmp_path):
    env = {"PKG_CONFIG_PATH": str(prefix / LIBDIR / "pkgconfig")}
    flags = check(["pkg-config", "--cflags", "--libs", "robottestingframework"], timeout=30,
                  env=env).stdout.split()
    assert "-lRobotTestingFramework" in flags and "-lRobotTestingFrameworkDll" in flags, flags
    includes = [Path(f[2:]).resolve() for f in flags if f.startswith("-I")]
    assert (prefix / "include").resolve() in includes, flags
    version = check(["pkg-config", "--modversion", "robottestingframework"], timeout=30,
                    env=env).stdout.strip()
    assert version.startswith("3."), version
    runner = check(["pkg-config", "--variable=testrunner", "robottestingframework"], timeout=30,
                   env=env).stdout.strip()
    assert Path(runner).resolve() == (prefix / "bin" / "robottestingframework-testrunner").resolve()

    # The flags are enough to build and link a program.
    program = tmp_path / "own_main"
    check(["c++", "-std=c++17", EXTERNAL / "own_main.cpp", "-o", program, *flags], timeout=120)
    result = run([program], 60, env={"LD_LIBRARY_PATH": str(prefix / LIBDIR)})
    assert result.returncode == 0, result.stdout + result.stderr


# Bad calls: CMake stops, and the message names the argument that is wrong.
BAD_CALLS = {
    "test without TYPE": ("robottestingframework_add_suite(NAME s "
                          "RobotTestingFramework_TEST t.so ARGS \"--x 1\")",
                          ["RobotTestingFramework_TEST t.so has no TYPE"]),
    "suite without NAME": ("robottestingframework_add_suite("
                           "RobotTestingFramework_TEST t.so TYPE dll)", ["NAME is required"]),
    "suite without tests": ("robottestingframework_add_suite(NAME s WEB_REPORTER)",
                            ["no RobotTestingFramework_TEST"]),
    "option without value": ("robottestingframework_add_suite(NAME s "
                             "RobotTestingFramework_TEST t.so TYPE dll WEB_PORT)",
                             ["WEB_PORT needs a value"]),
    "unknown argument": ("robottestingframework_add_suite(NAME s COLOUR red "
                         "RobotTestingFramework_TEST t.so TYPE dll)",
                         ["unexpected argument \"COLOUR\""]),
    "plugin without sources": ("robottestingframework_add_plugin(p HEADERS p.h)",
                               ["robottestingframework_add_plugin(p)", "SOURCES is required"]),
}


@pytest.mark.parametrize("case", sorted(BAD_CALLS))
def test_bad_call_stops_cmake_naming_the_argument(tmp_path, case):
    call, expected = BAD_CALLS[case]
    source = tmp_path / "src"
    source.mkdir()
    (source / "CMakeLists.txt").write_text(f"""cmake_minimum_required(VERSION 3.16)
project(bad LANGUAGES CXX)
find_package(RobotTestingFramework REQUIRED)
enable_testing()
{call}
""")
    result = run(["cmake", "-S", source, "-B", tmp_path / "build",
                  f"-DRobotTestingFramework_DIR={BUILD_DIR}"], 120)
    assert result.returncode != 0, result.stdout + result.stderr
    message = " ".join((result.stdout + result.stderr).split())
    for part in expected:
        assert part in message, message
    assert "CMakeLists.txt:5" in message, message
