"""Ctrl-C and SIGTERM while a world starts (a world that never says it is ready, awaited for
30 s): the start is cut short in the runner's own process (--isolation none) as in a worker,
the run ends within seconds with 130 or 143, its reports written and valid, every test
interrupted, the console saying what was interrupted, and no process left. In the runner's
own process it waited for the world's whole ready timeout. Loopback only."""
import signal
import time
import xml.etree.ElementTree as ET

import pytest

from conftest import (finish_runner, junit_state, leftover_processes, marked, start_runner,
                      validate_junit, wait_for)


@pytest.mark.parametrize("isolation", ["none", "process"])
@pytest.mark.parametrize("scope", ["run", "suite"])
@pytest.mark.parametrize("signum, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_a_signal_while_a_world_starts_cuts_the_start_short(tmp_path, marker, isolation, scope,
                                                            signum, status):
    (tmp_path / "never.xml").write_text("""<world name="never" logdir="logs">
  <process name="never" command="sh -c 'echo up > started.txt; exec sleep 60'">
    <ready timeout="30s"><output>ready</output></ready>
  </process>
</world>
""")
    shared = ' scope="run"' if scope == "run" else ""
    args = []
    for suite in ("arm", "base"):
        (tmp_path / f"{suite}.xml").write_text(f"""<suite name="{suite}">
  <fixture type="process"{shared}>never.xml</fixture>
  <test type="exec">/bin/true</test>
</suite>
""")
        args += ["-s", f"{suite}.xml"]
    proc = start_runner(*args, "-j", "2", "--isolation", isolation, "-o", "junit:report.xml",
                        "-o", "text:report.txt", cwd=tmp_path, env=marked(marker))
    wait_for(lambda: (tmp_path / "started.txt").exists(), what="the world's start")
    time.sleep(0.3)
    proc.send_signal(signum)
    began = time.monotonic()
    code, out, err = finish_runner(proc, timeout=20)
    output = out + err
    assert time.monotonic() - began < 10, output
    assert code == status, output
    # What was interrupted: the world's start (in a worker, the worker's set-up call).
    said = ("interrupted after", "while starting (not ready: 'never')") \
        if isolation == "none" else ("fixture never", "setup interrupted")
    assert all(words in output for words in said), output
    if scope == "run" and isolation == "process":
        # The suite that waited for the world (-j 2) says what it waited for.
        assert "failed: interrupted while shared world 'never' was starting" in output, output
    validate_junit(tmp_path / "report.xml")
    states = [junit_state(case)
              for case in ET.parse(tmp_path / "report.xml").getroot().iter("testcase")
              if case.get("name") == "true"]
    assert states == ["interrupted", "interrupted"], output
    assert "INTERRUPTED" in (tmp_path / "report.txt").read_text()
    assert not leftover_processes(marker)
