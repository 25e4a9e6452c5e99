"""RTF 2.x users' projects, unchanged, against the installed package: a CMake project that
registers its tests as RTF 2.x's test helper does (external_project/rtf2_testhelper/: empty and
given params and environments, a fixture reading RTF 2.x's argv, the collector's counts,
WebProgressListener with RTF only), and a Makefile linking RTF 2.x's library names
(external_project/rtf2_makefile/)."""
import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import BUILD_DIR, LIBDIR, plugin, run_runner

PROJECTS = Path(__file__).parent / "external_project"


LANGUAGES = [language for language in ("lua", "python", "ruby")
             if (BUILD_DIR / LIBDIR / f"libRobotTestingFramework{language.capitalize()}.so")
             .exists()]


def clean_env(**more):
    """Nothing pointing at the build tree: the installed package must do on its own."""
    env = {key: value for key, value in os.environ.items()
           if key not in ("RTF_LANGUAGE_DIR", "LD_LIBRARY_PATH")}
    env.update(more)
    return env


def run(args, timeout=300, cwd=None, **more):
    return subprocess.run([str(a) for a in args], capture_output=True, text=True,
                          timeout=timeout, cwd=cwd, env=clean_env(**more))


def check(args, timeout=300, **kwargs):
    result = run(args, timeout, **kwargs)
    assert result.returncode == 0, f"{args}\n{result.stdout}\n{result.stderr}"
    return result


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    prefix = tmp_path_factory.mktemp("prefix")
    check(["cmake", "--install", BUILD_DIR, "--prefix", prefix])
    return prefix


@pytest.fixture(scope="module")
def helper_project(prefix, tmp_path_factory):
    build = tmp_path_factory.mktemp("rtf2-testhelper")
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    check(["cmake", "-S", PROJECTS / "rtf2_testhelper", "-B", build, *generator,
           f"-DCMAKE_PREFIX_PATH={prefix}", "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON"],
          timeout=180)
    check(["cmake", "--build", build], timeout=600)
    return build


def runner(prefix):
    return prefix / "bin" / "robottestingframework-testrunner"


@pytest.mark.parametrize("name,target", [
    ("robottestingframework", "libRobotTestingFramework.so"),
    ("robottestingframework-dll", "libRobotTestingFrameworkDll.so"),
] + [(f"robottestingframework-{language}", f"libRobotTestingFramework{language.capitalize()}.so")
     for language in LANGUAGES])
def test_rtf2_library_names_are_installed(prefix, name, target):
    rtf2 = prefix / LIBDIR / f"lib{name}.so"
    assert rtf2.exists(), sorted(p.name for p in (prefix / LIBDIR).iterdir())
    assert rtf2.resolve() == (prefix / LIBDIR / target).resolve()


def test_helper_registers_tests_as_rtf2_does(helper_project):
    """The command lines CTest holds: an empty PARAM vanished, an empty ENV is an argument."""
    listing = json.loads(check(["ctest", "--test-dir", helper_project,
                                "--show-only=json-v1"], timeout=60).stdout)
    commands = {test["name"]: test["command"][1:] for test in listing["tests"]}
    assert commands["collector_counts"][:7] == ["-v", "--no-output", "--no-summary", "-p", "-e",
                                                "", "--test"], commands["collector_counts"]
    assert commands["param_empty"][3:7] == ["-p", "-e", "robot=icubSim", "--test"]
    assert commands["env_empty"][3:7] == ["-p", "--expect-env", "-e", ""]


def test_helper_project_tests_pass_in_both_isolation_modes(helper_project):
    tests = run(["ctest", "--test-dir", helper_project, "--output-on-failure",
                 "--timeout", "120"], timeout=400)
    assert "100% tests passed" in tests.stdout, tests.stdout + tests.stderr
    for name in ("env_given", "env_empty", "param_empty", "collector_counts", "fixture_loader"):
        assert f" {name} " in tests.stdout and f" {name}.in_process " in tests.stdout, name
    for isolation in ("process", "none"):
        assert f"argv_suite.{isolation} " in tests.stdout, tests.stdout
    assert " web_rtf_only " in tests.stdout, tests.stdout


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_fixture_argv_and_a_collapse_in_its_teardown(prefix, helper_project, tmp_path,
                                                     isolation):
    fixture = helper_project / "libargv_fixture.so"
    test = helper_project / "libenv_given.so"
    suite = tmp_path / "collapse.xml"
    suite.write_text(f"""<suite name="collapse">
  <fixture param="MY_FIXTURE_TEST_PARAM --collapse-in-teardown">{fixture}</fixture>
  <test param="--expect-env robot=icubSim">{test}</test>
</suite>
""")
    result = run([runner(prefix), "-v", "--no-output", "--isolation", isolation, "-e",
                  "robot=icubSim", "--suite", suite], timeout=120)
    output = result.stdout + result.stderr
    assert "argv fixture: argc 2, argv[0] MY_FIXTURE_TEST_PARAM" in output, output
    # The test ran and passed; the collapse reported from tearDown fails the suite, no crash.
    assert result.returncode == 1, output
    assert "collapsed in tearDown" in output, output
    assert "crash" not in result.stdout.lower() and "signal" not in output, output
    # The suite's collapsed fixture counts once as failed, as the exit status says.
    assert "1 passed, 1 failed" in output, output


def test_web_listener_program_links_rtf_only(helper_project):
    program = helper_project / "web_rtf_only"
    needed = check(["readelf", "-d", program], timeout=30).stdout
    assert "libRobotTestingFramework.so" in needed, needed
    assert "Web" not in needed and "httplib" not in needed, needed
    result = run([program], timeout=60)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "answered: HTTP/1.1 200 OK" in result.stdout, result.stdout


def test_makefile_links_rtf2_library_names(prefix, tmp_path):
    check(["make", "-C", PROJECTS / "rtf2_makefile", f"PREFIX={prefix}", f"LIBDIR={LIBDIR}",
           f"OUT={tmp_path}"], timeout=300)
    needed = check(["readelf", "-d", tmp_path / "make_runner"], timeout=30).stdout
    assert "libRobotTestingFramework.so" in needed, needed
    program = run([tmp_path / "make_runner"], timeout=60,
                  LD_LIBRARY_PATH=str(prefix / LIBDIR))
    assert program.returncode == 0, program.stdout + program.stderr
    assert "1 passed, 0 failed" in program.stdout, program.stdout
    for isolation in ("process", "none"):
        for param, status in (("--pass", 0), ("--fail", 1)):
            result = run([runner(prefix), "-v", "--no-output", "--isolation", isolation, "-p",
                          param, "--test", tmp_path / "libmake_test.so"], timeout=60,
                         LD_LIBRARY_PATH=str(prefix / LIBDIR))
            assert result.returncode == status, result.stdout + result.stderr
            assert "built by make" in result.stdout, result.stdout


def test_pkg_config_builds_a_web_listener_program(prefix, tmp_path):
    env = {"PKG_CONFIG_PATH": str(prefix / LIBDIR / "pkgconfig")}
    flags = check(["pkg-config", "--cflags", "--libs", "robottestingframework"], timeout=30,
                  **env).stdout.split()
    static = check(["pkg-config", "--libs", "--static", "robottestingframework"], timeout=30,
                   **env).stdout.split()
    assert "-lRobotTestingFrameworkWeb" in static, static
    program = tmp_path / "web_rtf_only"
    check(["c++", "-std=c++17", PROJECTS / "rtf2_testhelper" / "web_rtf_only.cpp", "-o", program,
           *flags], timeout=120)
    result = run([program], timeout=60, LD_LIBRARY_PATH=str(prefix / LIBDIR))
    assert result.returncode == 0, result.stdout + result.stderr


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_runner_loads_the_web_library_only_to_show_a_page(tmp_path, isolation):
    """WebProgressListener is in RTF; its server (cpp-httplib, OpenSSL) is loaded when used."""
    args = ["--isolation", isolation, "--no-output", "--test", plugin("passing_test")]
    plain = run_runner(*args, cwd=tmp_path, env={"LD_DEBUG": "files"})
    assert plain.returncode == 0, plain
    for library in ("libRobotTestingFrameworkWeb", "libcpp-httplib", "libssl"):
        assert library not in plain.stderr, plain.stderr[-3000:]
    web = run_runner(*args, "-w", "--web-port", "0", cwd=tmp_path, env={"LD_DEBUG": "files"})
    assert web.returncode == 0, web.stdout
    assert "live web page at http://127.0.0.1:" in web.stdout, web.stdout
    assert "libRobotTestingFrameworkWeb" in web.stderr, web.stderr[-3000:]
