#!/usr/bin/env python3
"""--history through the real runner: the time a run spends on its history, and the time of
the report with many runs stored (issue 22, "Measured").

    python3 bench/history_bench.py --build build

1. Append: a run of 10 000 trivial C++ tests in the runner's process (--isolation none), with
   --history and without; the difference is what the history costs the run (append the run in
   one transaction, read each test's last 30 runs back for the reports). Target: under 1 s.
   Also --history-import of one JUnit report of 10 000 tests (process start and parsing
   included).
2. Query: a history of 1 000 runs of --tests-per-run tests (default 1 000; loaded with
   --history-import from generated JUnit reports), then --history-report over the last 30 runs
   and over all 1 000 (process start included), and the time --history adds to a run of that
   many tests with those 1 000 runs stored. Target: under 200 ms.
Each figure is the best of --rounds runs. A benchmark, not a test: it prints, it asserts
nothing."""
import argparse
import os
import random
import subprocess
import sys
import tempfile
import time


def timed(args, cwd):
    start = time.perf_counter()
    done = subprocess.run(args, cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                          text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"{' '.join(args[:4])}... failed ({done.returncode}): {done.stderr}")
    return wall


def best(rounds, make_args, cwd, before=None):
    walls = []
    for _ in range(rounds):
        if before:
            before()
        walls.append(timed(make_args(), cwd))
    return min(walls)


def write_suite(folder, plugin, count):
    with open(os.path.join(folder, "many.xml"), "w") as f:
        f.write('<suite name="many">\n')
        f.writelines(f'  <test name="t{t}">{plugin}</test>\n' for t in range(count))
        f.write("</suite>\n")


def write_junit(path, tests, started, rng):
    """A foreign JUnit report of `tests` tests: mostly passing, some failing, times varying."""
    stamp = time.strftime("%Y-%m-%dT%H:%M:%S", time.gmtime(started))
    lines = [f'<testsuites><testsuite name="many" timestamp="{stamp}">']
    for t in range(tests):
        seconds = 0.01 * (1 + t % 7) * rng.uniform(0.8, 1.2)
        failure = '<failure message="x"/>' if rng.random() < 0.02 else ""
        lines.append(f'<testcase name="t{t}" time="{seconds:.4f}">{failure}</testcase>')
    lines.append("</testsuite></testsuites>")
    with open(path, "w") as f:
        f.write("\n".join(lines))


def verdict(value, target):
    return "met" if value < target else "NOT met"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the build tree")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--tests", type=int, default=10000, help="tests of the appended run")
    parser.add_argument("--runs", type=int, default=1000, help="runs stored for the query")
    parser.add_argument("--tests-per-run", type=int, default=1000)
    parser.add_argument("--workdir", default=None,
                        help="where its temporary folder goes (default: the system's)")
    args = parser.parse_args()
    runner = os.path.abspath(os.path.join(args.build, "bin", "robottestingframework-testrunner"))
    plugin = os.path.abspath(os.path.join(args.build, "bench", "rtf_bench_trivial_test.so"))
    for path in (runner, plugin):
        if not os.path.exists(path):
            sys.exit(f"{path} is missing: build the tree first")
    print(f"cores: {os.cpu_count()}, best of {args.rounds} rounds")
    rng = random.Random(22)
    with tempfile.TemporaryDirectory(prefix="rtf-history-bench-", dir=args.workdir) as folder:
        # 1. Append.
        write_suite(folder, plugin, args.tests)
        base = [runner, "--isolation", "none", "--no-output", "--no-summary", "--suite",
                "many.xml"]
        history = os.path.join(folder, "append.db")

        def fresh():
            for suffix in ("", "-wal", "-shm"):
                if os.path.exists(history + suffix):
                    os.remove(history + suffix)

        without = best(args.rounds, lambda: base, folder)
        with_history = best(args.rounds, lambda: base + ["--history", "append.db"], folder,
                            before=fresh)
        added = with_history - without
        print(f"\n1. a run of {args.tests} tests, in process")
        print(f"   without --history {without:8.3f} s")
        print(f"   with --history    {with_history:8.3f} s")
        print(f"   history's share   {added:8.3f} s   (target < 1 s: {verdict(added, 1.0)})")
        write_junit(os.path.join(folder, "one.xml"), args.tests, time.time(), rng)
        imported = best(args.rounds,
                        lambda: [runner, "--history", "import.db", "--history-import", "one.xml"],
                        folder,
                        before=lambda: [os.remove(os.path.join(folder, name))
                                        for name in ("import.db", "import.db-wal",
                                                     "import.db-shm")
                                        if os.path.exists(os.path.join(folder, name))])
        print(f"   --history-import of a {args.tests}-test JUnit report {imported:8.3f} s")

        # 2. Query.
        reports = os.path.join(folder, "reports")
        os.mkdir(reports)
        names = []
        now = time.time()
        for r in range(args.runs):
            name = os.path.join("reports", f"r{r:04d}.xml")
            write_junit(os.path.join(folder, name), args.tests_per_run,
                        now - 3600 * (args.runs - r), rng)
            names.append(name)
        start = time.perf_counter()
        for chunk in range(0, len(names), 200):  # a command line of a sane length
            timed([runner, "--history", "big.db", "--history-import", *names[chunk:chunk + 200]],
                  folder)
        loading = time.perf_counter() - start
        size = os.path.getsize(os.path.join(folder, "big.db"))
        print(f"\n2. {args.runs} runs of {args.tests_per_run} tests stored "
              f"({size / 1e6:.1f} MB; loaded in {loading:.1f} s, "
              f"{1000 * loading / args.runs:.1f} ms a run)")
        for window in (30, args.runs):
            report = best(args.rounds, lambda: [runner, "--history", "big.db",
                                                "--history-report", str(window)], folder)
            judged = (f"target < 200 ms: {verdict(report, 0.2)}" if window == 30
                      else "every run: no target")
            print(f"   --history-report {window:<5} {1000 * report:8.1f} ms   ({judged})")
        write_suite(folder, plugin, args.tests_per_run)
        small = [runner, "--isolation", "none", "--no-output", "--no-summary", "--suite",
                 "many.xml"]
        plain = best(args.rounds, lambda: small, folder)
        stored = best(args.rounds, lambda: small + ["--history", "big.db"], folder)
        print(f"   a run of {args.tests_per_run} tests: --history adds "
              f"{1000 * (stored - plain):8.1f} ms with {args.runs} runs stored "
              f"(append and read back; the runs it adds stay in the file)")


if __name__ == "__main__":
    main()
