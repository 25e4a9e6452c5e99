"""The Windows end-to-end tests: the installed Windows runner (robottestingframework-testrunner.exe
in e2e-installed/bin of the build tree, with the worker, DLLs and Lua module installed beside it)
run under Wine on real suite files, from the suite's folder with relative paths; its reports are
read back here, on Linux, with the checkers the Linux end-to-end tests use (xmllint with the
project's JUnit schema; tap-parser and CTRF's JSON schema from the build tree's node-tools).
Environment (tests/windows/CMakeLists.txt): RTF_TESTRUNNER, RTF_INSTALL_PREFIX,
RTF_TEST_PLUGIN_DIR, RTF_WINE, RTF_SOURCE_DIR, RTF_BUILD_DIR, WINEPREFIX."""
import json
import os
import signal
import subprocess
from pathlib import Path

RUNNER = Path(os.environ["RTF_TESTRUNNER"])
PLUGIN_DIR = Path(os.environ["RTF_TEST_PLUGIN_DIR"])
WINE = os.environ["RTF_WINE"]
SOURCE_DIR = Path(os.environ["RTF_SOURCE_DIR"])
BUILD_DIR = Path(os.environ["RTF_BUILD_DIR"])
SCHEMA = SOURCE_DIR / "schemas" / "junit.xsd"
TOOLS_DIR = SOURCE_DIR / "tests" / "e2e" / "tools"
NODE_TOOLS = BUILD_DIR / "node-tools" / "node_modules"


class Run:
    def __init__(self, proc):
        self.returncode = proc.returncode
        self.stdout = proc.stdout
        self.stderr = proc.stderr
        self.output = proc.stdout + proc.stderr

    def __repr__(self):
        return f"exit {self.returncode}\n--- stdout\n{self.stdout}\n--- stderr\n{self.stderr}"


def windows_path(path):
    """`path` as Windows programs under Wine see it (drive Z: is the Linux root)."""
    return "Z:" + str(Path(path).resolve()).replace("/", "\\")


def run_runner(*args, cwd, env=None, timeout=120, runner=RUNNER):
    """The Windows runner (the installed one unless `runner` says) under Wine with `args`, in
    `cwd`; Wine's own chatter is off."""
    full_env = {**os.environ, "WINEDEBUG": "-all", **(env or {})}
    proc = subprocess.run([WINE, str(runner), *map(str, args)], cwd=cwd, env=full_env,
                          capture_output=True, text=True, timeout=timeout,
                          stdin=subprocess.DEVNULL)
    return Run(proc)


def start_runner(*args, cwd, env=None):
    """The Windows runner under Wine started without waiting (for tests that talk to it while
    it runs): a Popen in a session of its own (stop_runner ends the whole group), text pipes."""
    full_env = {**os.environ, "WINEDEBUG": "-all", **(env or {})}
    return subprocess.Popen([WINE, str(RUNNER), *map(str, args)], cwd=cwd, env=full_env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            stdin=subprocess.DEVNULL, start_new_session=True, text=True)


def stop_runner(proc):
    """Kills a runner start_runner started, if it still runs (the wineserver stays)."""
    if proc.poll() is None:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait(timeout=30)


def run_with_ctrl_c(ready_file, *args, cwd, timeout=120):
    """The Windows runner with `args` started by console_ctrl_c.exe (RTF_CTRL_C), which sends it
    a console Ctrl-C once `ready_file` (relative to `cwd`) exists."""
    full_env = {**os.environ, "WINEDEBUG": "-all"}
    proc = subprocess.run([WINE, os.environ["RTF_CTRL_C"], str(ready_file), windows_path(RUNNER),
                           *map(str, args)], cwd=cwd, env=full_env, capture_output=True,
                          text=True, timeout=timeout, stdin=subprocess.DEVNULL)
    return Run(proc)


def copy_plugins(folder, *names):
    """The test plug-ins `names` (file names in RTF_TEST_PLUGIN_DIR) copied into `folder`."""
    folder.mkdir(parents=True, exist_ok=True)
    for name in names:
        (folder / name).write_bytes((PLUGIN_DIR / name).read_bytes())


def validate_junit(path):
    result = subprocess.run(["xmllint", "--noout", "--schema", str(SCHEMA), str(path)],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr


def _node_check(script, path):
    result = subprocess.run(["node", str(TOOLS_DIR / script), str(path)], capture_output=True,
                            text=True, timeout=60, env={**os.environ, "NODE_PATH": str(NODE_TOOLS)})
    assert result.returncode == 0, f"{script} {path}:\n{result.stderr}\n{result.stdout}"
    return result.stdout


def validate_tap(path):
    """tap-parser in strict mode; what it parsed (ok, count, pass, fail, ...)."""
    return json.loads(_node_check("validate_tap.js", path))


def validate_ctrf(path):
    """CTRF's published JSON schema; the report as read."""
    _node_check("validate_ctrf.js", path)
    return json.loads(Path(path).read_text())
