#!/usr/bin/env python3
"""8 suites sharing one world (<fixture type="process" scope="run">) through the real runner.

    python3 bench/shared_world_bench.py --build build      (also part of bench/perf_bench.py)

The world becomes ready 1 s after its start and counts its starts in a file; each suite has 2
short tests (/bin/true). The run is -j 4 --network private (the issue's 8 suites; without
--network private where no private network can be had). Figures: the world's starts (target:
1) and the whole run against 1 s + the tests' time, the tests' time being the same 8 suites
without their world, same options (target: <= 1.2x). Median of --rounds runs. A benchmark,
not a test."""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time

SUITES = 8
READY_AFTER_S = 1.0


def write(folder, with_world):
    with open(os.path.join(folder, "lab.xml"), "w") as f:
        f.write(f"""<world name="lab" logdir="logs">
  <process name="lab" command="sh -c 'echo start >> starts.txt; sleep {READY_AFTER_S}; echo ready; exec sleep 600'">
    <ready timeout="30s"><output>ready</output></ready>
  </process>
</world>
""")
    args = []
    for s in range(SUITES):
        name = f"{'shared' if with_world else 'bare'}{s}.xml"
        world = '  <fixture type="process" scope="run">lab.xml</fixture>\n' if with_world else ""
        with open(os.path.join(folder, name), "w") as f:
            f.write(f'<suite name="suite{s}">\n{world}'
                    '  <test type="exec">/bin/true</test>\n'
                    '  <test type="exec">/bin/true</test>\n</suite>\n')
        args += ["-s", name]
    return args


def timed(runner, folder, args):
    start = time.perf_counter()
    done = subprocess.run([runner, *args, "--no-output", "--no-summary"], cwd=folder,
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          timeout=300)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        raise RuntimeError(f"the runner failed ({done.returncode}): {done.stderr[-400:]}")
    return seconds


def measure(runner, folder, rounds):
    """{'starts': starts per run, 'run': seconds, 'tests': seconds, 'options': [...]}"""
    shared = write(folder, True)
    bare = write(folder, False)
    options = ["-j", "4", "--network", "private"]
    try:
        timed(runner, folder, bare + options)
    except RuntimeError:
        options = ["-j", "4"]  # no private network on this machine
    starts = os.path.join(folder, "starts.txt")
    runs, tests, counts = [], [], []
    timed(runner, folder, shared + options)  # warm-up
    for _ in range(rounds):
        if os.path.exists(starts):
            os.remove(starts)
        runs.append(timed(runner, folder, shared + options))
        with open(starts) as f:
            counts.append(len(f.read().split()))
        tests.append(timed(runner, folder, bare + options))
    return {"starts": max(counts), "run": statistics.median(runs),
            "tests": statistics.median(tests), "options": options}


def figures(table, runner, folder, rounds):
    """The two figures in perf_bench's table."""
    where = os.path.join(folder, "shared_world")
    os.makedirs(where, exist_ok=True)
    try:
        m = measure(runner, where, rounds)
    except (RuntimeError, subprocess.TimeoutExpired) as e:
        table.failed("8 suites sharing one world", str(e))
        return
    label = f"8 suites sharing one world, {' '.join(m['options'])}"
    table.line(f"{label}: world starts", str(m["starts"]), "", None, "1", m["starts"] == 1)
    ideal = READY_AFTER_S + m["tests"]
    table.line(f"{label}: time", f"{m['run']:.2f} s", f"1 s + tests {ideal:.2f} s",
               m["run"] / ideal, "<= 1.20x", m["run"] <= 1.2 * ideal)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the build tree (default: build)")
    parser.add_argument("--rounds", type=int, default=5, help="runs per figure (median)")
    args = parser.parse_args()
    runner = os.path.join(os.path.abspath(args.build), "bin", "robottestingframework-testrunner")
    with tempfile.TemporaryDirectory(prefix="rtf-shared-world-") as folder:
        m = measure(runner, folder, args.rounds)
    ideal = READY_AFTER_S + m["tests"]
    print(f"8 suites sharing one world ({' '.join(m['options'])}), median of {args.rounds}:")
    print(f"  world starts per run  {m['starts']}  (target 1)")
    print(f"  whole run             {m['run']:.2f} s  vs 1 s + tests' time {ideal:.2f} s = "
          f"{m['run'] / ideal:.2f}x  (target <= 1.20x)")
    print(f"  tests alone           {m['tests']:.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
