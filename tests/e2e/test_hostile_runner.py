"""The runner against hostile and real-world input (issue 14): outputs that must not replace
what is at their path, suite files that are no files, dependency cycles, numbers too large,
misleading messages, --var, and the installed runner loading plug-ins beside a suite given by a
relative path. The runner starts in the test's folder and is given relative paths, as users run
it; a device is named by its absolute path, as users name one, and section 17 starts the runner
in other folders on purpose."""
import os
import shutil
import signal
import stat
import subprocess
import threading
import time
import uuid
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from conftest import (BUILD_DIR, RUNNER, AbsoluteName, _marked_processes, junit_state,
                      leftover_processes, marked, plugin, run_runner, start_runner)

PASSING = plugin("passing_test")
ACTOR = Path(__file__).parent / "world" / "actor.py"


def passing_suite(tmp_path, name="suite.xml"):
    path = tmp_path / name
    path.write_text(f'<suite name="s">\n  <test>{PASSING}</test>\n</suite>\n')
    return path


# --- 1. Outputs never replace what is at their path ---------------------------------------------

def test_an_output_through_a_symlink_writes_its_target_and_keeps_the_link(tmp_path):
    target = tmp_path / "reports" / "junit.xml"
    target.parent.mkdir()
    target.write_text("old")
    link = tmp_path / "latest.xml"
    link.symlink_to(target)
    run = run_runner("--test", PASSING, "--output", f"junit:{link.name}", cwd=tmp_path)
    assert run.returncode == 0, run
    assert link.is_symlink(), "the link was replaced"
    assert "<testsuites" in target.read_text()


def test_an_output_that_is_a_folder_is_refused_before_the_run(tmp_path):
    folder = tmp_path / "out"
    folder.mkdir()
    run = run_runner("--test", PASSING, "--output", "text:out", cwd=tmp_path)
    assert run.returncode == 2, run
    assert "--output text:out: out is a folder" in run.stderr, run
    assert "passed" not in run.stdout, "the tests ran although the output was refused"
    assert folder.is_dir()


def test_an_output_to_a_fifo_is_written_through_to_its_reader(tmp_path):
    fifo = tmp_path / "results.fifo"
    os.mkfifo(fifo)
    received = []

    def read():
        with open(fifo, "rb") as f:  # blocks until the runner opens it for writing
            received.append(f.read())

    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    try:
        run = run_runner("--test", PASSING, "--output", f"junit:{fifo.name}", cwd=tmp_path)
    finally:
        reader.join(timeout=30)
        if reader.is_alive():  # the runner never opened it: release the reader
            os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
            reader.join(timeout=5)
    assert run.returncode == 0, run
    assert received and b"<testsuites" in received[0], received
    assert stat.S_ISFIFO(os.stat(fifo).st_mode), "the FIFO was replaced"


def test_an_output_to_a_fifo_nobody_reads_is_an_error_not_a_hang(tmp_path):
    fifo = tmp_path / "nobody.fifo"
    os.mkfifo(fifo)
    run = run_runner("--test", PASSING, "--output", f"text:{fifo.name}", cwd=tmp_path,
                     timeout=60)
    assert run.returncode == 2, run
    assert f"cannot write {fifo.name}: no process reads this FIFO" in run.stderr, run
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)


def device(tmp_path, name, minor):
    """/dev/NAME, or as root a node of the same device in tmp_path: a runner without the fix
    replaces the node it is given, and as root it could replace the system's. Named by its
    absolute path, as users name a device (/dev/null), whichever folder the runner is in: pass
    it as AbsoluteName."""
    if os.geteuid() != 0:
        return Path("/dev") / name
    node = tmp_path / name
    os.mknod(node, stat.S_IFCHR | 0o666, os.makedev(1, minor))
    return node


def test_a_write_error_is_exit_two_and_the_device_stays(tmp_path):
    full = device(tmp_path, "full", 7)
    run = run_runner("--test", PASSING, "--output", AbsoluteName(f"junit:{full}"), cwd=tmp_path)
    assert run.returncode == 2, run
    assert f"cannot write {full}: No space left on device" in run.stderr, run
    assert stat.S_ISCHR(os.stat(full).st_mode)


def test_an_output_to_dev_null_is_written_through(tmp_path):
    null = device(tmp_path, "null", 3)
    run = run_runner("--test", PASSING, "--output", AbsoluteName(f"junit:{null}"), "--output",
                     AbsoluteName(f"text:{null}"), cwd=tmp_path)
    assert run.returncode == 0, run
    assert stat.S_ISCHR(os.stat(null).st_mode)


def test_an_output_named_like_the_suite_file_is_refused(tmp_path):
    suite = passing_suite(tmp_path)
    before = suite.read_text()
    # Each spelling of the suite file's path, the absolute one too.
    for output in (AbsoluteName(f"junit:{suite}"), "text:./suite.xml", "suite.xml"):
        run = run_runner("--suite", suite.name, "--output", output, cwd=tmp_path)
        assert run.returncode == 2, (output, run)
        assert f"is the suite file {suite.name}; the output would replace it" in run.stderr, run
        assert suite.read_text() == before


def test_an_output_named_like_a_test_is_refused(tmp_path):
    test = tmp_path / "check.py"
    test.write_text("raise SystemExit('must not run')\n")
    copy = tmp_path / "libcopy.so"
    shutil.copy(PASSING, copy)
    # The test as given and the output as another spelling of its path (the absolute one).
    for args in (["--test", test.name, "--output", "text:./check.py"],
                 ["--test", f"./{copy.name}", "--output", AbsoluteName(f"junit:{copy}")]):
        run = run_runner(*args, cwd=tmp_path)
        assert run.returncode == 2, run
        assert "the output would replace it" in run.stderr and "is the test" in run.stderr, run
    assert test.read_text() == "raise SystemExit('must not run')\n"
    assert copy.read_bytes() == Path(PASSING).read_bytes()


def test_two_outputs_to_one_file_are_refused(tmp_path):
    run = run_runner("--test", PASSING, "--output", "junit:r.xml", "--output", "text:./r.xml",
                     cwd=tmp_path)
    assert run.returncode == 2, run
    assert ("--output text:./r.xml: ./r.xml is also the file of --output junit:r.xml"
            in run.stderr), run
    assert not (tmp_path / "r.xml").exists()


# --- 8. A suite file is a regular file of bounded size --------------------------------------------

def test_a_fifo_given_as_the_suite_is_refused_at_once(tmp_path):
    fifo = tmp_path / "suite.xml"
    os.mkfifo(fifo)
    run = run_runner("--suite", fifo.name, "--no-output", cwd=tmp_path, timeout=30)
    assert run.returncode == 2, run
    assert f"{fifo.name}: is a FIFO (named pipe), not a suite file" in run.stderr, run


def test_a_device_given_as_the_suite_is_refused(tmp_path):
    # A device is named by its absolute path, as users name it.
    run = run_runner("--suite", "/dev/zero", "--no-output", cwd=tmp_path, timeout=30)
    assert run.returncode == 2, run
    assert "/dev/zero: is a character device, not a suite file" in run.stderr, run


def test_a_suite_file_over_the_size_limit_is_refused(tmp_path):
    big = tmp_path / "big.xml"
    with open(big, "wb") as f:
        f.truncate(16 * 1024 * 1024 + 1)  # sparse: no disk used
    run = run_runner("--suite", big.name, "--no-output", cwd=tmp_path, timeout=30)
    assert run.returncode == 2, run
    assert (f"{big.name}: the suite file is larger than 16 MiB, the limit of a suite file"
            in run.stderr), run


# --- 11. Dependency cycles ------------------------------------------------------------------------

@pytest.mark.parametrize("tests,says", [
    ([("a", "b"), ("b", "a")],
     "suite.xml:2: dependency cycle: a (SUITE:2) depends on b (SUITE:3), which depends on a "
     "(SUITE:2)"),
    ([("a", "c"), ("b", "a"), ("c", "b")],
     "suite.xml:2: dependency cycle: a (SUITE:2) depends on c (SUITE:4), which depends on b "
     "(SUITE:3), which depends on a (SUITE:2)"),
    ([("ok", ""), ("a", "a")], "suite.xml:3: dependency cycle: a (SUITE:3) depends on itself"),
])
def test_a_dependency_cycle_is_a_configuration_error(tmp_path, tests, says):
    lines = "\n".join(f'<test name="{name}" depends="{on}">{PASSING}</test>' for name, on in tests)
    suite = tmp_path / "suite.xml"
    suite.write_text(f'<suite name="s">\n{lines}\n</suite>\n')
    run = run_runner("--suite", suite.name, "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert says.replace("SUITE", suite.name) in run.stderr, run


# --- 14. Messages that say what is wrong ----------------------------------------------------------

def test_a_repetition_too_large_says_the_limit(tmp_path):
    suite = tmp_path / "suite.xml"
    suite.write_text(f'<suite name="s">\n<test repetition="99999999999">{PASSING}</test>\n</suite>')
    run = run_runner("--suite", suite.name, "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert (f'{suite.name}:2: repetition="99999999999" is too large: at most 1000000000 runs'
            in run.stderr), run
    run = run_runner("--test", PASSING, "--repetition", "99999999999", "--no-output",
                     cwd=tmp_path)
    assert run.returncode == 2, run
    assert "--repetition: '99999999999' is too large: at most 1000000000 runs" in run.stderr, run


def test_an_empty_test_name_is_a_usage_error(tmp_path):
    run = run_runner("--test", "", "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert "--test: the value is empty" in run.stderr, run


@pytest.mark.parametrize("kind", ["folder", "fifo", "device"])
def test_a_test_or_fixture_that_is_no_file_says_what_it_is(tmp_path, kind):
    if kind == "folder":
        thing, says = tmp_path / "thing", "is a folder, not a plug-in file"
        thing.mkdir()
    elif kind == "fifo":
        thing, says = tmp_path / "thing", "is a FIFO (named pipe), not a plug-in file"
        os.mkfifo(thing)
    else:
        thing, says = Path("/dev/zero"), "is a character device, not a plug-in file"
    given = thing if kind == "device" else f"./{thing.name}"
    run = run_runner("--test", given, "--no-output", cwd=tmp_path, timeout=60)
    assert run.returncode == 1, run
    assert f"{says}: {given}" in run.output, run
    assert "not found" not in run.output, run

    suite = tmp_path / "suite.xml"
    suite.write_text(f'<suite name="s">\n<fixture type="dll">{given}</fixture>\n'
                     f'<test>{PASSING}</test>\n</suite>\n')
    run = run_runner("--suite", suite.name, "--no-output", cwd=tmp_path, timeout=60)
    assert run.returncode == 1, run
    assert f"{says}: {given}" in run.output, run


# --- 15. One rule for numbers and output types ----------------------------------------------------

def test_infinity_is_refused_by_one_rule_on_the_command_line_and_in_a_suite(tmp_path):
    run = run_runner("--test", PASSING, "--timeout", "inf", "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert "--timeout: 'inf' is not a number of seconds >= 0" in run.stderr, run
    suite = tmp_path / "suite.xml"
    suite.write_text(f'<suite name="s">\n<test timeout="inf">{PASSING}</test>\n</suite>')
    run = run_runner("--suite", suite.name, "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert f'{suite.name}:2: timeout "inf" is not a number of seconds >= 0' in run.stderr, run


def test_an_unknown_output_type_is_a_usage_error_listing_the_known_ones(tmp_path):
    run = run_runner("--test", PASSING, "--output", "junti:x.xml", cwd=tmp_path)
    assert run.returncode == 2, run
    assert "unknown output type 'junti' (expected text, junit, tap, json or html)" in run.stderr, run
    assert "text:junti:x.xml or ./junti:x.xml" in run.stderr, run
    assert list(tmp_path.iterdir()) == []


def test_a_file_name_with_a_colon_is_written_with_its_type_or_a_folder(tmp_path):
    run = run_runner("--test", PASSING, "--output", "text:junti:x.xml", "--output",
                     "./junti:y.xml", cwd=tmp_path)
    assert run.returncode == 0, run
    assert "passed" in (tmp_path / "junti:x.xml").read_text()
    assert "passed" in (tmp_path / "junti:y.xml").read_text()


def test_a_test_that_hangs_while_loading_reports_the_time_it_took(tmp_path):
    test = tmp_path / "slow_import.py"
    test.write_text("import time\ntime.sleep(30)\n")
    suite = tmp_path / "suite.xml"
    suite.write_text(f'<suite name="s">\n<test timeout="1">{test.name}</test>\n</suite>\n')
    junit = tmp_path / "r.xml"
    run = run_runner("--suite", suite.name, "--output", "junit:r.xml", cwd=tmp_path, timeout=60)
    assert run.returncode == 1, run
    assert "timed out after 1" in run.output, run
    case = ET.parse(junit).getroot().find(".//testcase")
    assert float(case.get("time")) >= 0.9, ET.tostring(case)


def wait_for(condition, timeout=30.0):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return True
        time.sleep(0.05)
    return False


def finish(proc, timeout=30):
    try:
        return proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        pytest.fail(f"the runner did not end within {timeout} s")


def test_a_second_ctrl_c_writes_the_result_files_with_what_is_known(tmp_path, marker):
    # In the runner's process nothing can stop fork_sleeper --hang politely: only the second
    # Ctrl-C ends the run.
    suite = tmp_path / "suite.xml"
    suite.write_text(f'''<suite name="stubborn">
  <test name="first">{PASSING}</test>
  <test name="stubborn" param="--hang">{plugin("fork_sleeper")}</test>
  <test name="never">{PASSING}</test>
</suite>''')
    junit = tmp_path / "out.xml"
    text = tmp_path / "out.txt"
    proc = start_runner("--isolation", "none", "--suite", suite.name, "--output", "junit:out.xml",
                        "--output", "text:out.txt", cwd=tmp_path, env=marked(marker))
    assert wait_for(lambda: len(_marked_processes(marker)) >= 2), "the sleeping child"
    proc.send_signal(signal.SIGINT)
    time.sleep(0.3)
    proc.send_signal(signal.SIGINT)
    begin = time.monotonic()
    out, err = finish(proc, timeout=10)
    assert time.monotonic() - begin < 5
    assert proc.returncode == 130, (out, err)
    assert "writing what is known and quitting" in out + err
    cases = {case.get("name"): junit_state(case)
             for case in ET.parse(junit).getroot().iter("testcase")}
    assert cases["first"] == "passed" and cases["stubborn"] == "interrupted", cases
    assert "stubborn" in text.read_text()
    assert leftover_processes(marker) == []


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_tests_not_run_because_ctrl_c_hit_a_fixture_set_up_are_interrupted(tmp_path, marker,
                                                                            isolation):
    # In the runner's process Ctrl-C does not cut the readiness wait short (the set-up ends at
    # its deadline): a short one there.
    deadline = "60s" if isolation == "process" else "4s"
    world = tmp_path / "world.xml"
    world.write_text(f'<world name="w" logdir="logs">\n'
                     f'  <process name="slow" command="/usr/bin/python3 {ACTOR} --say up">\n'
                     f'    <ready timeout="{deadline}"><file>{tmp_path / "never"}</file></ready>\n'
                     f'  </process>\n</world>\n')
    suite = tmp_path / "suite.xml"
    suite.write_text(f'<suite name="s">\n<fixture type="process">{world.name}</fixture>\n'
                     f'<test name="a">{PASSING}</test>\n<test name="b">{PASSING}</test>\n'
                     f'</suite>\n')
    junit = tmp_path / "out.xml"
    proc = start_runner("--isolation", isolation, "--suite", suite.name, "--output",
                        "junit:out.xml", "-v", cwd=tmp_path, env=marked(marker))
    log = tmp_path / "logs" / "slow.log"
    assert wait_for(lambda: log.exists() and "up" in log.read_text()), "the fixture's process"
    proc.send_signal(signal.SIGINT)
    out, err = finish(proc)
    assert proc.returncode == 130, (out, err)
    cases = {case.get("name"): junit_state(case)
             for case in ET.parse(junit).getroot().iter("testcase")}
    assert cases.get("a") == "interrupted" and cases.get("b") == "interrupted", (cases, out)
    assert leftover_processes(marker) == []


# --- 16. --var is never silently ignored ----------------------------------------------------------

def test_a_variable_nothing_reads_is_named_in_a_warning(tmp_path):
    run = run_runner("--test", PASSING, "--var", "robot=icub", "--no-output", cwd=tmp_path)
    assert run.returncode == 0, run
    assert ("warning: --var robot=icub is not used: no suite, test file or world file of a "
            "process fixture in this run reads ${robot}") in run.stderr, run


def test_a_variable_reaches_the_world_files_of_process_fixtures(tmp_path):
    world = tmp_path / "world.xml"
    world.write_text(f'<world name="w" logdir="logs">\n'
                     f'  <process name="p" command="/usr/bin/python3 {ACTOR} --say v=${{speed}}">\n'
                     f'    <ready timeout="10s"><output>^v=7$</output></ready>\n'
                     f'  </process>\n</world>\n')
    suite = tmp_path / "suite.xml"
    suite.write_text(f'<suite name="s">\n<fixture type="process">{world.name}</fixture>\n'
                     f'<test>{PASSING}</test>\n</suite>\n')
    run = run_runner("--suite", suite.name, "--var", "speed=7", "--var", "unused=1", "--no-output",
                     cwd=tmp_path, timeout=60)
    assert run.returncode == 0, run
    assert "--var speed=7" not in run.stderr, run
    assert "warning: --var unused=1 is not used" in run.stderr, run


# --- 17. Plug-ins beside a suite given by a relative path, installed or not -----------------------

@pytest.fixture(scope="module")
def installed_runner(tmp_path_factory):
    """The build tree installed into a fresh prefix (under the build tree): its runner."""
    prefix = tmp_path_factory.mktemp("prefix")
    result = subprocess.run(["cmake", "--install", str(BUILD_DIR), "--prefix", str(prefix)],
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    return prefix / "bin" / "robottestingframework-testrunner"


def run_with(runner, *args, cwd, timeout=60):
    env = dict(os.environ, RTF_E2E_MARK=uuid.uuid4().hex)
    return subprocess.run([str(runner), *map(str, args)], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=timeout, stdin=subprocess.DEVNULL)


@pytest.fixture(params=["installed", "build tree"])
def runner(request):
    return (request.getfixturevalue("installed_runner") if request.param == "installed"
            else RUNNER)


# The robot example listens on fixed ports: test_examples.py runs it, not here, where the
# installed and the build tree runners would race for them.
@pytest.mark.parametrize("suite,tests", [("example.xml", 2), ("./example.xml", 2),
                                         ("scripts.xml", 4)])
def test_the_examples_run_from_their_own_folder_by_a_relative_path(runner, suite, tests,
                                                                   tmp_path):
    run = run_with(runner, "--suite", suite, "--output", f"junit:{tmp_path / 'r.xml'}",
                   cwd=BUILD_DIR / "examples")
    assert run.returncode == 0, run.stdout + run.stderr
    assert "cannot load" not in run.stdout + run.stderr
    assert f"{tests} passed, 0 failed" in run.stdout, run.stdout


def test_plugins_beside_a_relative_suite_are_found(runner, tmp_path):
    folder = tmp_path / "suites"
    folder.mkdir()
    shutil.copy(PASSING, folder / "libbeside.so")
    (folder / "suite.xml").write_text('<suite name="s">\n<test>beside</test>\n'
                                      '<test>libbeside.so</test>\n</suite>\n')
    for isolation in ("process", "none"):
        run = run_with(runner, "--suite", "suites/suite.xml", "--isolation", isolation,
                       "--no-output", cwd=tmp_path)
        assert run.returncode == 0, run.stdout + run.stderr
        assert "2 passed, 0 failed" in run.stdout, run.stdout
        run = run_with(runner, "--suite", "suite.xml", "--isolation", isolation,
                       "--no-output", cwd=folder)
        assert run.returncode == 0, run.stdout + run.stderr
