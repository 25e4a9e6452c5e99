#!/usr/bin/env python3
"""The HTML report of a big run: its size, and how soon headless Chromium paints it.

    /usr/bin/python3 bench/html_bench.py --build build [--count 10000] [--isolation process]

Runs COUNT trivial C++ plug-in tests (bench/trivial_test.cpp) in one suite through the real
runner with `-o html:report.html`, then prints the report's size (whole and per test) and, from
Chromium's own timings (Debian's chromium and chromedriver, through python3-selenium), the time
to first paint and first contentful paint, and when the page's script was done (load event),
each the best of --rounds page loads from file://. A benchmark: it prints figures and checks
nothing beyond that the run and the page worked."""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time


def write_suite(folder, plugin, count):
    path = os.path.join(folder, "bench.xml")
    with open(path, "w") as f:
        f.write('<suite name="html bench">\n')
        f.write(f'  <test type="dll">{plugin}</test>\n' * count)
        f.write("</suite>\n")
    return path


def page_timings(page, rounds):
    # The e2e tests' Chromium (tests/e2e/browser.py): its files in a folder of its own.
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests",
                                    "e2e"))
    from browser import start_chromium

    profile = tempfile.mkdtemp(prefix="rtf-html-bench-chromium-")
    driver = start_chromium(profile, page_load_timeout=120)
    best = {}
    try:
        for _ in range(rounds):
            driver.get("about:blank")
            driver.get("file://" + os.path.abspath(page))
            timings = driver.execute_script("""
                const paint = {};
                for (const e of performance.getEntriesByType("paint")) paint[e.name] = e.startTime;
                const nav = performance.getEntriesByType("navigation")[0];
                return {"first paint": paint["first-paint"],
                        "first contentful paint": paint["first-contentful-paint"],
                        "load event end": nav ? nav.loadEventEnd : null,
                        "tests shown": document.getElementById("shown").textContent};""")
            for name, value in timings.items():
                if isinstance(value, (int, float)):
                    best[name] = min(best.get(name, value), value)
                else:
                    best[name] = value
    finally:
        driver.quit()
        shutil.rmtree(profile, ignore_errors=True)
    return best


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default="build", help="the build tree (default: build)")
    parser.add_argument("--count", type=int, default=10000, help="tests in the run")
    parser.add_argument("--isolation", default="process", choices=["process", "none"])
    parser.add_argument("--rounds", type=int, default=3, help="page loads; the best is shown")
    args = parser.parse_args()
    runner = os.path.join(args.build, "bin", "robottestingframework-testrunner")
    plugin = os.path.abspath(os.path.join(args.build, "bench", "rtf_bench_trivial_test.so"))
    for path in (runner, plugin):
        if not os.path.exists(path):
            sys.exit(f"html_bench: {path} is missing: build the project first")

    with tempfile.TemporaryDirectory(prefix="rtf-html-bench-") as folder:
        suite = write_suite(folder, plugin, args.count)
        page = os.path.join(folder, "report.html")
        started = time.monotonic()
        run = subprocess.run([os.path.abspath(runner), "--suite", suite, "--isolation",
                              args.isolation, "-o", f"html:{page}"], cwd=folder,
                             stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             timeout=3600)
        elapsed = time.monotonic() - started
        if run.returncode != 0 or not os.path.exists(page):
            sys.exit(f"html_bench: the run failed ({run.returncode}):\n{run.stdout[-2000:]}")
        size = os.path.getsize(page)
        timings = page_timings(page, args.rounds)

    print(f"HTML report of {args.count} trivial tests (--isolation {args.isolation})")
    print(f"  run, report written              {elapsed:10.2f} s")
    print(f"  report size                      {size / 1e6:10.2f} MB  ({size / args.count:.0f} bytes/test)")
    for name in ("first paint", "first contentful paint", "load event end"):
        value = timings.get(name)
        shown = f"{value:10.0f} ms" if isinstance(value, (int, float)) else "       n/a"
        print(f"  Chromium {name:<24}{shown}  (best of {args.rounds})")
    print(f"  page says                        {timings.get('tests shown')}")


if __name__ == "__main__":
    main()
