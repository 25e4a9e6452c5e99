#!/usr/bin/env python3
"""Suites at once (-j N) through the real runner: wall time and scheduler overhead.

    python3 bench/scheduler_bench.py --build build

1. 16 suites, each with a fixture that waits 0.5 s in its set-up and 10 trivial C++ tests: the
   wall time with -j1, -j2 and -j4 and its ratio to the ideal (the -j1 time divided by N).
2. 10 000 trivial isolated C++ tests in 40 suites of 250: the time per test with -j1 and -j4,
   as wall time and as CPU time (runner and workers, from getrusage of the children), and
   -j4's CPU time per test against -j1's (the scheduler's overhead; target: within 10 %).
Each figure is the best of --rounds runs. A benchmark, not a test: it prints, it asserts
nothing."""
import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time

FIXTURE = """import time


class FixtureManager:
    def setup(self, param):
        time.sleep(0.5)
        return True

    def tearDown(self):
        pass
"""


def write_suites(folder, plugin, suites, tests, fixture):
    paths = []
    for s in range(suites):
        lines = [f'<suite name="suite{s}">']
        if fixture:
            lines.append(f'  <fixture type="python">{fixture}</fixture>')
        lines += [f'  <test name="t{t}">{plugin}</test>' for t in range(tests)]
        lines.append("</suite>")
        path = os.path.join(folder, f"suite{s}.xml")
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        paths.append(path)
    return paths


def run(runner, suites, jobs):
    """(wall seconds, CPU seconds of the runner and everything it waited for)."""
    args = [runner, "--no-output", "--no-summary", "-j", str(jobs)]
    for path in suites:
        args += ["--suite", path]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        sys.exit(f"the runner failed ({done.returncode}): {done.stderr}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu


def best(runner, suites, jobs, rounds):
    runs = [run(runner, suites, jobs) for _ in range(rounds)]
    return min(r[0] for r in runs), min(r[1] for r in runs)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the build tree")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--tests", type=int, default=10000, help="tests of part 2")
    parser.add_argument("--workdir", default=None,
                        help="where its temporary folder goes (default: the system's)")
    args = parser.parse_args()
    runner = os.path.join(args.build, "bin", "robottestingframework-testrunner")
    plugin = os.path.join(args.build, "bench", "rtf_bench_trivial_test.so")
    for path in (runner, plugin):
        if not os.path.exists(path):
            sys.exit(f"{path} is missing: build the tree first")
    print(f"cores: {os.cpu_count()}, best of {args.rounds} rounds")
    with tempfile.TemporaryDirectory(prefix="rtf-sched-bench-", dir=args.workdir) as folder:
        fixture = os.path.join(folder, "wait_fixture.py")
        with open(fixture, "w") as f:
            f.write(FIXTURE)
        suites = write_suites(folder, plugin, 16, 10, fixture)
        print("\n16 suites x (0.5 s fixture + 10 trivial tests)")
        print(f"{'jobs':>5} {'wall s':>8} {'ideal s':>8} {'ideal/wall':>10}")
        one = None
        for jobs in (1, 2, 4):
            wall, _ = best(runner, suites, jobs, args.rounds)
            one = wall if one is None else one
            ideal = one / jobs
            print(f"{jobs:>5} {wall:>8.2f} {ideal:>8.2f} {ideal / wall:>10.2f}")

        many = os.path.join(folder, "many")
        os.mkdir(many)
        per_suite = args.tests // 40
        suites = write_suites(many, plugin, 40, per_suite, None)
        count = per_suite * 40
        print(f"\n{count} trivial isolated tests in 40 suites")
        print(f"{'jobs':>5} {'wall ms/test':>12} {'cpu ms/test':>12}")
        figures = {}
        for jobs in (1, 4):
            wall, cpu = best(runner, suites, jobs, args.rounds)
            figures[jobs] = cpu / count
            print(f"{jobs:>5} {1000 * wall / count:>12.3f} {1000 * cpu / count:>12.3f}")
        ratio = figures[4] / figures[1]
        print(f"\ncpu per test, -j4 / -j1: {ratio:.3f} (target <= 1.10: "
              f"{'met' if ratio <= 1.10 else 'NOT met'})")


if __name__ == "__main__":
    main()
