#!/usr/bin/env python3
"""Time per trivial script test through the real runner, per language and isolation mode.

    python3 bench/languages_bench.py --runner build/bin/robottestingframework-testrunner

Writes COUNT trivial tests per language into a temporary folder, runs them as one suite, and
prints the time per test: (best time for COUNT tests - best time for 1 test) / (COUNT - 1),
so the runner's start-up is left out; each best is over --rounds rounds. Also the whole time of
the COUNT tests beside pytest's on COUNT equivalent files (`def test_x(): assert 1 + 1 == 2`),
"process" with and without the pre-started interpreters (RTF_PRESTART=0: "process-cold"), and
with --cpp-plugin the runner's peak memory (VmHWM) for --memory-count isolated Python tests
against as many isolated C++ tests."""
import argparse
import contextlib
import os
import shutil
import subprocess
import sys
import tempfile
import time

SCRIPTS = {
    "python": ("py", """import robottestingframework
class TestCase:
    def run(self):
        robottestingframework.testCheck(True, "trivial")
"""),
    "lua": ("lua", """TestCase = {}
function TestCase.run()
    robottestingframework.testCheck(true, "trivial")
end
"""),
    "ruby": ("rb", """class TestCase
  def run
    RobotTestingFramework::testCheck(true, "trivial")
  end
end
"""),
}


def write_suite(folder, language, count):
    ext, text = SCRIPTS[language]
    lines = [f'<suite name="{language} bench">']
    for i in range(count):
        name = f"{language}_{i}.{ext}"
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)
        lines.append(f"  <test>{name}</test>")
    lines.append("</suite>")
    path = os.path.join(folder, f"{language}_{count}.xml")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def run(runner, suite, isolation):
    """Wall time of one run in seconds; None when the mode or the language is unavailable."""
    env = dict(os.environ)
    if isolation == "process-cold":
        isolation = "process"
        env["RTF_PRESTART"] = "0"
    start = time.perf_counter()
    proc = subprocess.run([runner, "--suite", suite, "--isolation", isolation, "--no-output"],
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          timeout=600, env=env)
    elapsed = time.perf_counter() - start
    if proc.returncode != 0:
        return None, proc.stderr.strip().splitlines()[:1] or [f"exit {proc.returncode}"]
    return elapsed, None


def pytest_time(folder, count, rounds):
    """Best wall time of pytest on `count` one-assertion files (one process, as pytest runs)."""
    tests = os.path.join(folder, f"pytest_{count}")
    os.makedirs(tests, exist_ok=True)
    for i in range(count):
        with open(os.path.join(tests, f"test_{i}.py"), "w") as f:
            f.write("def test_x():\n    assert 1 + 1 == 2\n")
    best = None
    for _ in range(rounds):
        start = time.perf_counter()
        proc = subprocess.run([sys.executable, "-B", "-m", "pytest", "-q", "-p", "no:cacheprovider",
                               tests], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                              cwd=folder, timeout=600)
        elapsed = time.perf_counter() - start
        if proc.returncode != 0:
            return None
        best = elapsed if best is None else min(best, elapsed)
    return best


def peak_memory(runner, suite):
    """The runner's own peak resident memory (VmHWM, KiB) over one isolated run."""
    proc = subprocess.Popen([runner, "--suite", suite, "--no-output"], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    peak = 0
    while proc.poll() is None:
        try:
            with open(f"/proc/{proc.pid}/status") as f:
                for line in f:
                    if line.startswith("VmHWM:"):
                        peak = max(peak, int(line.split()[1]))
        except OSError:
            pass
        time.sleep(0.005)
    return peak if proc.returncode == 0 else None


def write_cpp_suite(folder, plugin, count):
    path = os.path.join(folder, f"cpp_{count}.xml")
    with open(path, "w") as f:
        f.write('<suite name="cpp bench">\n')
        f.writelines(f'  <test name="cpp_{i}">{plugin}</test>\n' for i in range(count))
        f.write("</suite>\n")
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runner", required=True, help="robottestingframework-testrunner")
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--languages", default="python,lua,ruby",
                        help="comma-separated, among " + ", ".join(SCRIPTS))
    parser.add_argument("--isolation", default="none,process,process-cold")
    parser.add_argument("--no-pytest", action="store_true", help="leave pytest out")
    parser.add_argument("--cpp-plugin", help="a trivial C++ test plug-in, for the memory row "
                        "(build/bench/rtf_bench_trivial_test.so)")
    parser.add_argument("--memory-count", type=int, default=1000)
    parser.add_argument("--workdir", help="where the suites are written (default: a temporary "
                        "folder); emptied first")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 when a run failed (a row says n/a); never on a figure")
    args = parser.parse_args()

    if args.workdir:
        shutil.rmtree(args.workdir, ignore_errors=True)
        os.makedirs(args.workdir)
        context = contextlib.nullcontext(args.workdir)
    else:
        context = tempfile.TemporaryDirectory(prefix="rtf-languages-bench-")
    failed = False
    with context as folder:
        reference = None if args.no_pytest else pytest_time(folder, args.count, args.rounds)
        if reference is not None:
            print(f"pytest on {args.count} files: {reference:.3f} s "
                  f"({reference / args.count * 1000:.2f} ms a test, best of {args.rounds})")
        print(f"{'language':<8} {'isolation':<13} {'per test':>10} {args.count:>6} tests "
              f"{'x pytest':>9}   (best of {args.rounds})")
        for language in args.languages.split(","):
            one = write_suite(folder, language, 1)
            many = write_suite(folder, language, args.count)
            for isolation in args.isolation.split(","):
                # The best run of each size: noise only ever adds time.
                t1 = tn = None
                for _ in range(args.rounds):
                    one_time, why = run(args.runner, one, isolation)
                    if one_time is None:
                        break
                    many_time, why = run(args.runner, many, isolation)
                    if many_time is None:
                        break
                    t1 = one_time if t1 is None else min(t1, one_time)
                    tn = many_time if tn is None else min(tn, many_time)
                best = None if t1 is None or tn is None else (tn - t1) / (args.count - 1)
                if best is None:
                    failed = True
                    print(f"{language:<8} {isolation:<13} {'n/a':>10}   {' '.join(why)}")
                else:
                    ratio = f"{tn / reference:>8.2f}x" if reference else f"{'':>9}"
                    print(f"{language:<8} {isolation:<13} {best * 1000:>7.2f} ms {tn:>8.3f} s "
                          f"{ratio}")
        if args.cpp_plugin:
            python = write_suite(folder, "python", args.memory_count)
            cpp = write_cpp_suite(folder, os.path.abspath(args.cpp_plugin), args.memory_count)
            peaks = {}
            for name, suite in (("python", python), ("c++", cpp)):
                found = [peak_memory(args.runner, suite) for _ in range(args.rounds)]
                peaks[name] = None if None in found else min(found)
            if None in peaks.values():
                failed = True
                print("runner peak memory: n/a (a run failed)")
            else:
                print(f"runner peak memory, {args.memory_count} isolated tests: python "
                      f"{peaks['python'] / 1024:.1f} MiB, c++ {peaks['c++'] / 1024:.1f} MiB "
                      f"({peaks['python'] / peaks['c++']:.2f}x)")
    return 1 if args.check and failed else 0


if __name__ == "__main__":
    sys.exit(main())
