"""Shared helpers for the end-to-end tests: run the real runner on real files."""
import json
import os
import signal
import stat
import subprocess
import time
import uuid
from pathlib import Path

import pytest

RUNNER = os.environ.get("RTF_TESTRUNNER", "")
PLUGIN_DIR = Path(os.environ.get("RTF_TEST_PLUGIN_DIR", "."))
SOURCE_DIR = Path(os.environ.get("RTF_SOURCE_DIR", "."))
BUILD_DIR = Path(os.environ.get("RTF_BUILD_DIR", "."))
# Set by ctest in a build with RTF_SANITIZE=ON (tests/sanitizers/environment.cmake.in).
SANITIZED = os.environ.get("RTF_SANITIZED") == "1"
# The JUnit schema this project writes and owns (schemas/junit.xsd at the root).
SCHEMA = SOURCE_DIR / "schemas" / "junit.xsd"


def cache_value(name, default):
    """A variable of the build tree's CMake cache (the install layout the package tests use)."""
    cache = BUILD_DIR / "CMakeCache.txt"
    if not cache.is_file():  # pytest run by hand outside a build tree
        return default
    for line in cache.read_text().splitlines():
        if line.startswith(name + ":"):
            return line.split("=", 1)[1]
    return default


LIBDIR = cache_value("CMAKE_INSTALL_LIBDIR", "lib")


# What the caller's terminal and CI engine say, which the runner reads: the terminal (the
# progress line and colours), a CI engine's shard and run variables, the runner's own settings.
# A test that cares sets them itself (terminal_environment() for one on a pseudo-terminal), so
# the suite passes the same from a terminal, with TERM=dumb or unset, and under CI=true.
CALLER_VARIABLES = (
    "TERM", "COLUMNS", "LINES", "NO_COLOR", "CLICOLOR", "CLICOLOR_FORCE", "FORCE_COLOR", "CI",
    "TEST_SHARD_INDEX", "TEST_TOTAL_SHARDS", "TEST_SHARD_STATUS_FILE", "XML_OUTPUT_FILE",
    "GTEST_SHARD_INDEX", "GTEST_TOTAL_SHARDS", "CI_NODE_INDEX", "CI_NODE_TOTAL",
    "JOB_COMPLETION_INDEX", "RTF_SHARD_COUNT", "RTF_RUN_ID", "RTF_PLUGIN_PATH", "RTF_PRESTART",
    "GITHUB_RUN_ID", "GITHUB_RUN_ATTEMPT", "CI_PIPELINE_ID", "BUILD_TAG", "BUILDKITE_BUILD_ID",
    "TEST_INVOCATION_ID", "TEST_TMPDIR")


def _changes_a_runtime(name):
    """True for a variable that changes how the runtimes under test behave: the embedded
    Python (PYTHONUNBUFFERED once hid that a test's print() was lost), Ruby, Lua, the dynamic
    loader, the locale, and the caller's terminal and CI engine (CALLER_VARIABLES). A user's
    shell has none of them, or others; tests/user-environment.cmake removes the same ones from
    ctest's environment."""
    return (name.startswith(("PYTHON", "RUBY", "GEM_", "LUA_", "LC_"))
            or name in ("LANG", "LANGUAGE", "VIRTUAL_ENV")
            or name.startswith("LD_")
            or name in CALLER_VARIABLES)


def terminal_environment(**more):
    """The variables of a run on a user's terminal (a colour xterm, 80 columns), for a test
    that starts the runner on a pseudo-terminal: it must not depend on the caller's TERM."""
    return {"TERM": "xterm-256color", "COLUMNS": "80", **more}


# The tests run the runner in a user's environment, not in the developer's: as a fresh
# Debian 12 root has it, no PYTHON*, RUBY*, LUA_*, LD_* and no locale (POSIX). LC_CTYPE goes
# too: Python sets it (C.UTF-8, PEP 538) in its own environment when it starts in the POSIX
# locale. Done here, once, so that every process a test starts inherits it (the runner, and
# the cmake, ctest and python runs that start one). RTF_* stay: they are the harness's.
for _name in [name for name in os.environ if _changes_a_runtime(name)]:
    del os.environ[_name]


def plugin(name):
    """Path of a test plug-in built from tests/plugins/NAME.cpp."""
    return str(PLUGIN_DIR / f"{name}.so")


class Run:
    def __init__(self, proc, stdout, stderr):
        self.returncode = proc.returncode
        self.stdout = stdout
        self.stderr = stderr
        self.output = stdout + stderr

    def __repr__(self):
        return f"<exit {self.returncode}>\n--- stdout\n{self.stdout}\n--- stderr\n{self.stderr}"


def _hosts_ruby(args, cwd):
    """True when a run of the runner with `args`, started in `cwd`, starts the Ruby VM in its
    own process: in process (--isolation none) with a Ruby script named, or named in a suite
    file given (a relative one is found from `cwd`, as the runner finds it)."""
    args = [str(a) for a in args]
    in_process = "--isolation=none" in args or any(
        a == "--isolation" and b == "none" for a, b in zip(args, args[1:]))
    if not in_process:
        return False
    for arg in args:
        if arg.endswith(".rb"):
            return True
        suite = os.path.join(cwd or ".", arg)
        if arg.endswith(".xml") and os.path.isfile(suite):
            with open(suite, errors="replace") as f:
                if ".rb" in f.read():
                    return True
    return False


def _named_relatively(args, cwd):
    """Fails a test that names a file inside `cwd` by its absolute path: users run the runner
    from their suite's folder and name its files relatively, and a test that does not would
    miss what only relative names break (a test about absolute names passes them as
    AbsoluteName, which says so)."""
    if cwd is None:
        return
    folders = {os.path.abspath(cwd) + os.sep, os.path.realpath(cwd) + os.sep}
    for arg in args:
        if isinstance(arg, AbsoluteName):
            continue
        named = [folder for folder in folders if folder in str(arg)]
        if named:
            pytest.fail(f"runner argument {arg!r} names a file in the run's folder {named[0]} by "
                        "its absolute path: name it relative to cwd, as users do")


class AbsoluteName(str):
    """A runner argument that names a file by its absolute path on purpose (a test of
    absolute names)."""


def runner_environment(args, env, inherit=True, cwd=None):
    """The environment of one run of the runner in `cwd`: ours with `env` applied (only `env`
    when not `inherit`). Under the sanitizer job (ctest in build-asan/, tests/sanitizers/), a
    runner that hosts the Ruby VM runs without leak checks: LeakSanitizer crashes on the VM's
    thread at exit. ASan and UBSan stay on."""
    _named_relatively(args, cwd)
    full_env = dict(os.environ) if inherit else {}
    if env:
        full_env.update(env)
    asan = full_env.get("ASAN_OPTIONS", "")
    if "detect_leaks=1" in asan and _hosts_ruby(args, cwd):
        full_env["ASAN_OPTIONS"] = asan.replace("detect_leaks=1", "detect_leaks=0")
    return full_env


def run_runner(*args, cwd, timeout=120, env=None, input=None, inherit=True):
    """Runs the runner with `args` in the folder `cwd`; returns Run (exit status, stdout,
    stderr). `cwd` has no default: users run the runner from their suite's folder and name
    their files relatively, and so do the tests (a test about another folder says so). The
    runner is killed (its whole process group) if it outlives `timeout`. With inherit=False
    its environment is `env` alone (see empty_environment)."""
    assert RUNNER, "RTF_TESTRUNNER is not set (run through ctest)"
    full_env = runner_environment(args, env, inherit, cwd)
    proc = subprocess.Popen([RUNNER, *map(str, args)], cwd=cwd, env=full_env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            stdin=subprocess.PIPE if input else subprocess.DEVNULL,
                            start_new_session=True, text=True, errors="replace")
    try:
        out, err = proc.communicate(input=input, timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        pytest.fail(f"runner did not finish within {timeout} s\n{out}\n{err}")
    return Run(proc, out, err)


def empty_environment(**more):
    """What `env -i PATH=$PATH` gives the runner: an environment of PATH alone (and, under the
    sanitizer job, the sanitizers' options, without which its reports would not fail the
    test). The runner finds its libraries through its rpath. Pass it with inherit=False."""
    env = {"PATH": os.environ.get("PATH", "/usr/bin:/bin")}
    if SANITIZED:
        env.update({name: value for name, value in os.environ.items()
                    if name.endswith("SAN_OPTIONS")})
    env.update(more)
    return env


def validate_junit(*paths):
    """Fails the test unless every one of `paths` validates against the project's JUnit schema
    and the third-party readers read it with the report's own counts (read_junit)."""
    result = subprocess.run(["xmllint", "--noout", "--schema", str(SCHEMA), *map(str, paths)],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    return read_junit(*paths)


# The JUnit readers scripts/python-tools.sh installs into the build tree (a venv of its own).
PYTHON_TOOLS = BUILD_DIR / "python-tools" / "bin" / "python"


def read_junit(*paths):
    """Reads each of `paths` with junitparser and xunitparser; fails the test unless both read
    it and their counts (per suite, in total, after a junitparser merge) equal the report's.
    Returns what they read of each file: suites, totals, junitparser, xunitparser."""
    result = subprocess.run([str(PYTHON_TOOLS), str(TOOLS_DIR / "read_junit.py"),
                             *map(str, paths)], capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, f"read_junit.py:\n{result.stderr}\n{result.stdout}"
    return json.loads(result.stdout)


def runner_junit_reports(folder):
    """Every JUnit report of this runner under `folder` (whatever the file's name): regular
    files that start as the runner's do. Symbolic links and FIFOs are not opened."""
    found = []
    for path in sorted(Path(folder).rglob("*")):
        try:
            if path.is_symlink() or not stat.S_ISREG(path.stat().st_mode):
                continue
            with open(path, "rb") as f:
                head = f.read(300)
        except OSError:
            continue
        if b'<testsuites name="RobotTestingFramework"' in head:
            found.append(path)
    return found


def junit_state(case):
    """A <testcase>'s state as the runner's words say it ("timed out"), read from its elements
    as report_reader.cpp reads them: the reports carry no status= attribute."""
    if case.find("skipped") is not None:
        return "skipped"
    failure = case.find("failure")
    if failure is not None:
        return "timed out" if failure.get("type") == "timeout" else "failed"
    error = case.find("error")
    if error is not None:
        return {"crash": "crashed", "interrupted": "interrupted"}.get(error.get("type"), "error")
    if case.find("flakyFailure") is not None:
        return "flaky"
    return "passed"


def junit_display_names(root):
    """{<testcase>: the name the test gave itself}, from its suite's "rtf.name.S.T" property
    (S the suite's id + 1, T the test's place in it, the fixtures testcase not counted): the
    name beside the id (docs/reference/test-ids.md), where junit-10.xsd lets a report keep it."""
    names = {}
    for suite in root.iter("testsuite"):
        given = {p.get("name"): p.get("value") for p in suite.findall("properties/property")}
        place = int(suite.get("id", "0")) + 1
        cases = [c for c in suite.findall("testcase")
                 if (c.find("error") is None or c.find("error").get("type") != "fixture")]
        for index, case in enumerate(cases, start=1):
            name = given.get(f"rtf.name.{place}.{index}")
            if name is not None:
                names[case] = name
    return names


def pytest_configure(config):
    config.addinivalue_line("markers", "edited_reports: the test edits or forges reports on "
                            "purpose; its reports are not all read by the JUnit readers")


@pytest.fixture(autouse=True)
def every_junit_report_is_read(request):
    """After each test, every JUnit report it left in its folder validates against the schema
    and the third-party readers read it with the runner's counts (see validate_junit)."""
    checked = ("tmp_path" in request.fixturenames and
               not request.node.get_closest_marker("edited_reports"))
    # Asked for before the test, so that the folder outlives this fixture's end.
    folder = request.getfixturevalue("tmp_path") if checked else None
    yield
    reports = runner_junit_reports(folder) if checked else []
    if reports:
        validate_junit(*reports)


# The third-party checkers scripts/node-tools.sh installs into the build tree.
NODE_TOOLS = BUILD_DIR / "node-tools" / "node_modules"
TOOLS_DIR = Path(__file__).resolve().parent / "tools"


def _node_check(script, path):
    result = subprocess.run(["node", str(TOOLS_DIR / script), str(path)], capture_output=True,
                            text=True, timeout=60, env={**os.environ, "NODE_PATH": str(NODE_TOOLS)})
    assert result.returncode == 0, f"{script} {path}:\n{result.stderr}\n{result.stdout}"
    return result.stdout


def validate_tap(path):
    """Parses `path` with tap-parser in strict mode; fails on any parse error. Returns what it
    parsed: ok, count, pass, fail, skip, bailout, plan, and every test point with its depth."""
    return json.loads(_node_check("validate_tap.js", path))


def tap_verdict(path):
    """What the reference TAP 14 parser (tap-parser, not strict) makes of `path`: ok, bailout,
    count, pass, fail, skip, todo."""
    return json.loads(_node_check("tap_verdict.js", path))


def validate_ctrf(path):
    """Fails the test unless `path` validates against CTRF's published JSON schema."""
    _node_check("validate_ctrf.js", path)
    return json.loads(Path(path).read_text())


# Every process a run starts inherits the runner's environment: a unique value of this variable
# finds them all afterwards (see leftover_processes).
MARKER_VARIABLE = "RTF_E2E_MARKER"


def _marked_processes(marker):
    needle = f"{MARKER_VARIABLE}={marker}".encode()
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/environ", "rb") as f:
                environ = f.read()
            with open(f"/proc/{entry}/stat") as f:
                state = f.read().rsplit(")", 1)[1].split()[0]
        except (OSError, IndexError):
            continue  # gone, or not ours to read
        if state != "Z" and needle in environ.split(b"\0"):
            found.append(int(entry))
    return found


def leftover_processes(marker, grace=3.0):
    """Pids of the living processes started with MARKER_VARIABLE=marker in their environment,
    once they had up to `grace` seconds to end. Empty when the run left nothing behind."""
    deadline = time.monotonic() + grace
    while True:
        found = _marked_processes(marker)
        if not found or time.monotonic() >= deadline:
            return found
        time.sleep(0.05)


@pytest.fixture
def marker():
    """A unique marker for one test's runs (pass env=marked(marker)); whatever is still
    marked when the test ends is killed, so a failing test leaves nothing behind either."""
    value = uuid.uuid4().hex
    yield value
    for pid in _marked_processes(value):
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass


def marked(marker, **more):
    """The environment that marks a run's processes with `marker`."""
    return {MARKER_VARIABLE: marker, **more}


def start_runner(*args, cwd, env=None):
    """Starts the runner in the folder `cwd` (required, as for run_runner) without waiting
    (for tests that signal it): a Popen in a session of its own, text stdout/stderr pipes."""
    assert RUNNER, "RTF_TESTRUNNER is not set (run through ctest)"
    full_env = runner_environment(args, env, cwd=cwd)
    return subprocess.Popen([RUNNER, *map(str, args)], cwd=cwd, env=full_env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            stdin=subprocess.DEVNULL, start_new_session=True, text=True)


def wait_for(condition, timeout=20.0, what="the condition"):
    """Polls `condition` every 50 ms until it holds; fails the test after `timeout` seconds."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return
        time.sleep(0.05)
    raise AssertionError(f"timed out waiting for {what}")


def finish_runner(proc, timeout=30):
    """(status, stdout, stderr) of a runner start_runner started, killed with its session and
    failing the test when it has not ended within `timeout` seconds."""
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        pytest.fail(f"the runner did not end within {timeout} s\n{out}\n{err}")
    return proc.returncode, out, err


@pytest.fixture
def suite_file(tmp_path):
    """Writes a suite file in the test's folder: suite_file(text, name='suite.xml')."""
    def write(text, name="suite.xml"):
        path = tmp_path / name
        path.write_text(text)
        return path
    return write
