#!/usr/bin/env python3
"""What measurements cost (issue 22, "Measured"): 10 000 trivial isolated tests each recording
3 measurements against the same run without, in runner time and peak memory, beside the
targets (within 10 % time, 20 % memory).

    python3 bench/measure_bench.py --build build [--count 10000] [--rounds 3]

Both runs are the real runner (--isolation process, the default) on one generated suite of the
C++ trivial test, console to a pipe, every output written (JUnit, CTRF, TAP, HTML: the
measurements go into each). Times and peaks are medians over --rounds runs after a warm-up,
measured by rtf-bench-measure (wall time, the runner's own ru_maxrss). A benchmark: it exits
non-zero only when a run failed, never on a figure."""
import argparse
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import perf_bench  # noqa: E402  (its measured runs and suite writer)

TIME_TARGET = 1.10
MEMORY_TARGET = 1.20


def median_run(runner, suite, rounds, folder):
    """Median seconds and peak KiB of the runner on `suite` with every output written."""
    argv = [runner, "--suite", suite, "-o", "junit:r.xml", "-o", "json:r.json",
            "-o", "tap:r.tap", "-o", "html:r.html"]
    try:
        return perf_bench.median_run(argv, rounds, folder)
    except perf_bench.Failed as e:
        sys.exit(f"measure_bench: {e}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the build tree (default: build)")
    parser.add_argument("--count", type=int, default=10000, help="tests per run")
    parser.add_argument("--rounds", type=int, default=3, help="runs per figure (median)")
    args = parser.parse_args()
    build = os.path.abspath(args.build)
    runner = os.path.join(build, "bin", "robottestingframework-testrunner")
    measure = os.path.join(build, "bin", "rtf-bench-measure")
    plain = os.path.join(build, "bench", "rtf_bench_trivial_test.so")
    measuring = os.path.join(build, "bench", "rtf_bench_measuring_test.so")
    for needed in (runner, measure, plain, measuring):
        if not os.path.exists(needed):
            sys.exit(f"measure_bench: {needed} is missing; build first (cmake --build {build})")
    perf_bench.MEASURE = measure
    with tempfile.TemporaryDirectory(prefix="rtf-measure-bench-") as folder:
        figures = {}
        for name, plugin in (("without", plain), ("with", measuring)):
            suite = perf_bench.write_cpp_suite(folder, plugin, name, args.count)
            figures[name] = median_run(runner, suite, args.rounds, folder)
    (t0, m0), (t1, m1) = figures["without"], figures["with"]
    print(f"{args.count} trivial isolated tests, every output written, median of {args.rounds}")
    print(f"{'':28}{'without':>10}{'with 3 each':>13}{'ratio':>8}{'target':>9}")
    print(f"{'runner time (s)':28}{t0:>10.2f}{t1:>13.2f}{t1 / t0:>8.2f}"
          f"{'<= ' + format(TIME_TARGET, '.2f'):>9}  {'met' if t1 / t0 <= TIME_TARGET else 'NOT met'}")
    print(f"{'runner peak memory (MiB)':28}{m0 / 1024:>10.1f}{m1 / 1024:>13.1f}{m1 / m0:>8.2f}"
          f"{'<= ' + format(MEMORY_TARGET, '.2f'):>9}  {'met' if m1 / m0 <= MEMORY_TARGET else 'NOT met'}")


if __name__ == "__main__":
    main()
