"""The built-in process fixture through the real runner: readiness of every kind, dependencies,
deadlines, collapse, failing fixtures, long names, Ctrl-C and SIGKILL. After each test no
process of the run is left (each run marks its processes with an environment variable)."""
import os
import re
import shlex
import signal
import socket
import subprocess
import sys
import time
import uuid
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from conftest import RUNNER, cache_value, plugin, run_runner, start_runner, validate_junit

ACTOR = Path(__file__).parent / "world" / "actor.py"
PYTHON = "/usr/bin/python3"
MARK = "RTF_E2E_PROCESS_FIXTURE"
# A skipped test that was never loaded is named by its file.
SKIPPED_PASSING = r"skipped\s+.*?(PassingTest|passing_test)"  # "skipped  SUITE/ID"


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def marked(mark):
    """Pids of the live processes carrying MARK=mark."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                state = f.read().rsplit(")", 1)[1].split()[0]
            with open(f"/proc/{entry}/environ", "rb") as f:
                env = f.read().split(b"\0")
        except OSError:
            continue
        if state != "Z" and f"{MARK}={mark}".encode() in env:
            found.append(int(entry))
    return found


def wait_until(condition, timeout=10):
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        if condition():
            return True
        time.sleep(0.02)
    return condition()


@pytest.fixture
def mark():
    """A unique mark for this test's run; afterwards nothing may carry it."""
    value = uuid.uuid4().hex
    yield value
    # The portable build's parent-death guards leave within their poll interval (200 ms) of
    # the process they watch; nothing else may need the grace.
    wait_until(lambda: not marked(value), timeout=3)
    left = marked(value)
    for pid in left:
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass
    assert not left, f"processes left behind: {left}"


def actor(*args):
    """The command line of the test server, quoted for the world file's command splitting."""
    return " ".join(shlex.quote(str(word)) for word in [PYTHON, ACTOR, *args])


def world(tmp_path, processes, name="world.xml"):
    path = tmp_path / name
    path.write_text(f'<world name="e2e" logdir="logs">\n{processes}\n</world>\n')
    return path


def suite(tmp_path, fixtures, tests=None, name="suite.xml"):
    """Writes a suite file in tmp_path; returns its name relative to tmp_path, the folder the
    runner runs in (as users name their suite)."""
    tests = tests if tests is not None else [plugin("passing_test")]
    text = '<suite name="process world">\n' + "\n".join(fixtures) + "\n" + "\n".join(
        t if str(t).startswith("<") else f"<test>{t}</test>" for t in tests) + "\n</suite>\n"
    path = tmp_path / name
    path.write_text(text)
    return path.relative_to(tmp_path)


def process_fixture(world_path, param=""):
    """The fixture of the world file `world_path`, named relative to the suite beside it."""
    return f'<fixture type="process" param="{param}">{world_path.name}</fixture>'


def run(mark, *args, **kwargs):
    return run_runner(*args, env={MARK: mark}, **kwargs)


def waiting(seconds):
    """A test that takes `seconds` unless it is interrupted."""
    return f'<test param="--seconds {seconds}">{plugin("waiting_test")}</test>'


# --- Readiness of every kind -------------------------------------------------------------------

def test_ready_by_port_of_a_real_http_server(tmp_path, mark):
    port = free_port()
    w = world(tmp_path, f"""
  <process name="web" command="{PYTHON} -m http.server --bind 127.0.0.1 {port}">
    <ready timeout="10s"><port>{port}</port></ready>
  </process>""")
    r = run(mark, "-v", "-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path)
    assert r.returncode == 0, r
    assert f"starting 'web': {PYTHON} -m http.server --bind 127.0.0.1 {port}" in r.output, r
    assert f"waiting for 'web'" in r.output and f"TCP port 127.0.0.1:{port}" in r.output, r
    assert re.search(r"'web' is ready after \d+", r.output), r
    assert "stopping 'web'" in r.output, r
    # The server printed nothing (its banner stays in Python's buffer, no request was served):
    # an empty log is not kept, nor the folder made for it (issue 38, item 13).
    assert not (tmp_path / "logs").exists(), list((tmp_path / "logs").rglob("*"))


@pytest.mark.parametrize("kind", ["output", "file", "probe", "delay"])
def test_ready_by_each_kind_of_check(tmp_path, mark, kind):
    flag = tmp_path / "up.flag"
    checks = {
        "output": "<output>^calibration done in \\d+ ms$</output>",
        "file": f"<file>{flag.name}</file>",
        "probe": f'<probe interval="20ms">test -e {flag}</probe>',
        "delay": "<delay>600ms</delay>",
    }
    w = world(tmp_path, f"""
  <process name="robot" command="{actor('--sleep', 0.4, '--touch', flag,
                                         '--say', 'calibration done in 400 ms')}">
    <ready timeout="10s">{checks[kind]}</ready>
  </process>""")
    r = run(mark, "-v", "-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path)
    assert r.returncode == 0, r
    took = re.search(r"'robot' is ready after (\d+) ms", r.output)
    assert took, r
    assert int(took.group(1)) >= 400 if kind != "delay" else int(took.group(1)) >= 600, r
    assert int(took.group(1)) < 3000, r


def test_a_chain_of_three_starts_each_after_the_one_it_depends_on(tmp_path, mark):
    port = free_port()
    # Written out of order: the dependencies decide, and each fails unless its
    # dependency was ready (its file exists) when it started.
    w = world(tmp_path, f"""
  <process name="robot" depends="middleware">
    <command>{actor('--require', 'middleware.ready', '--say', 'robot up')}</command>
    <ready><output>robot up</output></ready>
  </process>
  <process name="simulator">
    <command>{actor('--sleep', 0.3, '--listen', port, '--touch', 'simulator.ready')}</command>
    <ready><port>{port}</port></ready>
  </process>
  <process name="middleware" depends="simulator">
    <command>{actor('--require', 'simulator.ready', '--sleep', 0.2,
                    '--touch', 'middleware.ready')}</command>
    <ready><file>middleware.ready</file></ready>
  </process>""")
    r = run(mark, "-v", "-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path)
    assert r.returncode == 0, r
    started = re.findall(r"starting '(\w+)'", r.output)
    stopped = re.findall(r"stopping '(\w+)'", r.output)
    assert started == ["simulator", "middleware", "robot"], r
    assert stopped == ["robot", "middleware", "simulator"], r


# --- Failures ----------------------------------------------------------------------------------

def test_a_process_that_never_becomes_ready_fails_the_suite_with_the_deadline(tmp_path, mark):
    w = world(tmp_path, f"""
  <process name="stuck" command="{actor('--say', 'waiting for the hardware')}">
    <ready timeout="700ms"><output>^ready$</output></ready>
  </process>""")
    junit = tmp_path / "out.xml"
    # No --verbose: the failure alone must tell the whole story.
    r = run(mark, "-s", suite(tmp_path, [process_fixture(w)]), "-o", junit.name,
            "--output-type", "junit", cwd=tmp_path)
    assert r.returncode == 1, r
    assert ("process 'stuck' did not become ready: a line of output matching '^ready$' did not "
            "happen within 700 ms") in r.output, r
    assert "waiting for the hardware" in r.output, r       # its last lines
    assert str(tmp_path / "logs" / "stuck.log") in r.output, r
    assert re.search(SKIPPED_PASSING, r.output), r
    text = junit.read_text()
    assert "did not become ready" in text
    validate_junit(junit)


def test_a_process_that_dies_mid_suite_skips_the_rest_with_the_reason(tmp_path, mark):
    w = world(tmp_path, f"""
  <process name="motor driver" command="{actor('--say', 'ready', '--die-after', 0.5,
                                                '--status', 5)}">
    <ready><output>ready</output></ready>
  </process>""")
    junit = tmp_path / "out.xml"
    s = suite(tmp_path, [process_fixture(w)],
              [waiting(3), plugin("passing_test"), plugin("passing_test")])
    began = time.monotonic()
    r = run(mark, "-s", s, "-o", junit.name, "--output-type", "junit", cwd=tmp_path)
    assert r.returncode == 1, r
    assert time.monotonic() - began < 10, r
    reason = "process 'motor driver' exited with status 5"
    assert reason in r.output, r
    assert "lost contact with the motors" in r.output, r
    assert len(re.findall(SKIPPED_PASSING, r.output)) == 2, r
    text = junit.read_text()
    # Said by the suite's error, not again on each skipped test (issue 38, friction 9).
    assert reason in text, text
    # Each skipped test gives the first line of the reason (a test case read alone says why),
    # not its log's tail.
    skipped = ET.parse(junit).getroot().iter("skipped")
    messages = [s.get("message") for s in skipped]
    assert len(messages) == 2 and all(
        m.startswith("the suite's fixture collapsed (see the suite's error): world ")
        and "\n" not in m for m in messages), messages
    validate_junit(junit)


def test_a_line_of_10_mb_costs_the_fixture_nothing_and_the_next_line_is_seen(tmp_path, mark):
    # The <output> check's std::regex recursed over the whole 10 MB line: the fixture died of
    # SIGSEGV. Each line is now matched on its first 4 KiB (docs/reference/world-file.md).
    w = world(tmp_path, f"""
  <process name="chatty" command="{actor('--spew', 10, '--say', 'ready')}">
    <ready timeout="30s"><output>^x*y?ready$</output></ready>
  </process>""")
    r = run(mark, "-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path)
    assert r.returncode == 0, r
    assert "1 passed" in r.output, r
    assert (tmp_path / "logs" / "chatty.log").stat().st_size > 10 * 1024 * 1024


def test_a_failing_fixture_plugin_after_the_world_takes_the_world_down(tmp_path, mark):
    w = world(tmp_path, f"""
  <process name="broker" command="{actor('--say', 'ready')}">
    <ready><output>ready</output></ready>
  </process>""")
    log = tmp_path / "order.log"
    failing = (f'<fixture param="--log {log} --name B --fail-setup">'
               f'{plugin("order_fixture")}</fixture>')
    r = run(mark, "-v", "-s", suite(tmp_path, [process_fixture(w), failing]), cwd=tmp_path)
    assert r.returncode == 1, r
    assert "'broker' is ready" in r.output, r
    assert "stopping 'broker'" in r.output, r
    assert re.search(SKIPPED_PASSING, r.output), r


def test_a_bad_world_file_names_file_and_line(tmp_path, mark):
    w = world(tmp_path, """
  <process name="a" command="true"/>
  <process name="b" depends="c" command="true"/>""")
    r = run(mark, "-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path)
    assert r.returncode == 2, r
    assert f"{w}:4: process 'b' depends on 'c', which is not a process of this world" \
        in r.output, r


# Issue 39, 12: a world file is read when the plan is made, so what is wrong with it is a
# configuration error (exit 2, file and line) before anything runs, --list included.
BAD_WORLDS = {
    "cycle": ("""<world name="w">
  <process name="a" depends="b" command="true"/>
  <process name="b" depends="a" command="true"/>
</world>
""", "world.xml:2: dependency cycle: 'a' -> 'b' -> 'a'"),
    "unknown depends": ("""<world name="w">
  <process name="a" depends="nobody" command="true"/>
</world>
""", "world.xml:2: process 'a' depends on 'nobody', which is not a process of this world"),
    "malformed XML": ("""<world name="w">
  <process name="a" command="true">
</world>
""", "world.xml:3: malformed XML"),
    "bad pattern": ("""<world name="w">
  <process name="a" command="true">
    <ready><output>(up)\\1</output></ready>
  </process>
</world>
""", "world.xml:3: '(up)\\1' in <output> is not a regular expression RE2 takes"),
}


@pytest.mark.parametrize("listing", [False, True], ids=["run", "list"])
@pytest.mark.parametrize("problem", sorted(BAD_WORLDS))
def test_a_bad_world_file_is_a_configuration_error_before_the_run(tmp_path, mark, problem,
                                                                   listing):
    text, expected = BAD_WORLDS[problem]
    (tmp_path / "world.xml").write_text(text)
    s = suite(tmp_path, ['<fixture type="process">world.xml</fixture>'])
    r = run(mark, *(["--list"] if listing else []), "-s", s, cwd=tmp_path, timeout=60)
    assert r.returncode == 2, r
    assert f"{tmp_path / expected}" in r.stderr, r
    assert "suite.xml:2" in r.stderr, r          # the fixture that names it
    assert "starting" not in r.output and not (tmp_path / "logs").exists(), r


@pytest.mark.parametrize("listing", [False, True], ids=["run", "list"])
def test_a_missing_world_file_is_named_and_not_searched_for_as_a_plugin(tmp_path, mark, listing):
    s = suite(tmp_path, ['<fixture type="process">world.xml</fixture>'])
    r = run(mark, *(["--list"] if listing else []), "-s", s, cwd=tmp_path, timeout=60)
    assert r.returncode == 2, r
    assert (f"suite.xml:2: the world file 'world.xml' of the process fixture does not exist "
            f"(looked for {tmp_path / 'world.xml'})") in r.stderr, r
    assert "libworld" not in r.output, r


# --- Readiness patterns and lines (issue 39, 4 and 13) -----------------------------------------

def test_a_backtracking_pattern_keeps_its_deadline(tmp_path, mark):
    # std::regex took 28 s on 18 a's and minutes on 24; RE2 matches in time linear in the line.
    w = world(tmp_path, f"""
  <process name="a" command="{actor('--say', 'a' * 28)}">
    <ready timeout="1s"><output>^(a*)*b$</output></ready>
  </process>""")
    began = time.monotonic()
    r = run(mark, "-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path, timeout=60)
    took = time.monotonic() - began
    assert r.returncode == 1, r
    assert "a line of output matching '^(a*)*b$' did not happen within 1 s" in r.output, r
    assert took < 15, (took, r)


def test_a_ready_line_without_a_newline_is_matched_at_the_deadline(tmp_path, mark):
    w = world(tmp_path, f"""
  <process name="a" command="{actor('--say', 'starting', '--print', 'READY')}">
    <ready timeout="1s"><output>^READY$</output></ready>
  </process>""")
    r = run(mark, "-v", "-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path, timeout=60)
    assert r.returncode == 0, r
    assert "its last line has no newline, so it was matched only at the deadline" in r.output, r


def test_a_line_without_a_newline_that_does_not_match_is_said(tmp_path, mark):
    w = world(tmp_path, f"""
  <process name="a" command="{actor('--print', 'NOT YET')}">
    <ready timeout="500ms"><output>^READY$</output></ready>
  </process>""")
    r = run(mark, "-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path, timeout=60)
    assert r.returncode == 1, r
    assert "its last line, not ended by a newline, does not match either" in r.output, r


# --- Whose listener (issue 39, 8) ---------------------------------------------------------------

def test_a_port_taken_after_the_start_by_another_program_is_not_the_world_ready(tmp_path, mark):
    # The world's server listens only after 3 s; this test listens on its port once the
    # process started (after the pre-check): the connection is accepted, by the wrong program.
    port = free_port()
    w = world(tmp_path, f"""
  <process name="server" command="{actor('--sleep', 3, '--listen', port)}">
    <ready timeout="10s"><port>{port}</port></ready>
  </process>""")
    runner = start_runner("-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path,
                          env={MARK: mark})
    try:
        assert wait_until(lambda: (tmp_path / "logs" / "server.log").exists()), "never started"
        time.sleep(0.5)   # the pre-check is over: it comes right after the log is made
        with socket.socket() as intruder:
            intruder.bind(("127.0.0.1", port))
            intruder.listen()
            out, err = runner.communicate(timeout=60)
    finally:
        if runner.poll() is None:
            runner.kill()
            runner.communicate()
    if cache_value("RTF_PORTABLE_POSIX", "OFF") == "ON":
        # The portable build (macOS code paths) cannot tell whose listener it reached and
        # counts it, as documented (docs/reference/world-file.md).
        assert runner.returncode == 0, (out, err)
        return
    assert runner.returncode == 1, (out, err)
    assert (f"process 'server' did not become ready: TCP port 127.0.0.1:{port} accepting "
            f"connections (line 4) accepts connections, but from pid {os.getpid()} (") \
        in out + err, (out, err)
    assert "is ready after" not in out + err, (out, err)


def test_a_port_of_a_descendant_that_left_the_group_is_the_world_ready(tmp_path, mark):
    # A listener of the world's own (a daemon that left the process group) still counts.
    port = free_port()
    w = world(tmp_path, f"""
  <process name="daemon">
    <command shell="true">setsid {actor('--listen', port)} &amp; exec sleep 60</command>
    <ready timeout="10s"><port>{port}</port></ready>
  </process>""")
    r = run(mark, "-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path, timeout=60)
    assert r.returncode == 0, r


# --- Stale files, zero grace (issue 39, 9 and 11) ----------------------------------------------

def test_a_file_left_from_an_earlier_run_is_refused(tmp_path, mark):
    (tmp_path / "up.flag").write_text("")   # left by an earlier run
    w = world(tmp_path, f"""
  <process name="a" command="{actor('--sleep', 30, '--touch', 'up.flag')}">
    <ready timeout="10s"><file>up.flag</file></ready>
  </process>""")
    r = run(mark, "-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path, timeout=60)
    assert r.returncode == 1, r
    assert (f"file {tmp_path / 'up.flag'} (readiness check, line 4) exists before the process "
            "starts") in r.output, r
    assert "ready after" not in r.output, r


def test_a_zero_grace_kills_at_once_and_is_no_failure(tmp_path, mark):
    w = world(tmp_path, f"""
  <process name="a" command="{actor('--say', 'up')}">
    <ready timeout="10s"><output>up</output></ready>
    <stop grace="0s"/>
  </process>""")
    r = run(mark, "-v", "-s", suite(tmp_path, [process_fixture(w)]), cwd=tmp_path, timeout=60)
    assert r.returncode == 0, r
    assert "stopping 'a'" in r.output and "with SIGKILL at once (grace 0)" in r.output, r
    assert "'a' was killed at once (grace 0): it was killed by signal SIGKILL" in r.output, r
    assert "did not stop within" not in r.output, r


# --- Names, signals ----------------------------------------------------------------------------

def test_a_200_character_application_and_process_name(tmp_path, mark):
    name = "robot-interface-" + "x" * 184
    assert len(name) == 200
    program = tmp_path / ("app-" + "y" * 196)   # a 200-character program name too
    program.write_text(f"#!/bin/sh\nexec {PYTHON} {ACTOR} \"$@\"\n")
    program.chmod(0o755)
    w = world(tmp_path, f"""
  <process name="{name}">
    <command><arg>./{program.name}</arg><arg>--say</arg><arg>ready</arg>
             <arg>--die-after</arg><arg>0.5</arg></command>
    <ready><output>ready</output></ready>
  </process>""")
    s = suite(tmp_path, [process_fixture(w)], [waiting(3), plugin("passing_test")])
    r = run(mark, "-v", "-s", s, cwd=tmp_path)
    assert r.returncode == 1, r
    assert f"'{name}' is ready" in r.output, r
    assert f"process '{name}' exited with status 3" in r.output, r


def test_sigint_during_setup_stops_the_world(tmp_path, mark):
    port = free_port()
    w = world(tmp_path, f"""
  <process name="up" command="{actor('--listen', port)}">
    <ready><port>{port}</port></ready>
  </process>
  <process name="slow" depends="up" command="{actor('--say', 'booting')}">
    <ready timeout="60s"><output>^never$</output></ready>
  </process>""")
    s = suite(tmp_path, [process_fixture(w)])
    proc = subprocess.Popen([RUNNER, "-s", str(s)], cwd=tmp_path, env={**os.environ, MARK: mark},
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    try:
        # Both processes of the world run: the runner is inside the fixture's setup.
        assert wait_until(lambda: len(marked(mark)) >= 3), "the world did not start"
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.communicate()
    assert proc.returncode != 0, out + err
    assert wait_until(lambda: not marked(mark), 5), f"left: {marked(mark)}\n{out}\n{err}"


@pytest.mark.parametrize("isolation", ["none", "default"])
def test_sigkill_of_the_runner_leaves_no_process(tmp_path, mark, isolation):
    w = world(tmp_path, f"""
  <process name="broker" command="{actor('--say', 'ready', '--orphan')}">
    <ready><output>ready</output></ready>
  </process>""")
    s = suite(tmp_path, [process_fixture(w)], [waiting(30)])
    args = [RUNNER, "-s", str(s)] + (["--isolation", isolation] if isolation != "default" else [])
    proc = subprocess.Popen(args, cwd=tmp_path, env={**os.environ, MARK: mark},
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        # The runner, the actor and its orphan.
        assert wait_until(lambda: len(marked(mark)) >= 3), "the world did not start"
        world_pids = set(marked(mark)) - {proc.pid}
        proc.kill()
        proc.wait(timeout=10)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    survivors = lambda: [p for p in marked(mark) if p in world_pids]  # noqa: E731
    gone = wait_until(lambda: not survivors(), 5)
    if not gone and isolation == "none":
        # Documented residual risk: in --isolation none a grandchild that left its process
        # group (setsid) is not killed when the runner is SIGKILLed. Clean up and tell.
        left = survivors()
        for pid in left:
            os.kill(pid, signal.SIGKILL)
        pytest.xfail(f"--isolation none: {len(left)} escaped grandchild(ren) outlived a SIGKILL "
                     "of the runner (docs/reference/world-file.md)")
    assert gone, f"left behind: {survivors()}"
