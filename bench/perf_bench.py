#!/usr/bin/env python3
"""Every performance figure of issue 23 in one run, each beside its reference and its target.

    python3 bench/perf_bench.py --build build        (or: ./run.sh bench)

Runs the real runner on generated suites of trivial tests (one check each, console to a pipe,
`--no-output`) and prints, one line per figure: our figure, the reference it is compared with,
the ratio, the target and whether it is met. The references are measured in the same run
(CTest on 1 000 `/bin/true`, pytest on 200 one-assertion files), except RTF 2.0.1's, which are
constants: RTF 2.0.1 is not built here (see RTF2_MEASURED). Times are medians over --rounds
runs (the machine is shared: a median is steadier than a best); peak memory is the runner's
ru_maxrss from wait4. The soak run (bench/soak_bench.py) comes last: --soak-count 0 leaves it
out. A benchmark: it exits non-zero only when a run failed, never on a figure."""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import soak_bench  # noqa: E402  (its suite writer and its measured run)
import network_bench  # noqa: E402  (private networks: bench/network_bench.py)
import ctest_world_bench  # noqa: E402  (worlds started under ctest)
import shared_world_bench  # noqa: E402  (8 suites sharing one world)

# RTF 2.0.1 (robotology/robot-testing-framework v2.0.1, built in Release), measured in 2026 on
# a 2-core machine of this project's kind, whole processes, median of 5-7 runs, the same trivial
# C++ suite, console to a pipe (issue 23).
RTF2_MEASURED = "2026 (issue 23)"
RTF2_ONE_TEST_S = 0.007
RTF2_10K_S, RTF2_10K_MIB = 0.058, 15.7
RTF2_20K_S, RTF2_20K_MIB = 0.231, 27.8
# The soak run's peak before issue 23 (docs/development/tests-and-benchmarks.md), and its allowed growth.
SOAK_PEAK_MIB = 41.0

TRIVIAL_PYTHON = """import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testCheck(True, "trivial")
"""
TRIVIAL_PYTEST = "def test_x():\n    assert 1 + 1 == 2\n"


MEASURE = None  # build/bin/rtf-bench-measure, set by main()


class Failed(Exception):
    pass


def spawn(argv, cwd, env=None):
    """(seconds, peak KiB) of one run of argv in cwd, through rtf-bench-measure (MEASURE): it
    times the run and reads the program's own peak memory, which a process forked from this
    one would start at Python's size."""
    proc = subprocess.run([MEASURE, *argv], cwd=cwd, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True, timeout=900)
    try:
        seconds, peak, code = proc.stdout.split()
    except ValueError:
        raise Failed(f"rtf-bench-measure {' '.join(argv[:4])}: {proc.stderr.strip()}")
    if code != "0":
        raise Failed(f"{' '.join(argv[:4])} ... exited {code}")
    return float(seconds), int(peak)


def median_run(argv, rounds, cwd, env=None):
    """Median seconds and median peak KiB over `rounds` runs, after one warm-up run."""
    spawn(argv, cwd, env)
    runs = [spawn(argv, cwd, env) for _ in range(rounds)]
    return (statistics.median(s for s, _ in runs), statistics.median(k for _, k in runs))


def write_cpp_suite(folder, plugin, name, count):
    path = os.path.join(folder, f"{name}.xml")
    with open(path, "w") as f:
        f.write(f'<suite name="{name}">\n')
        f.writelines(f'  <test type="dll">{plugin}</test>\n' for _ in range(count))
        f.write("</suite>\n")
    return path


def write_ctest_tree(folder, count):
    """A CTest tree of `count` tests, each /bin/true (what CTest does per test, at its least)."""
    tree = os.path.join(folder, f"ctest_{count}")
    os.makedirs(tree, exist_ok=True)
    with open(os.path.join(tree, "CTestTestfile.cmake"), "w") as f:
        f.writelines(f"add_test(true_{i} /bin/true)\n" for i in range(count))
    return tree


def write_python_suite(folder, count):
    tests = os.path.join(folder, f"python_{count}")
    os.makedirs(tests, exist_ok=True)
    lines = ['<suite name="python">']
    for i in range(count):
        with open(os.path.join(tests, f"check_{i}.py"), "w") as f:
            f.write(TRIVIAL_PYTHON)
        lines.append(f"  <test>check_{i}.py</test>")
    lines.append("</suite>")
    with open(os.path.join(tests, "suite.xml"), "w") as f:
        f.write("\n".join(lines) + "\n")
    return os.path.join(tests, "suite.xml")


def write_pytest_files(folder, count):
    tests = os.path.join(folder, f"pytest_{count}")
    os.makedirs(tests, exist_ok=True)
    for i in range(count):
        with open(os.path.join(tests, f"test_{i}.py"), "w") as f:
            f.write(TRIVIAL_PYTEST)
    return tests


def mib(kib):
    return kib / 1024.0


def fmt_time(seconds):
    return f"{seconds * 1e3:.1f} ms" if seconds < 1 else f"{seconds:.2f} s"


class Table:
    """One line per figure: ours, the reference, ratio, target, met or not."""

    def __init__(self, judged):
        self.missed = 0
        self.judged = judged  # --quick: the counts are not the targets', nothing is judged
        print(f"{'figure':<44} {'ours':>10} {'reference':>30} {'ratio':>7}  target")
        print("-" * 122)

    def line(self, figure, ours, reference, ratio, target, met):
        if not self.judged:
            target, met = "(--quick: not judged)", True
        if not met:
            self.missed += 1
        ratio_text = f"{ratio:.2f}x" if ratio is not None else ""
        print(f"{figure:<44} {ours:>10} {reference:>30} {ratio_text:>7}  {target}"
              f"{'' if met else '  MISSED'}", flush=True)

    def failed(self, figure, why):
        self.missed += 1
        print(f"{figure:<44} FAILED: {why}", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the build tree (default: build)")
    parser.add_argument("--rounds", type=int, default=5, help="runs per figure (median)")
    parser.add_argument("--soak-count", type=int, default=10000,
                        help="tests of the soak run per isolation mode (0: no soak run)")
    parser.add_argument("--workdir", help="where the generated files go (default: a new "
                        "temporary folder, removed afterwards)")
    parser.add_argument("--quick", action="store_true", help="a smoke run: one round, 1/100 of "
                        "the tests, no soak (CTest's bench.perf_smoke); its figures mean nothing")
    args = parser.parse_args()
    # Every count is divided by `scale` with --quick.
    scale = 100 if args.quick else 1
    if args.quick:
        args.rounds, args.soak_count = 1, 0
    build = os.path.abspath(args.build)
    runner = os.path.join(build, "bin", "robottestingframework-testrunner")
    plugin = os.path.join(build, "bench", "rtf_bench_trivial_test.so")
    global MEASURE
    MEASURE = os.path.join(build, "bin", "rtf-bench-measure")
    for needed in (runner, plugin, MEASURE):
        if not os.path.exists(needed):
            sys.exit(f"perf_bench: {needed} is missing; build first (cmake --build {args.build})")
    ctest = shutil.which("ctest")
    temporary = None
    if args.workdir:
        folder = os.path.abspath(args.workdir)
        os.makedirs(folder, exist_ok=True)
    else:
        temporary = tempfile.TemporaryDirectory(prefix="rtf-perf-")
        folder = temporary.name

    try:
        load = os.getloadavg()
        print(f"perf_bench: {runner}\nmedian of {args.rounds} runs after a warm-up; "
              f"{os.cpu_count()} cores, load average {load[0]:.1f} {load[1]:.1f} {load[2]:.1f}; "
              f"RTF 2.0.1's figures measured {RTF2_MEASURED}\n")
        table = Table(judged=not args.quick)
        rounds = args.rounds

        def ours(suites, isolation, extra=(), env=None, count_rounds=rounds):
            argv = [runner]
            for suite in suites:
                argv += ["--suite", suite]
            return median_run(argv + ["--isolation", isolation, "--no-output", *extra],
                              count_rounds, cwd=folder, env=env)

        one = write_cpp_suite(folder, plugin, "cpp_1", 1)
        # Start-up: the one-test runs are short; more rounds steady their median.
        seconds, one_peak = ours([one], "none", count_rounds=max(rounds, 11))
        table.line("1 test, in process (start-up)", fmt_time(seconds),
                   f"RTF 2.0.1 {fmt_time(RTF2_ONE_TEST_S)}", seconds / RTF2_ONE_TEST_S,
                   "<= 1.5x", seconds <= 1.5 * RTF2_ONE_TEST_S)
        seconds, _ = ours([one], "process", count_rounds=max(rounds, 11))
        table.line("1 test, isolated (the default)", fmt_time(seconds), "", None, "< 20 ms",
                   seconds < 0.020)

        for count, ref_s, ref_mib in ((10000 // scale, RTF2_10K_S, RTF2_10K_MIB),
                                      (20000 // scale, RTF2_20K_S, RTF2_20K_MIB)):
            suite = write_cpp_suite(folder, plugin, f"cpp_{count}", count)
            seconds, peak = ours([suite], "none")
            table.line(f"{count} tests, in process: time", fmt_time(seconds),
                       f"RTF 2.0.1 {fmt_time(ref_s)}", seconds / ref_s, "<= 1.00x",
                       seconds <= ref_s)
            per_test = (peak - one_peak) / (count - 1)  # KiB, the one-test run's peak aside
            table.line(f"{count} tests, in process: peak memory", f"{mib(peak):.1f} MiB",
                       f"RTF 2.0.1 {ref_mib:.1f} MiB", mib(peak) / ref_mib, "<= 1.00x",
                       mib(peak) <= ref_mib)
            table.line(f"{count} tests, in process: memory per test",
                       f"{per_test * 1024:.0f} B", "", None, "(stated)", True)

        isolated = 1000 // scale
        cpp_1000 = write_cpp_suite(folder, plugin, "cpp_isolated", isolated)
        quarters = [write_cpp_suite(folder, plugin, f"cpp_isolated_{i}", isolated // 4)
                    for i in range(4)]
        if ctest is None:
            table.failed(f"{isolated} tests, isolated", "ctest is not on PATH (the reference)")
        else:
            tree = write_ctest_tree(folder, isolated)
            for jobs, suites, target in (("1", [cpp_1000], 0.25), ("2", quarters, 0.15)):
                ref, _ = median_run([ctest, "--test-dir", tree, "-j", jobs, "-Q"], rounds, folder)
                seconds, _ = ours(suites, "process", extra=("-j", jobs))
                where = "one suite" if jobs == "1" else f"4 suites of {isolated // 4}"
                table.line(f"{isolated} tests, isolated, -j {jobs} ({where})", fmt_time(seconds),
                           f"CTest -j {jobs} /bin/true {fmt_time(ref)}", seconds / ref,
                           f"<= {target:.2f}x", seconds <= target * ref)

        files = 200 // scale
        python_suite = write_python_suite(folder, files)
        pytest_files = write_pytest_files(folder, files)
        python = shutil.which("python3") or sys.executable
        try:
            ref, _ = median_run([python, "-B", "-m", "pytest", "-q", "-p", "no:cacheprovider",
                                 pytest_files], rounds, cwd=folder)
        except Failed:
            ref = None
        seconds, _ = median_run([runner, "--suite", python_suite, "--no-output"], rounds,
                                cwd=os.path.dirname(python_suite))
        if ref is None:
            table.failed(f"{files} Python one-check files, isolated",
                         f"{fmt_time(seconds)}; pytest did not run (python3-pytest, "
                         "scripts/install-deps.sh)")
        else:
            table.line(f"{files} Python one-check files, isolated", fmt_time(seconds),
                       f"pytest, {files} files {fmt_time(ref)}", seconds / ref, "<= 0.50x",
                       seconds <= 0.5 * ref)

        network_bench.run(table, runner, folder, rounds, args.quick)

        if not args.quick:
            ctest_world_bench.report(runner, folder, lambda *f: table.line(*f[:3], None, *f[3:]))
        shared_world_bench.figures(table, runner, folder, rounds)

        if args.soak_count > 0:
            soak_folder = os.path.join(folder, "soak")
            os.makedirs(soak_folder, exist_ok=True)
            soak_suite = soak_bench.write_run(soak_folder, args.soak_count)
            for isolation in ("process", "none"):
                r = soak_bench.run_mode(runner, soak_folder, soak_suite, isolation)
                figure = f"soak {args.soak_count}, --isolation {isolation}"
                healthy = (r["status"] in (0, 1) and r["results"] == args.soak_count and
                           r["leftovers"] == 0)
                if not healthy:
                    table.failed(figure, f"exit {r['status']}, {r['results']} results, "
                                 f"{r['leftovers']} leftovers: {r['stderr'][-300:]}")
                    continue
                table.line(f"{figure}: peak", f"{r['peak_mib']:.1f} MiB",
                           f"before issue 23 {SOAK_PEAK_MIB:.0f} MiB",
                           r["peak_mib"] / SOAK_PEAK_MIB, "<= 1.10x (10 000 tests)",
                           args.soak_count != 10000 or r["peak_mib"] <= 1.1 * SOAK_PEAK_MIB)
                print(f"  {r['seconds']:.0f} s; results {r['results']}/{args.soak_count}, "
                      f"leftovers {r['leftovers']}, descriptors "
                      f"{r['fds_min']}/{r['fds_max']}/{r['fds_end']} (least/most/end)")
        load = os.getloadavg()
        print(f"\nload average at the end {load[0]:.1f} {load[1]:.1f} {load[2]:.1f}; "
              f"{table.missed} figure(s) missed their target")
        return 0
    except Failed as e:
        print(f"perf_bench: a run failed: {e}", file=sys.stderr)
        return 1
    finally:
        if temporary is not None:
            temporary.cleanup()


if __name__ == "__main__":
    sys.exit(main())
