#!/usr/bin/env python3
"""Private networks (--network private) through the real runner: what they buy and what they cost.

    python3 bench/network_bench.py --build build      (./run.sh bench runs it too)

1. 8 suites, each a world that becomes ready 1 s after its start on one fixed port (a server
   that sleeps 1 s, then listens; a <port> check), plus 2 short tests that connect to it:
   `-j 4 --network private` against `-j 1` (the machine's network, one suite at a time, as
   such suites must run without private networks). Figure: the speed-up over the ideal 4x;
   target >= 0.9.
2. The cost of a private network, from its making to the suite's first fixture start: one
   suite whose world is a process ready at once, plus one test, run alternately with and
   without --network private; the median of the paired differences is what a private network
   adds to a suite (making it, the worker joining it, the world started in it). Target: under
   5 ms. Beside it, the making alone as the runner's --verbose states it. As root, the same
   again as the user nobody (setpriv), whose private networks are made in user namespaces.
Medians over --rounds runs. A benchmark, not a test: it prints, it asserts nothing; it exits
non-zero only when a run failed."""
import argparse
import os
import re
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time

SERVER = """import socket, sys, time
time.sleep(1)
s = socket.socket()
s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
s.bind(("127.0.0.1", int(sys.argv[1])))
s.listen(16)
while True:
    s.accept()[0].close()
"""
# The system's interpreter, without site packages: a pyenv shim or a virtual environment would
# start in 0.1-0.3 s, on top of the world's 1 s.
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
CONNECT = "#!/bin/bash\nexec 3<>/dev/tcp/127.0.0.1/{port}\n"


class Failed(Exception):
    pass


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def write_fixed_port_suites(folder, count=8):
    """`count` suites naming one world file: ready 1 s after its start on one fixed port."""
    port = free_port()
    with open(os.path.join(folder, "server.py"), "w") as f:
        f.write(SERVER)
    with open(os.path.join(folder, "connect.sh"), "w") as f:
        f.write(CONNECT.format(port=port))
    os.chmod(os.path.join(folder, "connect.sh"), 0o755)
    with open(os.path.join(folder, "slow_world.xml"), "w") as f:
        f.write(f"""<world name="slow" logdir="logs">
  <process name="server" command="{PYTHON} -S server.py {port}">
    <ready timeout="20s"><port>{port}</port></ready>
  </process>
</world>
""")
    names = []
    for i in range(count):
        name = f"fixed{i}.xml"
        with open(os.path.join(folder, name), "w") as f:
            f.write('<suite>\n  <fixture type="process">slow_world.xml</fixture>\n'
                    '  <test type="exec">connect.sh</test>\n'
                    '  <test type="exec">connect.sh</test>\n</suite>\n')
        names.append(name)
    return names


def write_quick_suite(folder):
    """One suite whose world is ready as soon as it started, plus one test."""
    with open(os.path.join(folder, "quick_world.xml"), "w") as f:
        f.write('<world name="quick" logdir="logs">\n'
                '  <process name="sleeper" command="/bin/sleep 30"/>\n</world>\n')
    with open(os.path.join(folder, "quick.xml"), "w") as f:
        f.write('<suite>\n  <fixture type="process">quick_world.xml</fixture>\n'
                '  <test type="exec">/bin/true</test>\n</suite>\n')
    return "quick.xml"


def timed(runner, folder, suites, *extra, prefix=()):
    """(seconds, stdout) of one run of `suites`; a run that does not pass raises Failed."""
    argv = [*prefix, runner, "--no-output", *extra]
    for suite in suites:
        argv += ["-s", suite]
    start = time.perf_counter()
    done = subprocess.run(argv, cwd=folder, stdin=subprocess.DEVNULL, capture_output=True,
                          text=True, timeout=300)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        raise Failed(f"{' '.join(argv[3:])}: exit {done.returncode}\n"
                     f"{done.stdout[-1500:]}{done.stderr[-500:]}")
    return seconds, done.stdout + done.stderr


def fmt(seconds):
    return f"{seconds * 1e3:.2f} ms" if seconds < 1 else f"{seconds:.2f} s"


def run(table, runner, folder, rounds, quick=False):
    """Prints the figures through `table` (perf_bench's Table: line(figure, ours, reference,
    ratio, target, met))."""
    folder = os.path.join(folder, "network")
    os.makedirs(folder, exist_ok=True)
    try:
        side_by_side(table, runner, folder, rounds, quick)
    except Failed as e:
        table.failed("fixed-port worlds, -j 4 --network private", str(e))
    try:
        network_cost(table, runner, folder, rounds, quick)
    except Failed as e:
        table.failed("private network: added to a suite", str(e))
    # As another user (a CI job that is not root): through a user namespace.
    if os.getuid() == 0 and shutil.which("setpriv") and not quick:
        nobody = os.path.join(folder, "nobody")
        os.makedirs(nobody, exist_ok=True)
        for walked in (nobody, folder, os.path.dirname(folder)):
            os.chmod(walked, os.stat(walked).st_mode | 0o011)
        os.chown(nobody, 65534, 65534)
        try:
            network_cost(table, runner, nobody, rounds, quick, as_nobody=True)
        except Failed as e:
            table.failed("private network: added, as nobody", str(e))


def side_by_side(table, runner, folder, rounds, quick):
    count = 2 if quick else 8
    suites = write_fixed_port_suites(folder, count)
    slow_rounds = 1 if quick else max(1, min(rounds, 3))
    serial = statistics.median(timed(runner, folder, suites, "-j", "1")[0]
                               for _ in range(slow_rounds))
    parallel = statistics.median(
        timed(runner, folder, suites, "-j", "4", "--network", "private")[0]
        for _ in range(slow_rounds))
    speedup = serial / parallel
    table.line(f"{count} fixed-port 1 s worlds, -j 4 private nets", fmt(parallel),
               f"-j 1 {fmt(serial)}", speedup / 4, ">= 0.90x of 4x", speedup / 4 >= 0.9)


def network_cost(table, runner, folder, rounds, quick, as_nobody=False):
    quick_suite = write_quick_suite(folder)
    prefix = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups"] if as_nobody \
        else []
    if as_nobody:
        for name in os.listdir(folder):
            os.chown(os.path.join(folder, name), 65534, 65534)
    who = ", as nobody" if as_nobody else ""
    pairs = 5 if quick else max(21, 6 * rounds)
    timed(runner, folder, [quick_suite], prefix=prefix)  # warm-up
    differences, host_times, made, kind = [], [], [], ""
    for _ in range(pairs):
        host, _ = timed(runner, folder, [quick_suite], prefix=prefix)
        private, output = timed(runner, folder, [quick_suite], "--network", "private", "-v",
                                prefix=prefix)
        differences.append(private - host)
        host_times.append(host)
        found = re.search(r"a private network is made in ([\d.]+) ms \(([^)]*)\)", output)
        if found:
            made.append(float(found.group(1)) / 1e3)
            kind = found.group(2)
    added = statistics.median(differences)
    table.line(f"private network: added to a suite{who}", fmt(added),
               f"the suite alone {fmt(statistics.median(host_times))}", None, "< 5 ms",
               added < 0.005)
    if made:
        table.line(f"private network: making one{who}", fmt(statistics.median(made)),
                   kind, None, "(stated)", True)


class PlainTable:
    def __init__(self, judged=True):
        self.missed = self.failures = 0
        self.judged = judged  # --quick: nothing is judged
        print(f"{'figure':<44} {'ours':>10} {'reference':>30} {'ratio':>7}  target")

    def line(self, figure, ours, reference, ratio, target, met):
        if not self.judged:
            target, met = "(--quick: not judged)", True
        self.missed += 0 if met else 1
        ratio_text = f"{ratio:.2f}x" if ratio is not None else ""
        print(f"{figure:<44} {ours:>10} {reference:>30} {ratio_text:>7}  {target}"
              f"{'' if met else '  MISSED'}", flush=True)

    def failed(self, figure, why):
        self.missed += 1
        self.failures += 1
        print(f"{figure:<44} FAILED: {why}", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the build tree (default: build)")
    parser.add_argument("--rounds", type=int, default=3, help="runs per figure (median)")
    parser.add_argument("--quick", action="store_true", help="a smoke run; figures mean nothing")
    args = parser.parse_args()
    runner = os.path.join(os.path.abspath(args.build), "bin", "robottestingframework-testrunner")
    if not os.path.exists(runner):
        sys.exit(f"network_bench: {runner} is missing; build first")
    table = PlainTable(judged=not args.quick)
    with tempfile.TemporaryDirectory(prefix="rtf-network-") as folder:
        run(table, runner, folder, args.rounds, args.quick)
    return 1 if table.failures else 0


if __name__ == "__main__":
    sys.exit(main())
