#!/usr/bin/env python3
"""Every performance figure of issues 23 and 37 in one run, each beside its reference and target.

    python3 bench/perf_bench.py --build build        (or: ./run.sh bench)

Runs the real runner on generated suites of trivial tests (one check each, console to a pipe,
`--no-output`) and prints, one line per figure: our figure, the reference it is compared with,
the ratio, the target and whether it is met. Every reference is measured in the same run, on
the same machine: RTF 2.0.1's own runner (Debian 12's binary packages, unpacked into the build
tree by scripts/rtf2-binaries.sh, run with LD_LIBRARY_PATH into it, on the same trivial test
built against its headers), CTest on 1 000 `/bin/true`, a bare fork+_exit+waitpid
(rtf-bench-fork), pytest and `pytest --forked` on 200 one-assertion files (pytest-forked in a
venv of the build tree, scripts/bench-tools.sh). Ours and its reference run in turns (ours,
theirs, ours, ...), so that a machine shared with others loads both alike; times are medians
over --rounds runs (a median is steadier than a best); CPU time (user + system) is stated
beside the wall time, the steadier figure on a loaded machine; peak memory is the runner's
ru_maxrss from wait4. The soak run (bench/soak_bench.py) comes last: --soak-count 0 leaves it
out. A benchmark: it exits non-zero only when a run failed, never on a figure. --quick never
downloads: without RTF 2.0.1's packages or pytest-forked in the build tree, it says so and
leaves their figures out."""
import argparse
import glob
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

# What --part can select, in the order they run.
PARTS = ("start-up", "in-process", "isolated", "python", "network", "worlds", "soak")
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
# The soak run's peak before issue 23 (docs/development/tests-and-benchmarks.md), and its allowed growth.
SOAK_PEAK_MIB = 41.0

TRIVIAL_PYTHON = """import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testCheck(True, "trivial")
"""
TRIVIAL_PYTEST = "def test_x():\n    assert 1 + 1 == 2\n"

# The floor of a process per Python file: one interpreter (the python3 pytest runs on, nothing
# of pytest imported) forks a child per file, one at a time, which compiles and runs the file
# (TRIVIAL_PYTHON, its module a stand-in) and exits; the parent waits for it. What is left
# besides is the runner's own work: reading the suite, the events, the report.
PYTHON_FORK_FLOOR = """import os, sys, types
sys.dont_write_bytecode = True
module = types.ModuleType("robottestingframework")
module.testCheck = lambda condition, message: None
sys.modules["robottestingframework"] = module
folder = sys.argv[1]
for name in sorted(os.listdir(folder)):
    if not name.endswith(".py"):
        continue
    pid = os.fork()
    if pid == 0:
        with open(os.path.join(folder, name), "rb") as f:
            scope = {"__name__": name[:-3]}
            exec(compile(f.read(), name, "exec"), scope)
        scope["TestCase"]().run()
        os._exit(0)
    _, status = os.waitpid(pid, 0)
    if status != 0:
        sys.exit(1)
"""


MEASURE = None  # build/bin/rtf-bench-measure, set by main()


class Failed(Exception):
    pass


class Run:
    """One figure's medians: wall seconds, peak KiB, CPU seconds (user + system)."""

    def __init__(self, runs):
        self.seconds = statistics.median(r[0] for r in runs)
        self.peak = statistics.median(r[1] for r in runs)
        self.cpu = statistics.median(r[2] for r in runs)


def spawn(argv, cwd, env=None):
    """(seconds, peak KiB, CPU seconds) of one run of argv in cwd, through rtf-bench-measure
    (MEASURE): it times the run and reads the program's own peak memory, which a process
    forked from this one would start at Python's size."""
    proc = subprocess.run([MEASURE, *argv], cwd=cwd, env=env, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True, timeout=900)
    try:
        seconds, peak, code, cpu = proc.stdout.split()
    except ValueError:
        raise Failed(f"rtf-bench-measure {' '.join(argv[:4])}: {proc.stderr.strip()}")
    if code != "0":
        raise Failed(f"{' '.join(argv[:4])} ... exited {code}")
    return float(seconds), int(peak), float(cpu)


def median_run(argv, rounds, cwd, env=None):
    """The medians (Run) over `rounds` runs, after one warm-up run."""
    spawn(argv, cwd, env)
    return Run([spawn(argv, cwd, env) for _ in range(rounds)])


def paired_runs(ours, theirs, rounds):
    """Medians (Run, Run) of two commands run in turns, after a warm-up of each: `ours` and
    `theirs` are (argv, cwd, env). In turns, a machine shared with others loads both alike."""
    spawn(*ours)
    spawn(*theirs)
    a, b = [], []
    for _ in range(rounds):
        a.append(spawn(*ours))
        b.append(spawn(*theirs))
    return Run(a), Run(b)


def worker_libraries(worker):
    """The shared libraries the worker program maps (ldd), the dynamic loader aside; [] when
    ldd cannot say."""
    try:
        out = subprocess.run(["ldd", worker], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                             text=True, timeout=60).stdout
    except (OSError, subprocess.SubprocessError):
        return []
    return [line.split("=>")[1].split("(")[0].strip() for line in out.splitlines()
            if "=>" in line and "/" in line.split("=>")[1]]


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
    if seconds < 1e-3:
        return f"{seconds * 1e6:.0f} us"
    return f"{seconds * 1e3:.1f} ms" if seconds < 1 else f"{seconds:.2f} s"


class Rtf2:
    """RTF 2.0.1's runner from Debian 12's binary packages (scripts/rtf2-binaries.sh), unpacked
    into BUILD/rtf2-binary/root, and the bench's trivial test built against its headers."""

    def __init__(self, build, quick):
        self.runner = self.plugin = self.env = None
        self.why = ""
        root = os.path.join(build, "rtf2-binary", "root")
        runner = os.path.join(root, "usr", "bin", "robottestingframework-testrunner")
        if not os.path.exists(runner):
            if quick:
                self.why = (f"--quick: RTF 2.0.1's packages are not unpacked in {root} "
                            "(scripts/rtf2-binaries.sh BUILD, or ./run.sh bench once)")
                return
            fetch = subprocess.run(["bash", os.path.join(ROOT, "scripts", "rtf2-binaries.sh"),
                                    build], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                   text=True, timeout=900)
            if fetch.returncode != 0 or not os.path.exists(runner):
                self.why = "scripts/rtf2-binaries.sh failed: " + fetch.stdout.strip()[-300:]
                return
        headers = glob.glob(os.path.join(root, "usr", "include", "*", "robottestingframework"))
        libs = glob.glob(os.path.join(root, "usr", "lib", "*", "librobottestingframework.so.2"))
        if not headers or not libs:
            self.why = f"RTF 2.0.1's headers or library are missing from {root}"
            return
        lib = os.path.dirname(libs[0])
        # The bench's trivial test, built as an RTF 2.0.1 user builds it (optimised).
        source = os.path.join(HERE, "trivial_test.cpp")
        plugin = os.path.join(build, "bench", "rtf2", "rtf2_trivial_test.so")
        if (not os.path.exists(plugin) or
                os.path.getmtime(plugin) < os.path.getmtime(source)):
            os.makedirs(os.path.dirname(plugin), exist_ok=True)
            compiler = os.environ.get("CXX") or shutil.which("c++") or "g++"
            built = subprocess.run([compiler, "-O2", "-shared", "-fPIC", "-o", plugin, source,
                                    f"-I{os.path.dirname(headers[0])}", f"-L{lib}",
                                    "-lrobottestingframework", "-lrobottestingframework-dll"],
                                   stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                   timeout=300)
            if built.returncode != 0:
                self.why = "building the trivial test against RTF 2.0.1 failed: " + built.stdout
                return
        self.runner, self.plugin = runner, plugin
        self.env = dict(os.environ, LD_LIBRARY_PATH=lib)


def bench_tools(build, quick):
    """BUILD/bench-tools/bin/python with pytest-forked (scripts/bench-tools.sh), or (None, why)."""
    python = os.path.join(build, "bench-tools", "bin", "python")
    stamp = os.path.join(build, "bench-tools", "installed")
    if not os.path.exists(stamp):
        if quick:
            return None, (f"--quick: pytest-forked is not installed in {build}/bench-tools "
                          "(scripts/bench-tools.sh BUILD, or ./run.sh bench once)")
        made = subprocess.run(["bash", os.path.join(ROOT, "scripts", "bench-tools.sh"), build],
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                              timeout=900)
        if made.returncode != 0:
            return None, "scripts/bench-tools.sh failed: " + made.stdout.strip()[-300:]
    return python, ""


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

    def skipped(self, figure, why):
        """A figure left out on purpose (--quick without a reference): said, not counted."""
        print(f"{figure:<44} not measured: {why}", flush=True)

    def cpu(self, figure, ours, theirs, name):
        """The CPU time (user + system) of a pair of runs: stated, not judged."""
        self.line(f"{figure}: CPU", fmt_time(ours.cpu), f"{name} {fmt_time(theirs.cpu)}",
                  ours.cpu / theirs.cpu if theirs.cpu > 0 else None, "(stated)", True)


def python_figures(table, runner, folder, files, forked_python, forked_why, rounds, quick):
    """`files` one-check Python files isolated, against pytest and `pytest --forked`."""
    python_suite = write_python_suite(folder, files)
    pytest_files = write_pytest_files(folder, files)
    python = shutil.which("python3") or sys.executable
    ours_python = ([runner, "--suite", python_suite, "--no-output"],
                   os.path.dirname(python_suite), None)
    figure = f"{files} Python one-check files, isolated"
    pytest_argv = ["-B", "-m", "pytest", "-q", "-p", "no:cacheprovider", pytest_files]
    try:
        mine, ref = paired_runs(ours_python, ([python, *pytest_argv], folder, None), rounds)
    except Failed as e:
        table.failed(figure, f"pytest did not run (python3-pytest, scripts/install-deps.sh):"
                     f" {e}")
    else:
        table.line(figure, fmt_time(mine.seconds), f"pytest, {files} files "
                   f"{fmt_time(ref.seconds)}", mine.seconds / ref.seconds, "<= 0.50x",
                   mine.seconds <= 0.5 * ref.seconds)
        table.cpu(figure, mine, ref, "pytest")
        # The floor of any runner that gives each file a process of its own (PYTHON_FORK_FLOOR),
        # against the same pytest, in turns: stated, not judged.
        floor_script = os.path.join(folder, "python_fork_floor.py")
        with open(floor_script, "w") as f:
            f.write(PYTHON_FORK_FLOOR)
        floor_figure = f"{files} Python files: bare fork per file"
        try:
            floor, ref = paired_runs(([python, "-B", floor_script, os.path.dirname(python_suite)],
                                      folder, None),
                                     ([python, *pytest_argv], folder, None), rounds)
        except Failed as e:
            table.failed(floor_figure, f"the bare fork loop did not run: {e}")
        else:
            table.line(floor_figure, fmt_time(floor.seconds),
                       f"pytest, {files} files {fmt_time(ref.seconds)}",
                       floor.seconds / ref.seconds, "(stated: python3 forks, runs, waits)", True)
            table.cpu(floor_figure, floor, ref, "pytest")
    figure = f"{files} Python files, isolated vs --forked"
    if forked_python is None:
        (table.skipped if quick else table.failed)(figure, forked_why)
    else:
        try:
            mine, ref = paired_runs(ours_python, ([forked_python, *pytest_argv, "--forked"],
                                                  folder, None), rounds)
        except Failed as e:
            table.failed(figure, f"pytest --forked did not run: {e}")
        else:
            table.line(figure, fmt_time(mine.seconds),
                       f"pytest --forked {fmt_time(ref.seconds)}", mine.seconds / ref.seconds,
                       "<= 0.20x", mine.seconds <= 0.2 * ref.seconds)


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
    parser.add_argument("--part", action="append", choices=PARTS, help="measure only this part "
                        "(repeatable; default: all of them): " + ", ".join(PARTS))
    args = parser.parse_args()
    parts = set(args.part or PARTS)
    # Every count is divided by `scale` with --quick.
    scale = 100 if args.quick else 1
    if args.quick:
        args.rounds, args.soak_count = 1, 0
    build = os.path.abspath(args.build)
    runner = os.path.join(build, "bin", "robottestingframework-testrunner")
    plugin = os.path.join(build, "bench", "rtf_bench_trivial_test.so")
    global MEASURE
    MEASURE = os.path.join(build, "bin", "rtf-bench-measure")
    fork_cost = os.path.join(build, "bin", "rtf-bench-fork")
    for needed in (runner, plugin, MEASURE, fork_cost):
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
        rtf2 = Rtf2(build, args.quick)
        forked_python, forked_why = bench_tools(build, args.quick)
        load = os.getloadavg()
        print(f"perf_bench: {runner}\nRTF 2.0.1: "
              f"{rtf2.runner + ' (Debian 12 binary packages)' if rtf2.runner else rtf2.why}\n"
              f"median of {args.rounds} runs after a warm-up, ours and the reference in turns; "
              f"{os.cpu_count()} cores, load average {load[0]:.1f} {load[1]:.1f} {load[2]:.1f}\n")
        table = Table(judged=not args.quick)
        rounds = args.rounds

        def ours_argv(suites, isolation, extra=()):
            argv = [runner]
            for suite in suites:
                argv += ["--suite", suite]
            return argv + ["--isolation", isolation, "--no-output", *extra]

        def ours(suites, isolation, extra=(), count_rounds=rounds):
            return median_run(ours_argv(suites, isolation, extra), count_rounds, cwd=folder)

        def against_rtf2(count, count_rounds):
            """(ours, RTF 2.0.1's) Run of `count` trivial tests in process, in turns."""
            suite = write_cpp_suite(folder, plugin, f"cpp_{count}", count)
            theirs = write_cpp_suite(folder, rtf2.plugin, f"rtf2_cpp_{count}", count)
            return paired_runs((ours_argv([suite], "none"), folder, None),
                               ([rtf2.runner, "--suite", theirs, "--no-output"], folder,
                                rtf2.env), count_rounds)

        one = write_cpp_suite(folder, plugin, "cpp_1", 1)
        # Start-up: the one-test runs are short; more rounds steady their median.
        start_rounds = max(rounds, 21)
        figure = "1 test, in process (start-up)"
        one_peak = None
        if "start-up" not in parts:
            pass
        elif rtf2.runner:
            mine, theirs = against_rtf2(1, start_rounds)
            table.line(figure, fmt_time(mine.seconds), f"RTF 2.0.1 {fmt_time(theirs.seconds)}",
                       mine.seconds / theirs.seconds, "<= 1.5x",
                       mine.seconds <= 1.5 * theirs.seconds)
            table.cpu(figure, mine, theirs, "RTF 2.0.1")
        else:
            mine = ours([one], "none", count_rounds=start_rounds)
            table.skipped(figure, f"ours {fmt_time(mine.seconds)}; {rtf2.why}")
        if "start-up" in parts:
            one_peak = mine.peak
        isolated_one = None
        if parts & {"start-up", "isolated"}:
            isolated_one = ours([one], "process", count_rounds=start_rounds)
            table.line("1 test, isolated (the default)", fmt_time(isolated_one.seconds), "",
                       None, "< 20 ms", isolated_one.seconds < 0.020)

        for count in (10000 // scale, 20000 // scale) if "in-process" in parts else ():
            if rtf2.runner:
                mine, theirs = against_rtf2(count, rounds)
                table.line(f"{count} tests, in process: time", fmt_time(mine.seconds),
                           f"RTF 2.0.1 {fmt_time(theirs.seconds)}",
                           mine.seconds / theirs.seconds, "<= 1.00x",
                           mine.seconds <= theirs.seconds)
                table.cpu(f"{count} tests, in process", mine, theirs, "RTF 2.0.1")
                table.line(f"{count} tests, in process: peak memory", f"{mib(mine.peak):.1f} MiB",
                           f"RTF 2.0.1 {mib(theirs.peak):.1f} MiB", mine.peak / theirs.peak,
                           "<= 1.00x", mine.peak <= theirs.peak)
            else:
                mine = ours([write_cpp_suite(folder, plugin, f"cpp_{count}", count)], "none")
                table.skipped(f"{count} tests, in process", f"ours {fmt_time(mine.seconds)}, "
                              f"{mib(mine.peak):.1f} MiB; {rtf2.why}")
            if one_peak is None:
                one_peak = ours([one], "none", count_rounds=start_rounds).peak
            per_test = (mine.peak - one_peak) / (count - 1)  # KiB, the one-test run's peak aside
            table.line(f"{count} tests, in process: memory per test",
                       f"{per_test * 1024:.0f} B", "", None, "(stated)", True)

        isolated = 1000 // scale
        cpp_1000 = write_cpp_suite(folder, plugin, "cpp_isolated", isolated)
        quarters = [write_cpp_suite(folder, plugin, f"cpp_isolated_{i}", isolated // 4)
                    for i in range(4)]
        if "isolated" not in parts:
            pass
        elif ctest is None:
            table.failed(f"{isolated} tests, isolated", "ctest is not on PATH (the reference)")
        else:
            tree = write_ctest_tree(folder, isolated)
            # Issue 37: 1 000 isolated tests <= 0.30x CTest's time on 1 000 /bin/true, with -j 1
            # as with -j 2; with -j 2 the cost per test is judged against a bare fork+exit+wait
            # (the line after).
            for jobs, suites, target in (("1", [cpp_1000], 0.30), ("2", quarters, 0.30)):
                mine, ref = paired_runs(
                    (ours_argv(suites, "process", ("-j", jobs)), folder, None),
                    ([ctest, "--test-dir", tree, "-j", jobs, "-Q"], folder, None), rounds)
                where = "one suite" if jobs == "1" else f"4 suites of {isolated // 4}"
                table.line(f"{isolated} tests, isolated, -j {jobs} ({where})",
                           fmt_time(mine.seconds),
                           f"CTest -j {jobs} /bin/true {fmt_time(ref.seconds)}",
                           mine.seconds / ref.seconds, f"<= {target:.2f}x",
                           mine.seconds <= target * ref.seconds)
                if jobs == "2":
                    # Per test, the one-test isolated run (start-up) aside, against a bare
                    # fork+_exit+waitpid two at a time, measured now (rtf-bench-fork).
                    forks = [spawn([fork_cost, str(isolated), "2"], folder)
                             for _ in range(rounds)]
                    bare = Run(forks)
                    per_test = (mine.seconds - isolated_one.seconds) / isolated
                    table.line(f"{isolated} tests, isolated, -j 2: per test", fmt_time(per_test),
                               f"bare fork+exit+wait x2 {fmt_time(bare.seconds / isolated)}",
                               per_test * isolated / bare.seconds, "<= 2.00x",
                               per_test * isolated <= 2.0 * bare.seconds)
                    # The CPU each costs (every process of the run, user + system): steadier
                    # than the wall time when the machine is shared.
                    cpu = (mine.cpu - isolated_one.cpu) / isolated
                    table.line(f"{isolated} tests, isolated, -j 2: CPU per test", fmt_time(cpu),
                               f"bare fork+exit+wait {fmt_time(bare.cpu / isolated)}",
                               cpu * isolated / bare.cpu, "(stated)", True)
                    # The same forks from a process with the worker's libraries mapped (as
                    # every test's process has them: libstdc++, RTF's): what a fork costs a
                    # worker before it loads its plug-in, reads its request or says anything.
                    libraries = worker_libraries(os.path.join(build, "bin",
                                                              "robottestingframework-worker"))
                    if libraries:
                        env = dict(os.environ, LD_PRELOAD=" ".join(libraries))
                        mapped = Run([spawn([fork_cost, str(isolated), "2"], folder, env)
                                      for _ in range(rounds)])
                        table.line(f"{isolated} tests, isolated, -j 2: the worker's fork",
                                   fmt_time(mapped.seconds / isolated),
                                   f"bare fork+exit+wait x2 {fmt_time(bare.seconds / isolated)}",
                                   mapped.seconds / bare.seconds,
                                   "(stated: a fork with its libraries)", True)

        files = 200 // scale
        if "python" in parts:
            python_figures(table, runner, folder, files, forked_python, forked_why, rounds,
                           args.quick)
        if "network" in parts:
            network_bench.run(table, runner, folder, rounds, args.quick)
        if not args.quick and "worlds" in parts:
            ctest_world_bench.report(runner, folder, lambda *f: table.line(*f[:3], None, *f[3:]))
        if "worlds" in parts:
            shared_world_bench.figures(table, runner, folder, rounds)

        if args.soak_count > 0 and "soak" in parts:
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
