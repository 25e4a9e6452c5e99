#!/usr/bin/env python3
"""CTest over robottestingframework_discover_tests: worlds started per suite, not per test.

    python3 bench/ctest_world_bench.py --build build

8 suites, each in a private network with a world that serves one fixed port and becomes
ready 1 s after it starts, and 2 short tests; `ctest -j 4` over discover_tests. Each world
counts its starts in a file. Figures: worlds started (target: the number of suites, 8; 1 when
the suites share one world, `<fixture type="process" scope="run">`, measured too: one keeper
for the 8 suites, docs/new/ctest-shared-worlds.md) and ctest's wall time, for WORLD PER_SUITE
(the default), the shared world, and WORLD PER_TEST (one world per test, as before). A
benchmark: it prints, it asserts nothing."""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

SUITES, TESTS, JOBS = 8, 2, 4
SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

WORLD = """<world name="slow">
  <process name="server">
    <command shell="true">echo started &gt;&gt; {starts}; sleep 1; exec /usr/bin/python3 -m http.server 18777 --bind 127.0.0.1</command>
    <ready timeout="30s"><port>18777</port></ready>
  </process>
</world>
"""


def write_project(folder, world, network, scope="suite"):
    os.makedirs(folder, exist_ok=True)
    starts = os.path.join(folder, "starts.txt")
    with open(os.path.join(folder, "world.xml"), "w") as f:
        f.write(WORLD.format(starts=starts))
    calls = []
    for s in range(SUITES):
        lines = [f'<suite name="s{s}" network="{network}">',
                 f'  <fixture type="process" scope="{scope}">world.xml</fixture>']
        lines += [f'  <test type="exec" name="t{t}">/bin/true</test>' for t in range(TESTS)]
        with open(os.path.join(folder, f"s{s}.xml"), "w") as f:
            f.write("\n".join(lines + ["</suite>"]) + "\n")
        calls.append(f"robottestingframework_discover_tests(SUITE s{s}.xml WORLD {world} "
                     "TIMEOUT 120)")
    with open(os.path.join(folder, "CMakeLists.txt"), "w") as f:
        f.write("cmake_minimum_required(VERSION 3.19)\nproject(ctest_world_bench NONE)\n"
                "enable_testing()\n" + "\n".join(calls) + "\n")
    return starts


def measure(runner, folder, world, network="private", scope="suite"):
    """(seconds, worlds started, ctest's exit status) of `ctest -j 4` over the 8 suites."""
    project = os.path.join(folder, f"ctest_{world.lower()}_{scope}")
    starts = write_project(project, world, network, scope)
    build = os.path.join(project, "build")
    helpers = os.path.join(SOURCE, "cmake", "RobotTestingFrameworkCTest.cmake")
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    subprocess.run(["cmake", "-S", project, "-B", build, *generator,
                    f"-DRobotTestingFramework_TESTRUNNER={runner}",
                    f"-DCMAKE_PROJECT_INCLUDE={helpers}"], check=True,
                   stdout=subprocess.DEVNULL)
    if os.path.exists(starts):
        os.unlink(starts)
    start = time.monotonic()
    run = subprocess.run(["ctest", "--test-dir", build, "-j", str(JOBS)], capture_output=True,
                         text=True, timeout=600)
    seconds = time.monotonic() - start
    count = open(starts).read().count("started") if os.path.exists(starts) else 0
    return seconds, count, run.returncode


def private_networks_work():
    return subprocess.run(["unshare", "--user", "--net", "--map-root-user", "true"],
                          capture_output=True).returncode == 0


def report(runner, folder, line):
    """The figures, each through line(figure, ours, reference, target, met)."""
    network = "private" if private_networks_work() else "host"
    if network == "host":
        print("ctest_world_bench: no private networks here: the suites share the machine's "
              "network (one world at a time would be needed; the counts still hold)")
    per_suite = measure(runner, folder, "PER_SUITE", network)
    per_test = measure(runner, folder, "PER_TEST", network)
    shared = measure(runner, folder, "PER_SUITE", network, scope="run")
    line(f"ctest -j {JOBS}, {SUITES} suites x {TESTS}: worlds", f"{per_suite[1]}",
         f"one per test {per_test[1]}", f"= {SUITES} (suites)",
         per_suite[1] == SUITES and per_suite[2] == 0)
    line(f"ctest -j {JOBS}, {SUITES} suites x {TESTS}, shared: worlds", f"{shared[1]}",
         f"not shared {per_suite[1]}", "= 1 (shared)", shared[1] == 1 and shared[2] == 0)
    line(f"ctest -j {JOBS}, {SUITES} suites x {TESTS}: time", f"{per_suite[0]:.2f} s",
         f"one per test {per_test[0]:.2f} s", "(stated)", per_suite[2] == 0)
    line(f"ctest -j {JOBS}, {SUITES} suites x {TESTS}, shared: time", f"{shared[0]:.2f} s",
         f"not shared {per_suite[0]:.2f} s", "(stated)", shared[2] == 0)
    if per_suite[2] != 0 or per_test[2] != 0 or shared[2] != 0:
        print(f"ctest_world_bench: ctest exit {per_suite[2]} (per suite), {per_test[2]} "
              f"(per test), {shared[2]} (shared)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the build tree (default: build)")
    args = parser.parse_args()
    runner = os.path.join(os.path.abspath(args.build), "bin", "robottestingframework-testrunner")
    if not os.path.exists(runner):
        sys.exit(f"ctest_world_bench: {runner} is missing; build first")
    with tempfile.TemporaryDirectory(prefix="rtf-ctest-worlds-") as folder:
        def line(figure, ours, reference, target, met):
            print(f"{figure:<44} {ours:>10} {reference:>30}  {target}"
                  f"{'' if met else '  MISSED'}", flush=True)
        report(runner, folder, line)
    return 0


if __name__ == "__main__":
    sys.exit(main())
