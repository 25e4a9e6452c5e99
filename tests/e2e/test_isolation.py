"""Process isolation (the default): nothing a test or a fixture does takes the run down, every
outcome gets its own state in every output, and no process outlives the run."""
import os
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from conftest import (RUNNER, junit_state, leftover_processes, marked, plugin, run_runner,
                      validate_junit)


def junit_cases(path):
    """{test name: (state, <error>/<failure>/<skipped> element or None)}."""
    cases = {}
    for case in ET.parse(path).getroot().iter("testcase"):
        problem = None
        for tag in ("error", "failure", "skipped"):
            if case.find(tag) is not None:
                problem = case.find(tag)
        cases[case.get("name")] = (junit_state(case), problem)
    return cases


def console_line(output, name):
    """The console's result line of test `name` (e.g. '  CRASHED     segv  (0.01 s)')."""
    for line in output.splitlines():
        words = line.split()
        if len(words) >= 2 and name in line and line.startswith("  ") and "(" in line:
            shown = line.split("  (")[0].rstrip()  # "  passed      SUITE/ID (NAME)"
            if shown.endswith(" " + name) or shown.endswith("/" + name):
                return line
    raise AssertionError(f"no console line for {name}:\n{output}")


# name, plug-in, extra attributes, state in JUnit, console word, JUnit element and type, text
NASTY = [
    ("first", "passing_test", "", "passed", "passed", None, None, None),
    ("segv", "crash_segv", "", "crashed", "CRASHED", "error", "crash", "SIGSEGV"),
    ("abort", "crash_abort", "", "crashed", "CRASHED", "error", "crash", "SIGABRT"),
    ("exit3", "exit3", "", "error", "ERROR", "error", "error", "exited with status 3"),
    ("throw_int", "throw_int", "", "error", "ERROR", "error", "error", "unknown type"),
    ("throw_runtime", "throw_runtime", "", "error", "ERROR", "error", "error", None),
    ("block", "hang_block", 'timeout="1"', "timed out", "TIMED OUT", "failure", "timeout",
     "timed out after 1 s"),
    ("spin", "hang_spin", 'timeout="1"', "timed out", "TIMED OUT", "failure", "timeout",
     "timed out after 1 s"),
    ("stubborn", "ignore_sigterm", 'timeout="1"', "timed out", "TIMED OUT", "failure", "timeout",
     "ignored SIGTERM"),
    ("sleeper", "fork_sleeper", "", "passed", "passed", None, None, None),
    ("hung_sleeper", "fork_sleeper", 'param="--hang" timeout="1"', "timed out", "TIMED OUT",
     "failure", "timeout", "timed out"),
    ("setup_crash", "crash_in_setup", "", "crashed", "CRASHED", "error", "crash", "SIGSEGV"),
    ("teardown_crash", "crash_in_teardown", "", "crashed", "CRASHED", "error", "crash",
     "SIGABRT"),
    ("last", "passing_test", "", "passed", "passed", None, None, None),
]


def nasty_suites(tmp_path):
    tests = "\n".join(
        f'  <test name="{name}" {attrs}>{plugin(p)}</test>' for name, p, attrs, *_ in NASTY)
    nasty = tmp_path / "nasty.xml"
    nasty.write_text(f'<suite name="nasty">\n{tests}\n</suite>\n')
    broken = tmp_path / "broken_fixture.xml"
    broken.write_text(f'''<suite name="broken fixture">
  <fixture>{plugin("fixture_crash_setup")}</fixture>
  <test name="never">{plugin("passing_test")}</test>
</suite>
''')
    after = tmp_path / "after.xml"
    after.write_text(f'<suite name="after">\n  <test name="still">{plugin("passing_test")}</test>\n</suite>\n')
    return nasty, broken, after


def test_nothing_a_test_does_takes_the_run_down(tmp_path, marker):
    nasty, broken, after = nasty_suites(tmp_path)
    junit = tmp_path / "out.xml"
    text = tmp_path / "out.txt"
    r = run_runner("--suite", nasty.name, "--suite", broken.name, "--suite", after.name,
                   "--output", f"junit:{junit.name}", "--output", f"text:{text.name}",
                   timeout=90, env=marked(marker), cwd=tmp_path)
    assert r.returncode == 1, r
    validate_junit(junit)
    cases = junit_cases(junit)
    for name, _, _, state, word, element, kind, says in NASTY:
        status, problem = cases[name]
        assert status == state, (name, status, r)
        assert console_line(r.stdout, name).split()[0] == word.split()[0], (name, r)
        if element is None:
            assert problem is None, name
            continue
        assert problem is not None and problem.tag == element, (name, r)
        assert problem.get("type") == kind, (name, problem.attrib)
        if says:
            assert says in problem.get("message") + (problem.text or ""), (name, problem.attrib)
    # What a test reported before it died is kept.
    assert "about to exit with status 3" in text.read_text()
    # The fixture that crashed fails its own suite only; the next suite runs.
    assert cases["never"][0] == "skipped"
    assert "SIGSEGV" in text.read_text() or "crash" in text.read_text().lower()
    assert cases["still"][0] == "passed"
    assert leftover_processes(marker) == []


def test_the_closing_line_counts_every_state(tmp_path, marker):
    nasty, _, _ = nasty_suites(tmp_path)
    r = run_runner("--suite", nasty.name, "--no-output", timeout=90, env=marked(marker),
                   cwd=tmp_path)
    assert r.returncode == 1, r
    passed = sum(1 for row in NASTY if row[3] == "passed")
    assert f"{passed} passed, {len(NASTY) - passed} failed" in r.stdout.splitlines()[-1], r
    assert leftover_processes(marker) == []


def test_a_test_that_leaves_a_child_behind_leaves_nothing(tmp_path, marker):
    r = run_runner("--test", plugin("fork_sleeper"), "--no-output", timeout=30,
                   env=marked(marker), cwd=tmp_path)
    assert r.returncode == 0, r
    assert leftover_processes(marker) == []


def test_a_worker_gets_dev_null_its_output_pipe_and_its_channel_only(tmp_path, marker):
    # The runner's stdin is a pipe with bytes in it: no test reads them. Three tests, so that
    # workers forked ahead of time (spares) are checked too.
    r = run_runner(*(["--test", plugin("worker_descriptors")] * 3), "--verbose",
                   timeout=30, env=marked(marker), cwd=tmp_path, input="not for the tests\n")
    assert r.returncode == 0, r
    assert "3 passed, 0 failed" in r.stdout.splitlines()[-1], r
    assert leftover_processes(marker) == []


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_critical_error_skips_the_rest_of_the_suite(tmp_path, isolation, suite_file):
    suite = suite_file(f'''<suite name="crit">
  <test name="before">{plugin("passing_test")}</test>
  <test name="crit">{plugin("critical_error")}</test>
  <test name="after1">{plugin("passing_test")}</test>
  <test name="after2">{plugin("passing_test")}</test>
</suite>''')
    other = suite_file(f'<suite name="other"><test name="elsewhere">{plugin("passing_test")}</test></suite>', "other.xml")
    junit = tmp_path / "out.xml"
    r = run_runner("--isolation", isolation, "--suite", suite.name, "--suite", other.name,
                   "--output", f"junit:{junit.name}", timeout=60, cwd=tmp_path)
    assert r.returncode == 1, r
    validate_junit(junit)
    cases = junit_cases(junit)
    assert cases["before"][0] == "passed"
    assert cases["crit"][0] == "error"
    for name in ("after1", "after2"):
        status, problem = cases[name]
        assert status == "skipped", (name, r)
        assert "the robot is not powered" in (problem.text or ""), name
    assert cases["elsewhere"][0] == "passed"


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_fail_fast_stops_the_run_at_the_first_failure(tmp_path, isolation, suite_file):
    suite = suite_file(f'''<suite name="one">
  <test name="ok">{plugin("passing_test")}</test>
  <test name="bad">{plugin("failing_test")}</test>
  <test name="skipped1">{plugin("passing_test")}</test>
</suite>''')
    other = suite_file(f'<suite name="two"><test name="skipped2">{plugin("passing_test")}</test></suite>', "two.xml")
    junit = tmp_path / "out.xml"
    r = run_runner("--isolation", isolation, "--fail-fast", "--suite", suite.name, "--suite",
                   other.name, "--output", f"junit:{junit.name}", timeout=60, cwd=tmp_path)
    assert r.returncode == 1, r
    validate_junit(junit)
    cases = junit_cases(junit)
    assert cases["ok"][0] == "passed"
    assert cases["bad"][0] == "failed"
    for name in ("skipped1", "skipped2"):
        status, problem = cases[name]
        assert status == "skipped", (name, r)
        assert "--fail-fast" in (problem.text or ""), name
    assert "skipped: --fail-fast, bad failed" in r.stdout and "skipped: skipped" not in r.stdout, r
    # Without --fail-fast everything runs.
    r = run_runner("--isolation", isolation, "--suite", suite.name, "--suite", other.name,
                   "--output", f"junit:{junit.name}", timeout=60, cwd=tmp_path)
    assert junit_cases(junit)["skipped2"][0] == "passed"


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_depends_runs_only_after_its_dependency_passed(tmp_path, isolation, suite_file):
    suite = suite_file(f'''<suite name="deps">
  <test name="good">{plugin("passing_test")}</test>
  <test name="bad">{plugin("failing_test")}</test>
  <test name="on_good" depends="good">{plugin("passing_test")}</test>
  <test name="on_bad" depends="bad">{plugin("passing_test")}</test>
  <test name="on_plugin" depends="{plugin("failing_test")}">{plugin("passing_test")}</test>
</suite>''')
    junit = tmp_path / "out.xml"
    r = run_runner("--isolation", isolation, "--suite", suite.name, "--output",
                   f"junit:{junit.name}", timeout=60, cwd=tmp_path)
    assert r.returncode == 1, r
    cases = junit_cases(junit)
    assert cases["on_good"][0] == "passed", r
    for name, reason in (("on_bad", "depends on bad"), ("on_plugin", "did not pass")):
        status, problem = cases[name]
        assert status == "skipped", (name, r)
        assert reason in (problem.text or ""), (name, problem.text)
    # The console says "skipped" once, then why.
    assert "skipped: depends on bad, which did not pass (failed)" in r.stdout, r
    assert "skipped: skipped" not in r.stdout, r


def test_depends_on_a_plugin_named_without_its_folder(tmp_path, suite_file):
    suite = suite_file(f'''<suite name="deps">
  <test>{plugin("failing_test")}</test>
  <test name="x" depends="failing_test">{plugin("passing_test")}</test>
</suite>''')
    junit = tmp_path / "out.xml"
    r = run_runner("--suite", suite.name, "--output", f"junit:{junit.name}", timeout=60,
                   cwd=tmp_path)
    status, problem = junit_cases(junit)["x"]
    assert status == "skipped" and "failing_test" in problem.text, r


def test_unknown_dependency_is_a_configuration_error(suite_file):
    suite = suite_file(f'''<suite name="deps">
  <test name="good">{plugin("passing_test")}</test>
  <test name="lost"
        depends="nobody">{plugin("passing_test")}</test>
</suite>''')
    r = run_runner("--suite", suite.name, "--no-output", timeout=30, cwd=suite.parent)
    assert r.returncode == 2, r
    assert f"{suite.name}:3" in r.stderr and "unknown dependency 'nobody'" in r.stderr, r
    assert "passed" not in r.stdout


@pytest.mark.parametrize("where, expect", [
    ("command", "1 s"), ("suite", "1.5 s"), ("test", "0.5 s")])
def test_the_most_specific_timeout_wins(tmp_path, where, expect, marker, suite_file):
    suite_timeout = "<timeout>1.5</timeout>" if where in ("suite", "test") else ""
    test_timeout = 'timeout="0.5"' if where == "test" else ""
    suite = suite_file(f'''<suite name="t">{suite_timeout}
  <test name="hung" {test_timeout}>{plugin("hang_block")}</test>
</suite>''')
    junit = tmp_path / "out.xml"
    command = "1" if where == "command" else "30"
    r = run_runner("--suite", suite.name, "--timeout", command, "--output", f"junit:{junit.name}",
                   timeout=60, env=marked(marker), cwd=tmp_path)
    assert r.returncode == 1, r
    status, problem = junit_cases(junit)["hung"]
    assert status == "timed out", r
    assert problem.get("type") == "timeout"
    assert f"timed out after {expect}" in problem.get("message"), problem.attrib
    assert "waiting for a message that never comes" in problem.text, problem.text
    assert leftover_processes(marker) == []


def test_a_timeout_bounds_setup_and_teardown_too(tmp_path, marker, suite_file):
    # The hang is in setup here (a fixture-free test that blocks before run()).
    script = tmp_path / "slow_setup.py"
    script.write_text("import time\nclass TestCase:\n    def setup(self, param):\n"
                      "        time.sleep(60)\n        return True\n    def run(self):\n"
                      "        pass\n")
    r = run_runner("--test", script.name, "--timeout", "1", "--no-output", timeout=30,
                   env=marked(marker), cwd=tmp_path)
    if "is not supported by this build" in r.output:
        pytest.skip("no Python in this build")
    assert r.returncode == 1, r
    assert "TIMED OUT" in r.stdout, r
    assert leftover_processes(marker) == []


def test_in_process_timeout_stops_a_test_that_listens(tmp_path):
    r = run_runner("--isolation", "none", "--test", plugin("waiting_test"), "--param",
                   "--seconds 30", "--timeout", "1", "--no-output", timeout=20, cwd=tmp_path)
    assert r.returncode == 1, r
    assert "TIMED OUT" in r.stdout and "timed out after 1 s" in r.stdout, r


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_repetition_runs_every_time(tmp_path, isolation, suite_file):
    suite = suite_file(f'<suite name="r"><test name="rep" repetition="3">{plugin("passing_test")}</test></suite>')
    r = run_runner("--isolation", isolation, "--suite", suite.name, "--no-output", "-v", timeout=30,
                   cwd=tmp_path)
    assert r.returncode == 0, r
    for k in (1, 2, 3):
        assert f"repetition {k}/3" in r.stdout, r


def test_a_crash_in_repetition_two_stops_the_later_ones(tmp_path, marker, suite_file):
    suite = suite_file(f'''<suite name="r">
  <test name="rep" repetition="3" param="--crash-at 2">{plugin("crash_at_repetition")}</test>
  <test name="next">{plugin("passing_test")}</test>
</suite>''')
    junit = tmp_path / "out.xml"
    r = run_runner("--suite", suite.name, "--output", f"junit:{junit.name}", "-v", timeout=30,
                   env=marked(marker), cwd=tmp_path)
    assert r.returncode == 1, r
    cases = junit_cases(junit)
    status, problem = cases["rep"]
    assert status == "crashed", r
    # The signal is the one-line message (what CI tools show); the details say where.
    assert problem.get("message") == "SIGSEGV", problem.attrib
    assert "crashed in repetition 2/3: SIGSEGV" in problem.text, problem.text
    assert "run 1 done" in r.stdout
    assert "repetition 3/3" not in r.stdout
    assert cases["next"][0] == "passed"
    assert leftover_processes(marker) == []


def test_worker_missing_is_a_configuration_error(tmp_path):
    # A runner with no worker beside it (nor in ../libexec, nor installed) cannot isolate.
    if Path("/usr/local/libexec/robottestingframework-worker").exists():
        pytest.skip("a worker is installed on this machine")
    lonely = tmp_path / "bin" / "robottestingframework-testrunner"
    lonely.parent.mkdir()
    shutil.copy(RUNNER, lonely)
    env = dict(os.environ)
    env.pop("RTF_WORKER", None)
    # The installed runner finds its libraries through $ORIGIN/../lib: the copy is shown them.
    libraries = {str(found.parent) for found in
                 Path(RUNNER).resolve().parent.parent.glob("lib*/**/libRobotTestingFramework.so*")}
    assert libraries, f"no library of the runner {RUNNER}"
    env["LD_LIBRARY_PATH"] = os.pathsep.join(sorted(libraries))
    r = subprocess.run([lonely, "--test", plugin("passing_test"), "--no-output"], env=env,
                       capture_output=True, text=True, timeout=30)
    assert r.returncode == 2, r
    assert "cannot start process isolation" in r.stderr, r.stderr
    # --isolation none needs no worker.
    r = subprocess.run([lonely, "--isolation", "none", "--test", plugin("passing_test"),
                        "--no-output"], env=env, capture_output=True, text=True, timeout=30)
    assert r.returncode == 0, r.stdout + r.stderr


RENAMING_SCRIPTS = {
    "py": """import robottestingframework
class TestCase:
    def setup(self, param):
        robottestingframework.setName("renamed by the script")
        return True
    def run(self):
        robottestingframework.testCheck(False, "fails under its new name")
""",
    "lua": """TestCase = {}
function TestCase.setup(param)
    robottestingframework.setName("renamed by the script")
    return true
end
function TestCase.run()
    robottestingframework.testCheck(false, "fails under its new name")
end
""",
    "rb": """class TestCase
  def setup(param)
    RobotTestingFramework::setName("renamed by the script")
    true
  end
  def run
    RobotTestingFramework::testCheck(false, "fails under its new name")
  end
end
""",
}


@pytest.mark.parametrize("isolation", ["process", "none"])
@pytest.mark.parametrize("ext", list(RENAMING_SCRIPTS))
def test_a_script_that_names_itself_is_named_so_in_every_output(tmp_path, isolation, ext):
    script = tmp_path / f"renaming.{ext}"
    script.write_text(RENAMING_SCRIPTS[ext])
    junit = tmp_path / "out.xml"
    text = tmp_path / "out.txt"
    r = run_runner("--isolation", isolation, "--test", script.name, "--output",
                   f"junit:{junit.name}", "--output", f"text:{text.name}", timeout=60,
                   cwd=tmp_path)
    if "is not supported by this build" in r.output:
        pytest.skip("this build leaves the language out")
    assert r.returncode == 1, r
    # Shown beside its id (the file given, docs/reference/test-ids.md), which the reports name it by.
    shown = f"renaming.{ext} (renamed by the script)"
    assert console_line(r.stdout, shown).split()[0] == "FAILED", r
    assert list(junit_cases(junit)) == [f"renaming.{ext}"]
    assert 'value="renamed by the script"' in junit.read_text()
    assert "renamed by the script" in text.read_text()
