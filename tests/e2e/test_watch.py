"""--watch (issue 38 item 14, docs/how-to/watch.md): the runner runs, waits for a suite file, a
test file or a plug-in to change, runs again (the tests that failed first), and Ctrl-C ends it
cleanly: its status is the last run's, no process and no temporary folder are left. Run from
the suite's folder with relative paths; every wait is bounded."""
import os
import signal
import subprocess
import sys
import time

import pytest

from conftest import RUNNER, runner_environment

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="--watch: not on Windows")


def save(path, text):
    """As editors save: a new file renamed over the old one (a file truncated, then written,
    may be read between the two under load)."""
    path.with_suffix(".new").write_text(text)
    path.with_suffix(".new").chmod(path.stat().st_mode)
    os.replace(path.with_suffix(".new"), path)


def wait_for(predicate, seconds=30):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.05)
    return False


def test_a_change_runs_again_failed_first_and_ctrl_c_leaves_nothing(tmp_path):
    (tmp_path / "t.sh").write_text('#!/bin/sh\n[ ! -e broken ]\n')
    (tmp_path / "t.sh").chmod(0o755)
    (tmp_path / "ok.sh").write_text("#!/bin/sh\nexit 0\n")
    (tmp_path / "ok.sh").chmod(0o755)
    (tmp_path / "broken").write_text("")
    (tmp_path / "s.xml").write_text('<suite name="s"><test type="exec">t.sh</test>'
                                    '<test type="exec">ok.sh</test></suite>')
    temporary = tmp_path / "tmp"
    temporary.mkdir()
    env = runner_environment([], {"TMPDIR": str(temporary)}, True, tmp_path)
    out = open(tmp_path / "out.txt", "w")
    proc = subprocess.Popen([RUNNER, "--suite", "s.xml", "--watch"], cwd=tmp_path, env=env,
                            stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                            start_new_session=True)
    text = lambda: (tmp_path / "out.txt").read_text()
    try:
        assert wait_for(lambda: "waiting for a change" in text()), text()
        assert "1 passed, 1 failed" in text(), text()
        # s.xml, t.sh and ok.sh, each once (the suite given on the command line was counted
        # twice, "of 4 files", in the second first-hour trial).
        assert "waiting for a change of 3 files" in text(), text()
        assert len(os.listdir(temporary)) == 1  # the last run's report, for the failed first
        (tmp_path / "broken").unlink()
        save(tmp_path / "t.sh", '#!/bin/sh\n[ ! -e broken ]\n# edited\n')
        assert wait_for(lambda: text().count("waiting for a change") == 2), text()
        second = text().split("run 2", 1)[1]
        assert "t.sh changed" in text() and "failed last time first" in second, text()
        assert second.index("1 passed, 0 failed") < second.index("2 passed, 0 failed"), second
        save(tmp_path / "s.xml", '<suite name="s"><test type="exec">ok.sh</test></suite>')
        assert wait_for(lambda: text().count("waiting for a change") == 3), text()
        assert "s.xml changed" in text() and "1 passed, 0 failed" in text().split("run 3")[1]
        assert "waiting for a change of 2 files" in text().split("run 3")[1], text()
        os.killpg(proc.pid, signal.SIGINT)  # what Ctrl-C does: the terminal's whole group
        assert proc.wait(timeout=30) == 0, text()
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
        out.close()
    assert os.listdir(temporary) == []
    left = subprocess.run(["pgrep", "-g", str(proc.pid)], capture_output=True, text=True)
    assert left.stdout == "", left


def test_ctrl_c_during_a_run_stops_it_and_the_watch(tmp_path):
    (tmp_path / "slow.sh").write_text("#!/bin/sh\nsleep 30\n")
    (tmp_path / "slow.sh").chmod(0o755)
    (tmp_path / "s.xml").write_text('<suite name="s"><test type="exec">slow.sh</test></suite>')
    env = runner_environment([], None, True, tmp_path)
    proc = subprocess.Popen([RUNNER, "--suite", "s.xml", "--watch", "--no-output"],
                            cwd=tmp_path, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                            start_new_session=True, text=True)
    try:
        time.sleep(1.5)
        started = time.monotonic()
        os.killpg(proc.pid, signal.SIGINT)
        out, _ = proc.communicate(timeout=30)
        assert proc.returncode == 130, out
        assert time.monotonic() - started < 15, out
        assert "waiting for a change" not in out, out
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
    left = subprocess.run(["pgrep", "-g", str(proc.pid)], capture_output=True, text=True)
    assert left.stdout == "", left


def test_watch_with_list_lists_once(tmp_path):
    (tmp_path / "s.xml").write_text('<suite name="s"><test type="exec">t.sh</test></suite>')
    env = runner_environment([], None, True, tmp_path)
    run = subprocess.run([RUNNER, "--suite", "s.xml", "--watch", "--list"], cwd=tmp_path,
                         env=env, capture_output=True, text=True, timeout=30)
    assert run.returncode == 0 and "t.sh" in run.stdout, run
