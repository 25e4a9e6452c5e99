"""Hostile world files and world processes of the process fixture, through the installed runner:
what a world process or a world file does must not hang the run, lose what a failure says, nor
pass unnoticed. Each run marks its processes (conftest.marked) and asserts none is left."""
import re
import resource
import shutil
import socket
import time

import pytest

from conftest import SANITIZED, leftover_processes, marked, plugin, run_runner

PYTHON = "/usr/bin/python3"
ISOLATIONS = ["process", "none"]


def write_world(tmp_path, processes, prolog=""):
    (tmp_path / "world.xml").write_text(
        f'<world name="hostile" logdir="logs">\n{prolog}{processes}\n</world>\n')


def write_suite(tmp_path):
    (tmp_path / "suite.xml").write_text(
        '<suite name="hostile">\n'
        '  <fixture type="process">world.xml</fixture>\n'
        f'  <test>{plugin("passing_test")}</test>\n'
        '</suite>\n')
    return "suite.xml"


def run(tmp_path, marker, isolation, timeout=60):
    return run_runner("--isolation", isolation, "-s", write_suite(tmp_path), cwd=tmp_path,
                      env=marked(marker), timeout=timeout)


# --- Durations: "inf" and "1e99s" read as numbers, and held the run for ever -----------------------

@pytest.mark.parametrize("isolation", ISOLATIONS)
@pytest.mark.parametrize("where, value, says", [
    ('<stop grace="{}"/>', "inf", 'grace="..." of <stop>'),
    ('<stop grace="{}"/>', "1e99s", 'grace="..." of <stop>'),
    ('<ready timeout="{}"><output>up</output></ready>', "infinity", 'timeout="..." of <ready>'),
    ('<ready><delay>{}</delay></ready>', "1e308min", "<delay>"),
], ids=["grace-inf", "grace-1e99s", "ready-infinity", "delay-1e308min"])
def test_an_endless_duration_is_a_configuration_error_not_a_run_held_for_ever(
        tmp_path, marker, isolation, where, value, says):
    # Before the fix, a process that ignores SIGTERM with grace="inf" was waited for without
    # end (the run never finished); "infinity" as a deadline waited for ever for a line.
    write_world(tmp_path, f"""  <process name="stubborn">
    <command shell="true">trap '' TERM; echo up; exec {PYTHON} -c "import signal,time;\
signal.signal(signal.SIGTERM, signal.SIG_IGN);time.sleep(30)"</command>
    {where.format(value)}
  </process>""")
    r = run(tmp_path, marker, isolation, timeout=20)
    assert r.returncode == 2, r
    assert f"world.xml:4: '{value}' is not a duration in {says}" in r.stderr, r
    assert "at most 1000000 s, about 11.5 days" in r.stderr, r
    assert "suite.xml:2" in r.stderr, r
    assert not (tmp_path / "logs").exists(), r
    assert not leftover_processes(marker), r


# --- A NUL byte in a world process's output ----------------------------------------------------

NUL_PRINTER = """import sys, time
sys.stdout.buffer.write(b"loading \\xff\\xfe \\x00 half a line\\n")
sys.stdout.buffer.write(b"the line after the NUL\\n")
sys.stdout.flush()
time.sleep(0.2)
sys.exit(3)
"""


@pytest.mark.parametrize("isolation", ISOLATIONS)
def test_a_nul_byte_in_a_world_process_output_does_not_cut_the_failure(tmp_path, marker,
                                                                         isolation):
    # The failure quotes the process's last lines; before the fix, a NUL in one ended the
    # message there (the fixture's exception was read through what(), a C string): the status,
    # the command, the following lines were lost from the console and from every report.
    (tmp_path / "nul.py").write_text(NUL_PRINTER)
    write_world(tmp_path, f"""  <process name="nul printer" command="{PYTHON} nul.py">
    <ready timeout="10s"><output>never printed</output></ready>
  </process>""")
    r = run_runner("--isolation", isolation, "-s", write_suite(tmp_path), "-o",
                   "junit:report.xml", cwd=tmp_path, env=marked(marker), timeout=60)
    assert r.returncode == 1, r
    assert "process 'nul printer' exited with status 3 before it was ready" in r.stdout, r
    error = r.stdout[r.stdout.index("error: fixture world.xml failed"):]
    assert "half a line" in error, r
    assert "| the line after the NUL" in error, r
    report = (tmp_path / "report.xml").read_text(errors="replace")
    assert "the line after the NUL" in report, report
    assert not leftover_processes(marker), r


# --- What a world file says in the wrong place ------------------------------------------------------

# Each was read without a word before the fix: the run started the world as if the line were not
# there (a process "ready" at once, the first value of a variable silently replaced).
MISPLACED = {
    "text in ready": (
        '  <process name="server" command="sleep 30">\n    <ready>\n      5s</ready>\n'
        '  </process>',
        "world.xml:4: text '5s' in <ready> (expected readiness checks"),
    "variable twice": (
        '  <process name="server" command="sleep ${seconds}"/>',
        'world.xml:3: <variable name="seconds"> given twice (first at line 2)'),
    "element in port": (
        '  <process name="server" command="sleep 30">\n    <ready><port>8080\n'
        '      <host>::1</host></port></ready>\n  </process>',
        "world.xml:4: unexpected element <host> in <port> (it takes text only)"),
    "element in stop": (
        '  <process name="server" command="sleep 30">\n    <stop>\n      <grace>1s</grace>\n'
        '    </stop>\n  </process>',
        "world.xml:4: unexpected element <grace> in <stop>"),
}


@pytest.mark.parametrize("listing", [False, True], ids=["run", "list"])
@pytest.mark.parametrize("case", sorted(MISPLACED))
def test_text_or_elements_in_the_wrong_place_are_a_configuration_error(tmp_path, marker, case,
                                                                        listing):
    processes, expected = MISPLACED[case]
    prolog = ('  <variable name="seconds">30</variable>\n  <variable name="seconds">1</variable>\n'
              if case == "variable twice" else "")
    write_world(tmp_path, processes, prolog)
    r = run_runner(*(["--list"] if listing else []), "-s", write_suite(tmp_path), cwd=tmp_path,
                   env=marked(marker), timeout=60)
    assert r.returncode == 2, r
    assert str(tmp_path / expected) in r.stderr, r
    assert "suite.xml:2" in r.stderr, r
    assert "starting" not in r.output and not (tmp_path / "logs").exists(), r
    assert not leftover_processes(marker), r


@pytest.mark.parametrize("reference", ["&#0;", "&#x000;"])
def test_a_nul_character_reference_is_refused_not_a_pattern_cut_short(tmp_path, marker,
                                                                       reference):
    # Before the fix the pattern ended at the NUL pugixml decoded: the world was "ready" on a
    # line matching READY, which is not what the file asks for.
    write_world(tmp_path, f"""  <process name="server" command="{PYTHON} -u -c 'print(&quot;READY&quot;);import time;time.sleep(30)'">
    <ready timeout="5s"><output>READY{reference}NOT</output></ready>
  </process>""")
    r = run(tmp_path, marker, "process")
    assert r.returncode == 2, r
    assert (f"{tmp_path / 'world.xml'}:3: '{reference}' is a NUL character, which XML does not "
            "allow") in r.stderr, r
    assert "passed" not in r.stdout, r
    assert not leftover_processes(marker), r


# --- A program that daemonizes ---------------------------------------------------------------------

def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.mark.parametrize("isolation", ISOLATIONS)
@pytest.mark.parametrize("leaves", ["group", "session"])
def test_a_program_that_daemonizes_fails_saying_so_and_leaves_no_server(tmp_path, marker,
                                                                        isolation, leaves):
    # Its parent exits 0 at once while the server it forked (in its group, or in a session of
    # its own) keeps the port: the world cannot wait for a process that is gone. The failure
    # said only "exited with status 0 before it was ready"; it now says what to do, and the
    # server it left is stopped either way.
    port = free_port()
    setsid = "setsid " if leaves == "session" else ""
    write_world(tmp_path, f"""  <process name="broker">
    <command shell="true">{setsid}{PYTHON} -m http.server --bind 127.0.0.1 {port} &amp; exit 0</command>
    <ready timeout="10s"><port>{port}</port></ready>
  </process>""")
    r = run(tmp_path, marker, isolation)
    assert r.returncode == 1, r
    assert "process 'broker' exited with status 0 before it was ready" in r.stdout, r
    assert ("a program that puts itself in the background (daemonizes) must be told to stay in "
            "the foreground") in r.stdout, r
    assert not leftover_processes(marker), r


# --- A probe that never ends and prints without end --------------------------------------------------

@pytest.mark.parametrize("isolation", ISOLATIONS)
def test_an_endless_probe_printing_without_end_keeps_the_runner_small(tmp_path, marker,
                                                                      isolation):
    # The probe's whole output was kept while it ran (only its end is ever quoted): a status
    # command that never returns and prints without end grew the runner (or its fixture
    # worker) by about 500 MB a second until the deadline, 1 GB in 2 s here; with the default
    # deadline of 30 s a robot's PC ran out of memory and the run was killed.
    write_world(tmp_path, """  <process name="server" command="sleep 30">
    <ready timeout="2s"><probe>cat /dev/zero</probe></ready>
  </process>""")
    r = run(tmp_path, marker, isolation)
    peak_kib = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
    assert r.returncode == 1, r
    assert "probe `cat /dev/zero` to exit with status 0 did not happen within 2 s" in r.stdout, r
    assert not leftover_processes(marker), r
    if not SANITIZED:
        # The largest process this test session waited for (runners, workers, probes).
        assert peak_kib < 300 * 1024, f"peak {peak_kib} KiB\n{r}"


# --- Descendants that flood the output pipe ----------------------------------------------------

@pytest.mark.parametrize("isolation", ISOLATIONS)
def test_an_exit_under_a_flood_of_output_is_seen_at_once_and_timed_right(tmp_path, marker,
                                                                         isolation):
    # Its child keeps the output pipe full after it exits with status 3 at 0.5 s. The fixture
    # read the pipe for as long as it stayed full (each read of 64 KiB was followed by another):
    # the exit was seen late and said to be "after 4 ms" or "after 140 ms", and the last drain
    # of the ended process read its children's flood for up to a second more.
    write_world(tmp_path, """  <process name="flooded">
    <command shell="true">yes &amp; sleep 0.5; exit 3</command>
    <ready timeout="10s"><output>never printed</output></ready>
  </process>""")
    began = time.monotonic()
    r = run(tmp_path, marker, isolation)
    took = time.monotonic() - began
    assert r.returncode == 1, r
    found = re.search(r"process 'flooded' exited with status 3 before it was ready "
                      r"\(after (\d+) ms\)", r.stdout)
    assert found, r
    assert 450 <= int(found.group(1)) <= 1500, r
    assert took < 5, f"{took:.1f} s\n{r}"
    assert not leftover_processes(marker), r
    shutil.rmtree(tmp_path / "logs")  # hundreds of MB of "y"


def test_an_empty_port_host_is_a_configuration_error_before_anything_starts(tmp_path, marker):
    # It was found only once the process ran: "could not be started: cannot resolve host ''",
    # exit 1, the process started and stopped for nothing.
    write_world(tmp_path, """  <process name="server" command="sleep 30">
    <ready timeout="5s"><port host="">8080</port></ready>
  </process>""")
    r = run(tmp_path, marker, "process")
    assert r.returncode == 2, r
    assert f"{tmp_path / 'world.xml'}:3: <port host=\"\"> is empty" in r.stderr, r
    assert not leftover_processes(marker), r
