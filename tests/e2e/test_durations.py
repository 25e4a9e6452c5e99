"""--durations N as pytest has it (issue 38, item 8): the N slowest tests after the run (0: all);
the shard-balancing and ETA input is --durations-from REPORT (a value of --durations that is
not a number still is that REPORT), and a report that only feeds the ETA is no warning. Run
from the suite's folder with relative paths."""
import json
import re

from conftest import run_runner

SUITE = """<suite name="timed">
  <test type="exec">fast.sh</test>
  <test type="exec">slow.sh</test>
  <test type="exec">bad.sh</test>
  <test type="exec">mid.sh</test>
</suite>
"""


def make_suite(folder):
    for name, body in (("fast", "exit 0"), ("slow", "sleep 0.6"), ("bad", "exit 1"),
                       ("mid", "sleep 0.3")):
        script = folder / f"{name}.sh"
        script.write_text(f"#!/bin/sh\n{body}\n")
        script.chmod(0o755)
    (folder / "timed.xml").write_text(SUITE)


def slowest_lines(text):
    """(seconds, state, id) of each line of the --durations table."""
    return [(float(m.group(1)), m.group(2), m.group(3)) for m in
            re.finditer(r"^ +(\d+\.\d{3}) s  (\S+) +(\S+)$", text, re.M)]


def test_durations_n_prints_the_n_slowest_tests_slowest_first(tmp_path):
    make_suite(tmp_path)
    run = run_runner("--suite", "timed.xml", "--durations", "2", "--no-output", cwd=tmp_path)
    assert run.returncode == 1, run
    assert "slowest 2 of 4 tests:\n" in run.stdout, run
    lines = slowest_lines(run.stdout)
    assert [(state, test) for _, state, test in lines] == [
        ("passed", "timed/slow.sh"), ("passed", "timed/mid.sh")], run.stdout
    assert lines[0][0] >= 0.6 and lines[1][0] >= 0.3, lines
    # Not a report to read: no "cannot read the report; no ETA".
    assert "cannot read" not in run.stderr and "ETA" not in run.stderr, run

    every = run_runner("--suite", "timed.xml", "--durations=0", "--no-output", cwd=tmp_path)
    assert "the 4 tests, slowest first:\n" in every.stdout, every
    lines = slowest_lines(every.stdout)
    assert [test for _, _, test in lines][:2] == ["timed/slow.sh", "timed/mid.sh"], lines
    assert ("FAILED", "timed/bad.sh") in [(state, test) for _, state, test in lines], lines


def test_the_table_goes_with_the_console_when_a_report_takes_the_standard_output(tmp_path):
    make_suite(tmp_path)
    run = run_runner("--suite", "timed.xml", "--durations", "1", "-o", "json:-", cwd=tmp_path)
    assert run.returncode == 1, run
    assert json.loads(run.stdout)["results"]["summary"]["tests"] == 4, run
    assert "slowest 1 of 4 tests:" in run.stderr, run


def test_durations_from_a_report_gives_no_warning_without_shards(tmp_path):
    make_suite(tmp_path)
    first = run_runner("--suite", "timed.xml", "-o", "json:r.json", cwd=tmp_path)
    assert first.returncode == 1, first
    for option in ("--durations-from", "--durations"):  # the second: the earlier form
        run = run_runner("--suite", "timed.xml", option, "r.json", "--no-output", cwd=tmp_path)
        assert run.returncode == 1, run
        assert "warning" not in run.stderr, (option, run)
        assert "slowest" not in run.stdout, (option, run)
    shard = run_runner("--suite", "timed.xml", "--durations-from", "r.json", "--shard-index", "0",
                       "--shard-count", "1", "--no-output", cwd=tmp_path)
    assert "balanced by r.json" in shard.stdout, shard
    both = run_runner("--suite", "timed.xml", "--durations", "r.json", "--durations-from",
                      "r.json", cwd=tmp_path)
    assert both.returncode == 2 and "one REPORT at most" in both.stderr, both
