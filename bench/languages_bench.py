#!/usr/bin/env python3
"""Time per trivial script test through the real runner, per language and isolation mode.

    python3 bench/languages_bench.py --runner build/bin/robottestingframework-testrunner

Writes COUNT trivial tests per language into a temporary folder, runs them as one suite, and
prints the time per test: (best time for COUNT tests - best time for 1 test) / (COUNT - 1),
so the runner's start-up is left out; each best is over --rounds rounds."""
import argparse
import os
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
    start = time.perf_counter()
    proc = subprocess.run([runner, "--suite", suite, "--isolation", isolation, "--no-output"],
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          timeout=600)
    elapsed = time.perf_counter() - start
    if proc.returncode != 0:
        return None, proc.stderr.strip().splitlines()[:1] or [f"exit {proc.returncode}"]
    return elapsed, None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runner", required=True, help="robottestingframework-testrunner")
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--languages", default="python,lua",
                        help="comma-separated, among " + ", ".join(SCRIPTS))
    parser.add_argument("--isolation", default="none,process")
    args = parser.parse_args()

    print(f"{'language':<8} {'isolation':<10} {'per test':>10}   ({args.count} tests, "
          f"best of {args.rounds})")
    with tempfile.TemporaryDirectory(prefix="rtf-languages-bench-") as folder:
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
                    print(f"{language:<8} {isolation:<10} {'n/a':>10}   {' '.join(why)}")
                else:
                    print(f"{language:<8} {isolation:<10} {best * 1000:>8.2f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
