"""The progress line: on a terminal (a real pseudo-terminal, python's pty) the runner keeps a
line at the bottom that rewrites itself, `[k/N] suite :: test (elapsed)`, with the failures so
far and an ETA from --durations; in a pipe the output stays one line per test with no such
line. --color=auto|always|never and NO_COLOR decide the colours. Run from the suite's own
folder with relative paths."""
import os
import pty
import re
import select
import shutil
import subprocess
import time

import pytest

from conftest import RUNNER, plugin, run_runner, terminal_environment

ERASE = "\r\033[K"
COLOURS = re.compile(r"\033\[3[123]m")


def suite_folder(tmp_path, seconds="1.6"):
    """Two suites: one whose first test waits `seconds`, then fails a check; one that passes."""
    shutil.copy(plugin("waiting_test"), tmp_path / "waiting_test.so")
    shutil.copy(plugin("failing_test"), tmp_path / "failing_test.so")
    shutil.copy(plugin("passing_test"), tmp_path / "passing_test.so")
    (tmp_path / "arm.xml").write_text(
        '<suite name="arm">\n'
        f'  <test name="slow" param="--seconds {seconds}">waiting_test</test>\n'
        '  <test name="broken">failing_test</test>\n'
        '</suite>\n')
    (tmp_path / "leg.xml").write_text(
        '<suite name="leg"><test name="walk">passing_test</test></suite>\n')
    return tmp_path


def run_on_terminal(args, cwd, env=None, timeout=60):
    """Runs the runner with stdout and stderr on a pseudo-terminal; (status, what it wrote)."""
    master, slave = pty.openpty()
    full_env = dict(os.environ)
    full_env.update(terminal_environment(**(env or {})))
    proc = subprocess.Popen([RUNNER, *args], cwd=cwd, stdin=subprocess.DEVNULL, stdout=slave,
                            stderr=slave, env=full_env, close_fds=True)
    os.close(slave)
    chunks = []
    deadline = time.monotonic() + timeout
    try:
        while time.monotonic() < deadline:
            ready, _, _ = select.select([master], [], [], 0.5)
            if ready:
                try:
                    data = os.read(master, 65536)
                except OSError:  # EIO: the terminal's other side is closed
                    break
                if not data:
                    break
                chunks.append(data)
            elif proc.poll() is not None:
                break
    finally:
        os.close(master)
        if proc.poll() is None:
            proc.kill()
        proc.wait(timeout=10)
    return proc.returncode, b"".join(chunks).decode(errors="replace")


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_on_a_terminal_the_line_rewrites_itself(tmp_path, jobs):
    folder = suite_folder(tmp_path)
    status, text = run_on_terminal(["-j", jobs, "--suite", "arm.xml", "--suite", "leg.xml",
                                    "--no-output"], folder)
    assert status == 1, text
    # k of N, the suite and the test, and its time going up while it runs (the ticker).
    slow = re.findall(r"\[\d/3\] arm :: slow \((\d+\.\d) s\)", text)
    assert slow, text
    assert min(float(s) for s in slow) < 1.0 < max(float(s) for s in slow), slow
    # Once the broken test has ended, the line counts one failure.
    assert re.search(r"\[\d/3\][^\r\n]*, \033\[31m1 failed\033\[0m", text), text
    assert ERASE in text
    # It is gone at the end: the closing line stands alone on the last line.
    closing = text.rfind("2 passed, 1 failed")
    assert closing > 0 and "/3]" not in text[closing:], text[-300:]


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_in_a_pipe_the_output_is_one_line_per_test(tmp_path, jobs):
    folder = suite_folder(tmp_path, seconds="0.3")
    run = run_runner("-j", jobs, "--suite", "arm.xml", "--suite", "leg.xml", "--no-output",
                     cwd=folder)
    assert run.returncode == 1, run
    assert "\033[" not in run.stdout and "\r" not in run.stdout, repr(run.stdout)
    assert "/3]" not in run.stdout, run.stdout


def test_the_eta_comes_from_an_earlier_report(tmp_path):
    folder = suite_folder(tmp_path, seconds="1.2")
    first = run_runner("--suite", "arm.xml", "--suite", "leg.xml", "--output", "junit:r.xml",
                       cwd=folder)
    assert first.returncode == 1, first
    status, without = run_on_terminal(["--suite", "arm.xml", "--suite", "leg.xml",
                                       "--no-output"], folder)
    assert "ETA" not in without, without
    status, text = run_on_terminal(["--suite", "arm.xml", "--suite", "leg.xml", "--no-output",
                                    "--durations", "r.xml"], folder)
    assert status == 1, text
    assert re.search(r"\[\d/3\] arm :: slow \(\d+\.\d s\), ETA \d+:\d\d", text), text


def test_colour_follows_the_option_and_no_color(tmp_path):
    folder = suite_folder(tmp_path, seconds="0.1")
    args = ["--suite", "leg.xml", "--no-output"]
    status, auto = run_on_terminal(args, folder)
    assert status == 0 and COLOURS.search(auto), auto
    status, no_color = run_on_terminal(args, folder, env={"NO_COLOR": "1"})
    assert status == 0 and not COLOURS.search(no_color), no_color
    status, never = run_on_terminal(["--color=never", *args], folder)
    assert status == 0 and not COLOURS.search(never), never
    # Forced in a pipe (a CI log that shows colour), even with NO_COLOR; still no progress line.
    forced = run_runner("--color", "always", *args, cwd=folder, env={"NO_COLOR": "1"})
    assert forced.returncode == 0 and COLOURS.search(forced.stdout), forced
    assert ERASE not in forced.stdout, repr(forced.stdout)
    piped = run_runner(*args, cwd=folder)
    assert not COLOURS.search(piped.stdout), repr(piped.stdout)
    bad = run_runner("--color", "sometimes", *args, cwd=folder)
    assert bad.returncode == 2 and "--color sometimes" in bad.stderr, bad
