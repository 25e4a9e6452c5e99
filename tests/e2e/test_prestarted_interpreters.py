"""Pre-started interpreters (--isolation process): script tests run in forks of one process per
language that has the runtime started, yet nothing of one test reaches the next, and everything
isolation promises (crash, exit, hang, Ctrl-C, SIGKILL of the runner) still holds."""
import os
import re
import signal
import subprocess
import time
import xml.etree.ElementTree as ET

import pytest

from conftest import (RUNNER, finish_runner, junit_state, leftover_processes, marked, run_runner,
                      start_runner, wait_for)

PRESTARTED = re.compile(r"(\w+) tests run in forks of a pre-started interpreter \(pid (\d+)\)")


def cases(junit):
    return {case.get("name"): case for case in ET.parse(junit).getroot().iter("testcase")}


def message(case):
    problem = [child for child in case if child.tag in ("failure", "error")]
    return problem[0].get("message", "") if problem else ""


def run_suite(tmp_path, tests, *extra, env=None, timeout=120):
    """Runs the files `tests` ({name: text}) as one suite in order, verbose, from the suite's
    folder with relative names; returns (Run, JUnit test cases by name)."""
    lines = ['<suite name="prestart">']
    for name, text in tests.items():
        (tmp_path / name).write_text(text)
        lines.append(f'  <test name="{name}">{name}</test>')
    lines.append("</suite>")
    suite = tmp_path / "suite.xml"
    suite.write_text("\n".join(lines) + "\n")
    junit = tmp_path / "out.xml"
    r = run_runner("--suite", suite.name, "-v", "--output", f"junit:{junit.name}", *extra,
                   cwd=tmp_path, env=env, timeout=timeout)
    return r, cases(junit)


PYTHON_LEAKS = {
    "state.py": "count = 0\n",
    "a_test.py": """import builtins
import json
import os
import sys
import threading
import types
import robottestingframework
import state


class TestCase:
    def run(self):
        global LEAKED
        LEAKED = True
        state.count += 1
        json.leaked = True
        builtins.leaked = True
        robottestingframework.leaked = True
        robottestingframework.testCheck = lambda *args: None
        sys.modules["rtf_leak_probe"] = types.ModuleType("rtf_leak_probe")
        sys.path.append("/rtf-leak-probe")
        os.environ["RTF_LEAK_PROBE"] = "set by a_test"
        threading.Thread(target=threading.Event().wait, daemon=True).start()
        with open(os.environ["RTF_PIDS"], "a") as f:
            f.write("%d %d\\n" % (os.getpid(), os.getppid()))
""",
    "b_test.py": """import builtins
import json
import os
import sys
import threading
import state


class TestCase:
    def run(self):
        with open(os.environ["RTF_PIDS"], "a") as f:
            f.write("%d %d\\n" % (os.getpid(), os.getppid()))
        seen = [what for what, leaked in [
            ("a module global", "LEAKED" in globals()),
            ("an imported module's state", state.count != 0),
            ("a standard module's attribute", hasattr(json, "leaked")),
            ("a builtin", hasattr(builtins, "leaked")),
            ("robottestingframework's attribute", hasattr(robottestingframework, "leaked")),
            ("a sys.modules entry", "rtf_leak_probe" in sys.modules),
            ("a sys.path entry", "/rtf-leak-probe" in sys.path),
            ("an environment variable", "RTF_LEAK_PROBE" in os.environ),
            ("a thread", threading.active_count() != 1),
        ] if leaked]
        if seen:
            raise RuntimeError("leaked from the previous test: " + ", ".join(seen))
        robottestingframework.testCheck(False, "the real testCheck still fails")
""",
}


def test_python_tests_run_in_forks_of_one_prestarted_interpreter_and_share_nothing(tmp_path):
    pids = tmp_path / "pids"
    tests = {name: text for name, text in PYTHON_LEAKS.items() if name != "state.py"}
    (tmp_path / "state.py").write_text(PYTHON_LEAKS["state.py"])
    r, junit = run_suite(tmp_path, tests, env={"RTF_PIDS": str(pids)})
    assert r.returncode == 1, r
    assert junit_state(junit["a_test.py"]) == "passed", r
    # Failed by the real check: not an error for a leak.
    assert junit_state(junit["b_test.py"]) == "failed", r
    assert "the real testCheck still fails" in message(junit["b_test.py"]), r
    found = PRESTARTED.findall(r.stderr)
    assert [language for language, _ in found] == ["python"], r
    server = int(found[0][1])
    (first, parent1), (second, parent2) = [map(int, line.split())
                                           for line in pids.read_text().splitlines()]
    assert first != second
    assert parent1 == parent2 == server, "both tests are forks of the pre-started interpreter"


# The pre-started interpreter keeps two spares (forks waiting for a test) besides the test that
# runs, and has not imported threading (whose hook would run in every fork): a test that imports
# it, after the fork, finds it fresh.
SPARES_PROBE = """import os
import sys
import time
import robottestingframework

parent = os.getppid()
threading_before = "threading" in sys.modules


def children():
    with open("/proc/%d/task/%d/children" % (parent, parent)) as f:
        return f.read().split()


class TestCase:
    def run(self):
        seen = children()
        for _ in range(500):  # the spares are forked as this test starts
            if len(seen) >= 3:
                break
            time.sleep(0.01)
            seen = children()
        robottestingframework.testCheck(len(seen) == 3, "the test and two spares: %s" % seen)
        robottestingframework.testCheck(not threading_before, "threading not imported before")
"""


def test_the_prestarted_interpreter_keeps_two_spares_and_imports_no_threading(tmp_path):
    r, junit = run_suite(tmp_path, {"probe.py": SPARES_PROBE})
    assert r.returncode == 0, r
    assert junit_state(junit["probe.py"]) == "passed", r
    assert [language for language, _ in PRESTARTED.findall(r.stderr)] == ["python"], r


def test_rtf_prestart_0_runs_each_python_test_in_its_own_interpreter(tmp_path):
    pids = tmp_path / "pids"
    tests = {name: text for name, text in PYTHON_LEAKS.items() if name != "state.py"}
    (tmp_path / "state.py").write_text(PYTHON_LEAKS["state.py"])
    r, junit = run_suite(tmp_path, tests, env={"RTF_PIDS": str(pids), "RTF_PRESTART": "0"})
    assert junit_state(junit["a_test.py"]) == "passed", r
    assert junit_state(junit["b_test.py"]) == "failed", r
    assert not PRESTARTED.search(r.stderr), r
    assert len(set(line.split()[1] for line in pids.read_text().splitlines())) == 1


LUA_LEAKS = {
    "a_test.lua": """local state = require("state")
TestCase = {}
function TestCase.run()
    LEAKED = true
    state.count = state.count + 1
    string.leaked = true
    robottestingframework.leaked = true
    robottestingframework.testCheck = function() end
end
""",
    "b_test.lua": """local state = require("state")
TestCase = {}
function TestCase.run()
    local seen = {}
    if LEAKED ~= nil then seen[#seen + 1] = "a global" end
    if state.count ~= 0 then seen[#seen + 1] = "a required module's state" end
    if string.leaked ~= nil then seen[#seen + 1] = "a standard library's field" end
    if robottestingframework.leaked ~= nil then seen[#seen + 1] = "robottestingframework's field" end
    if #seen > 0 then error("leaked from the previous test: " .. table.concat(seen, ", ")) end
    robottestingframework.testCheck(false, "the real testCheck still fails")
end
""",
}


def test_lua_tests_run_in_forks_of_a_prestarted_lua_and_share_nothing(tmp_path):
    (tmp_path / "state.lua").write_text("return {count = 0}\n")
    r, junit = run_suite(tmp_path, LUA_LEAKS,
                         env={"LUA_PATH": f"{tmp_path}/?.lua;;"})
    if "is not supported by this build" in r.output or "not available" in r.output:
        pytest.skip("this build leaves Lua out")
    assert junit_state(junit["a_test.lua"]) == "passed", r
    assert junit_state(junit["b_test.lua"]) == "failed", r
    assert "the real testCheck still fails" in message(junit["b_test.lua"]), r
    assert [language for language, _ in PRESTARTED.findall(r.stderr)] == ["lua"], r


RUBY_LEAKS = {
    "a_test.rb": """$leaked = true
LEAKED = true
class String
  def leaked; true; end
end
module RobotTestingFramework
  def self.leaked; true; end
end
class TestCase
  def run
  end
end
""",
    "b_test.rb": """class TestCase
  def run
    seen = []
    seen << "a global" if $leaked
    seen << "a constant" if defined?(LEAKED)
    seen << "a patched class" if "".respond_to?(:leaked)
    seen << "a patched RobotTestingFramework" if RobotTestingFramework.respond_to?(:leaked)
    raise "leaked from the previous test: " + seen.join(", ") unless seen.empty?
    RobotTestingFramework::testCheck(false, "the real testCheck still fails")
  end
end
""",
}


def test_ruby_tests_run_in_forks_of_a_prestarted_vm_and_share_nothing(tmp_path):
    r, junit = run_suite(tmp_path, RUBY_LEAKS)
    if "is not supported by this build" in r.output or "not available" in r.output:
        pytest.skip("this build leaves Ruby out")
    assert junit_state(junit["a_test.rb"]) == "passed", r
    assert junit_state(junit["b_test.rb"]) == "failed", r
    assert "the real testCheck still fails" in message(junit["b_test.rb"]), r
    assert [language for language, _ in PRESTARTED.findall(r.stderr)] == ["ruby"], r


RUBY_HOSTILE = {
    # Forked from the VM's thread: threads, their switching and Process.pid still work.
    "threads_test.rb": ("""class TestCase
  def run
    RobotTestingFramework::testCheck(Thread.new { 6 * 7 }.value == 42, "a thread runs")
    Thread.new { loop { } }
    queue = Queue.new
    Thread.new { queue << Process.pid }
    RobotTestingFramework::testCheck(queue.pop == $$, "threads switch while one spins")
    Thread.new { sleep }
  end
end
""", "passed", ""),
    "exit_test.rb": ("""class TestCase
  def run
    exit!(0)
  end
end
""", "error", "would end the test runner's process"),
    "segv_test.rb": ("""class TestCase
  def run
    Process.kill(:SEGV, Process.pid)
    sleep 5
  end
end
""", "crashed", "SIGSEGV"),
    "hang_test.rb": ("""class TestCase
  def run
    sleep
  end
end
""", "timed out", "timed out after 1 s"),
    "syntax_test.rb": ("""class TestCase
  def run(
end
""", "failed", "syntax_test.rb:"),
    "after_test.rb": ("""class TestCase
  def run
    RobotTestingFramework::testCheck(true, "the next test still runs")
  end
end
""", "passed", ""),
}


def test_ruby_threads_exit_crash_hang_and_bad_files_in_forks(tmp_path, marker):
    tests = {name: text for name, (text, _, _) in RUBY_HOSTILE.items()}
    r, junit = run_suite(tmp_path, tests, "--timeout", "1", env=marked(marker))
    if "is not supported by this build" in r.output or "not available" in r.output:
        pytest.skip("this build leaves Ruby out")
    assert [language for language, _ in PRESTARTED.findall(r.stderr)] == ["ruby"], r
    for name, (_, status, words) in RUBY_HOSTILE.items():
        case = junit[name]
        assert junit_state(case) == status, (name, r)
        assert words in message(case) + "".join(case.itertext()), (name, message(case), r)
    assert leftover_processes(marker) == []


HOSTILE = {
    "segv_test.py": ("""import os, signal
class TestCase:
    def run(self):
        os.kill(os.getpid(), signal.SIGSEGV)
""", "crashed", "SIGSEGV"),
    "ctypes_test.py": ("""import ctypes
class TestCase:
    def run(self):
        ctypes.string_at(0)
""", "crashed", "SIGSEGV"),
    "exit_test.py": ("""import os
class TestCase:
    def run(self):
        os._exit(0)
""", "error", "would end the test runner's process"),
    "thread_test.py": ("""import threading, time
class TestCase:
    def run(self):
        threading.Thread(target=lambda: time.sleep(3600)).start()
        robottestingframework.testCheck(True, "started a thread that never ends")
""", "passed", ""),
    "recursion_test.py": ("""class TestCase:
    def run(self):
        def down(n):
            return down(n + 1)
        down(0)
""", "error", "RecursionError"),
    "hang_test.py": ("""import time
class TestCase:
    def run(self):
        while True:
            time.sleep(0.01)
""", "timed out", "timed out after 1 s"),
    "syntax_test.py": ("""class TestCase:
    def run(self)
        pass
""", "failed", "syntax_test.py\", line 2"),
    "missing_test.py": ("x = 1\n", "failed", "TestCase"),
    "setup_test.py": ("""class TestCase:
    def setup(self, argv):
        raise ValueError("setup says no")
    def run(self):
        pass
""", "", "setup says no"),
    "after_test.py": ("""class TestCase:
    def run(self):
        robottestingframework.testCheck(True, "the next test still runs")
""", "passed", ""),
}


def test_python_crashes_exits_threads_recursion_hangs_and_bad_files_in_forks(tmp_path, marker):
    tests = {name: text for name, (text, _, _) in HOSTILE.items()}
    r, junit = run_suite(tmp_path, tests, "--timeout", "1", env=marked(marker))
    assert PRESTARTED.search(r.stderr), r
    for name, (_, status, words) in HOSTILE.items():
        case = junit[name]
        if status:
            assert junit_state(case) == status, (name, r)
        else:
            assert junit_state(case) in ("failed", "error"), (name, r)
        assert words in message(case) + "".join(case.itertext()), (name, message(case), r)
    assert leftover_processes(marker) == []


def test_ctrl_c_and_sigkill_of_the_runner_leave_no_interpreter_behind(tmp_path, marker):
    started = tmp_path / "started"
    test = tmp_path / "hang_test.py"
    test.write_text(f"""import time
class TestCase:
    def run(self):
        open({str(started)!r}, "w").close()
        time.sleep(3600)
""")
    for signum in (signal.SIGINT, signal.SIGKILL):
        if started.exists():
            started.unlink()
        proc = start_runner("--test", test.name, "-v", cwd=tmp_path, env=marked(marker))
        wait_for(started.exists, what="the test to start")
        proc.send_signal(signum)
        status, out, err = finish_runner(proc)
        assert status == (130 if signum == signal.SIGINT else -signal.SIGKILL), (out, err)
        assert leftover_processes(marker, grace=5.0) == [], signum


def test_killing_the_prestarted_interpreter_fails_only_its_running_test(tmp_path, marker):
    tests = {
        "a_test.py": """import os, signal
class TestCase:
    def run(self):
        os.kill(os.getppid(), signal.SIGKILL)
        time.sleep(10)
""".replace("import os, signal", "import os, signal, time"),
        "b_test.py": """class TestCase:
    def run(self):
        robottestingframework.testCheck(True, "a new interpreter runs me")
""",
    }
    r, junit = run_suite(tmp_path, tests, env=marked(marker))
    assert junit_state(junit["a_test.py"]) in ("crashed", "error"), r
    assert junit_state(junit["b_test.py"]) == "passed", r
    assert PRESTARTED.search(r.stderr), r
    assert leftover_processes(marker) == []


# Reads /proc: the minor page faults of a process, and the spare waiting beside this test (the
# other child of the pre-started interpreter).
SPARE_FAULTS = """import os
import time


def faults(pid):
    with open("/proc/%d/stat" % pid) as f:
        return int(f.read().rsplit(")", 1)[1].split()[7])


def spare_beside(me):
    parent = os.getppid()
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline:
        with open("/proc/%d/task/%d/children" % (parent, parent)) as f:
            others = [int(pid) for pid in f.read().split() if int(pid) != me]
        if others:
            return others[0]
        time.sleep(0.02)
    raise RuntimeError("no spare beside the test")
"""


def test_a_python_spare_rehearses_a_test_before_its_own_comes(tmp_path):
    # The spare forked for the next test runs a script of nothing while this one runs, so the
    # pages a test touches are copied before its request: it has already faulted in a good part
    # of what a whole test (this one) faulted in. Without the rehearsal it only has its fork's.
    tests = {"a_test.py": SPARE_FAULTS + """

class TestCase:
    def run(self):
        me = os.getpid()
        spare = spare_beside(me)
        deadline = time.monotonic() + 10  # the spare may not have had a processor yet
        while faults(spare) <= 0.3 * faults(me) and time.monotonic() < deadline:
            time.sleep(0.05)
        ratio = faults(spare) / faults(me)
        robottestingframework.testCheck(ratio > 0.3, "the spare rehearsed a test (%.2f)" % ratio)
""", "b_test.py": """import sys

class TestCase:
    def run(self):
        # Nothing of the rehearsal is left: no other script module, no "/dev" on the path.
        scripts = [name for name in sys.modules if name.startswith("_rtf_script_")]
        robottestingframework.testCheck(scripts == [__name__], "modules: %s" % scripts)
        robottestingframework.testCheck("/dev" not in sys.path, "path: %s" % sys.path)
"""}
    r, junit = run_suite(tmp_path, tests)
    assert PRESTARTED.search(r.stderr), r
    assert junit_state(junit["a_test.py"]) == "passed", r
    assert junit_state(junit["b_test.py"]) == "passed", r


BIND_NOW = """import os


class TestCase:
    def run(self):
        with open("/proc/self/environ", "rb") as f:
            started = f.read().split(b"\\0")
        robottestingframework.testCheck(b"LD_BIND_NOW=1" in started,
                                        "the worker started with every symbol bound")
        robottestingframework.testReport(
            "LD_BIND_NOW=%s mark=%s" % (os.environ.get("LD_BIND_NOW"),
                                        os.environ.get("RTF_WORKER_BIND_NOW")))
"""


def test_workers_start_bound_yet_tests_see_the_users_environment(tmp_path):
    # The runner starts its worker with LD_BIND_NOW=1 (no symbol resolved again in each fork)
    # and takes it out of the environment the tests see; a user's own LD_BIND_NOW stays.
    (tmp_path / "bind_test.py").write_text(BIND_NOW)
    env = {k: v for k, v in os.environ.items() if k not in ("LD_BIND_NOW", "RTF_WORKER_BIND_NOW")}
    for users in (None, "1"):
        shell = tmp_path / "env_test.sh"
        shell.write_text(f"""#!/bin/sh
echo "1..1"
if [ "${{LD_BIND_NOW-unset}}" = "{users or 'unset'}" ] && [ -z "${{RTF_WORKER_BIND_NOW+x}}" ]; then
    echo "ok 1"
else
    echo "not ok 1 - LD_BIND_NOW=${{LD_BIND_NOW-unset}} mark=${{RTF_WORKER_BIND_NOW-unset}}"
fi
""")
        shell.chmod(0o755)
        suite = tmp_path / "suite.xml"
        suite.write_text('<suite name="env"><test>bind_test.py</test>'
                         f"<test>./{shell.name}</test></suite>\n")
        proc = subprocess.run([RUNNER, "--suite", suite.name, "-v"], cwd=tmp_path,
                              env=dict(env, LD_BIND_NOW=users) if users else env,
                              capture_output=True, text=True, timeout=120)
        output = proc.stdout + proc.stderr
        assert proc.returncode == 0, output
        assert f"LD_BIND_NOW={users} mark=None" in output, output


def test_traceback_is_imported_by_the_prestarted_interpreter_or_when_a_test_fails(tmp_path):
    # traceback (with re, tokenize, linecache...) is most of what a Python test that starts its
    # own interpreter imports: only a failing test needs it, and a pre-started one has it.
    tests = {"passing_test.py": """import sys

class TestCase:
    def run(self):
        robottestingframework.testReport("traceback imported: %s" % ("traceback" in sys.modules))
""", "raising_test.py": """def helper():
    raise ValueError("deliberate")

class TestCase:
    def run(self):
        helper()
"""}
    for prestart, imported in (("1", "True"), ("0", "False")):
        r, junit = run_suite(tmp_path, tests, env={"RTF_PRESTART": prestart})
        assert f"traceback imported: {imported}" in r.output, (prestart, r)
        raised = junit["raising_test.py"]
        assert junit_state(raised) == "error", (prestart, r)
        text = message(raised) + "".join(raised.itertext())
        assert "ValueError: deliberate" in text and "in helper" in text, (prestart, text)


def test_python_workers_find_the_prestarted_interpreters_objects_frozen(tmp_path):
    # gc.freeze() before the fork point: a test's collections leave the objects every fork
    # shares alone instead of writing to (and so copying) each of their pages.
    tests = {"frozen_test.py": """import gc

class TestCase:
    def run(self):
        robottestingframework.testReport("frozen objects: %d" % gc.get_freeze_count())
"""}
    for prestart in ("1", "0"):
        r, junit = run_suite(tmp_path, tests, env={"RTF_PRESTART": prestart})
        assert junit_state(junit["frozen_test.py"]) != "failure", (prestart, r)
        found = re.search(r"frozen objects: (\d+)", r.output)
        assert found, (prestart, r)
        frozen = int(found.group(1))
        # Without a pre-started interpreter nothing is frozen; with one, all it made (thousands).
        assert (frozen > 1000) if prestart == "1" else (frozen == 0), (prestart, frozen)
