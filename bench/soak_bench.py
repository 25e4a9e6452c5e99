#!/usr/bin/env python3
"""A soak run: many tests that pass, fail, crash, hang, flood their output and leave children
behind, through the real runner in each isolation mode. Prints what a long CI run needs to
stay healthy: the runner's peak memory, its open file descriptors while it runs and at the end,
the results in the JUnit file against the tests run, and the processes left behind.

    python3 bench/soak_bench.py --runner build/bin/robottestingframework-testrunner

Targets: every result present, 0 leftovers, descriptors flat, peak memory <= 64 MiB. A
benchmark: it prints the figures beside the targets. It exits non-zero only when the run could
not be measured, or with --check when a result is missing or a process is left (the CTest smoke
run)."""
import argparse
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
import uuid
import xml.etree.ElementTree as ET

# Per 100 tests: (kind, how many, timeout in seconds, the script). Hangs dominate the time
# (each costs its 0.2 s timeout), so they are 1 in 100.
MIX = [
    ("pass", 60, 30, "exit 0\n"),
    ("fail", 15, 30, "echo 'the arm did not move' >&2\nexit 1\n"),
    ("crash", 5, 30, "kill -SEGV $$\n"),
    ("hang", 1, 0.2, "exec sleep 60\n"),
    ("output", 4, 30, "yes 'a line of output, printed again and again' | head -c 1000000\n"),
    ("children", 15, 30, "sleep 60 &\n(sleep 60 &)\nexit 0\n"),
]
MARKER = "RTF_SOAK_MARKER"


def write_run(folder, count):
    """Writes one script per kind and a suite of `count` tests mixing them; returns the suite."""
    kinds = []
    for kind, share, timeout, body in MIX:
        path = os.path.join(folder, kind)
        with open(path, "w") as f:
            f.write("#!/bin/sh\n" + body)
        os.chmod(path, 0o755)
        kinds.append((kind, share, timeout, path))
    # Each kind spread evenly over every 100 tests, so that a short run has them all too.
    pattern = sorted(((k + 0.5) * 100 / share, kind, timeout, path)
                     for kind, share, timeout, path in kinds for k in range(share))
    lines = ['<suite name="soak">']
    for i in range(count):
        _, kind, timeout, path = pattern[i % len(pattern)]
        lines.append(f'  <test type="exec" name="{kind} {i}" timeout="{timeout}">{path}</test>')
    lines.append("</suite>")
    suite = os.path.join(folder, "soak.xml")
    with open(suite, "w") as f:
        f.write("\n".join(lines) + "\n")
    return suite


def marked(marker):
    """Pids of the processes whose environment carries the marker."""
    needle = f"{MARKER}={marker}".encode()
    found = []
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/environ", "rb") as f:
                    if needle in f.read().split(b"\0"):
                        found.append(int(entry))
            except OSError:
                pass
    return found


class Sampler:
    """Reads the runner's VmHWM and its count of open descriptors from /proc while it runs."""

    def __init__(self, pid, every):
        self.pid = pid
        self.every = every
        self.peak_kib = 0
        self.fds = []  # (seconds since start, open descriptors)
        self.running = True
        self.start = time.monotonic()
        self.thread = threading.Thread(target=self.loop, daemon=True)
        self.thread.start()

    def sample(self):
        try:
            with open(f"/proc/{self.pid}/status") as f:
                for line in f:
                    if line.startswith("VmHWM:"):
                        self.peak_kib = max(self.peak_kib, int(line.split()[1]))
            fds = len(os.listdir(f"/proc/{self.pid}/fd"))
            if fds > 0:  # 0: it has exited (a zombie lists none)
                self.fds.append((time.monotonic() - self.start, fds))
        except (OSError, ValueError):
            pass

    def loop(self):
        while self.running:
            self.sample()
            time.sleep(self.every)

    def stop(self):
        self.running = False
        self.thread.join(timeout=5)


def run_mode(runner, folder, suite, isolation):
    junit = os.path.join(folder, f"soak-{isolation}.xml")
    marker = uuid.uuid4().hex
    env = {**os.environ, MARKER: marker, "TMPDIR": folder}
    start = time.monotonic()
    # The last descriptor count is read while it writes its outputs, after the last test.
    proc = subprocess.Popen([runner, "--isolation", isolation, "--suite", suite,
                             "--output", f"junit:{junit}", "--no-summary"],
                            cwd=folder, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                            start_new_session=True)
    sampler = Sampler(proc.pid, 0.2)
    tail = []

    def read_stdout():
        for line in proc.stdout:
            tail.append(line)
            del tail[:-50]

    reader = threading.Thread(target=read_stdout, daemon=True)
    reader.start()
    err = proc.stderr.read()
    status = proc.wait()
    reader.join(timeout=5)
    sampler.stop()
    seconds = time.monotonic() - start
    time.sleep(1.0)  # a child still on its way out is not a leftover
    leftovers = marked(marker)
    for pid in leftovers:
        try:
            os.kill(pid, signal.SIGKILL)
        except OSError:
            pass
    try:
        root = ET.parse(junit).getroot()
        results = sum(1 for _ in root.iter("testcase"))
        states = {}
        for case in root.iter("testcase"):
            kind = case.get("name", "").split(" ")[0]
            state = ("failed" if case.find("failure") is not None else
                     "error" if case.find("error") is not None else
                     "skipped" if case.find("skipped") is not None else "passed")
            states.setdefault(kind, {}).setdefault(state, 0)
            states[kind][state] += 1
    except (OSError, ET.ParseError) as e:
        results, states = -1, {"unreadable": str(e)}
    fds = [n for _, n in sampler.fds]
    # "Flat": after the first tests, the count moves by no more than a test's own few.
    settled = fds[len(fds) // 10:] or fds
    return {
        "isolation": isolation, "status": status, "seconds": seconds,
        "peak_mib": sampler.peak_kib / 1024, "fds_min": min(settled) if settled else -1,
        "fds_max": max(settled) if settled else -1, "fds_end": fds[-1] if fds else -1,
        "results": results, "leftovers": len(leftovers), "states": states,
        "stderr": err.decode(errors="replace")[-2000:], "tail": b"".join(tail)[-2000:],
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runner", required=True)
    parser.add_argument("--count", type=int, default=10000)
    parser.add_argument("--isolation", default="process,none")
    parser.add_argument("--workdir", help="where the tests and reports go (default: a new "
                        "temporary folder, removed afterwards)")
    parser.add_argument("--check", action="store_true",
                        help="exit 1 if a result is missing or a process is left behind")
    args = parser.parse_args()
    runner = os.path.abspath(args.runner)
    temporary = None
    if args.workdir:
        folder = os.path.abspath(args.workdir)
        os.makedirs(folder, exist_ok=True)
    else:
        temporary = tempfile.TemporaryDirectory(prefix="rtf-soak-")
        folder = temporary.name
    suite = write_run(folder, args.count)
    mix = ", ".join(f"{share}% {kind}" for kind, share, _, _ in MIX)
    print(f"soak: {args.count} tests ({mix}; hangs time out after 0.2 s, output is 1 MB, "
          "children: two sleep 60 left behind)")
    print(f"{'isolation':<10} {'time':>8} {'peak MiB':>9} {'fds min/max/end':>16} "
          f"{'results':>13} {'leftovers':>9}")
    healthy = True
    for isolation in args.isolation.split(","):
        r = run_mode(runner, folder, suite, isolation)
        print(f"{isolation:<10} {r['seconds']:>7.1f}s {r['peak_mib']:>9.1f} "
              f"{r['fds_min']:>6}/{r['fds_max']}/{r['fds_end']:<6} "
              f"{r['results']:>6}/{args.count:<6} {r['leftovers']:>9}")
        print(f"  states by kind: {r['states']}")
        if r["status"] not in (0, 1) or r["results"] != args.count or r["leftovers"] != 0:
            healthy = False
            print(f"  exit status {r['status']}\n  stderr: {r['stderr']}\n"
                  f"  stdout tail: {r['tail'].decode(errors='replace')}")
    print("targets: every result present, 0 leftovers, descriptors flat, peak <= 64 MiB")
    if temporary is not None:
        temporary.cleanup()
    return 1 if args.check and not healthy else 0


if __name__ == "__main__":
    sys.exit(main())
