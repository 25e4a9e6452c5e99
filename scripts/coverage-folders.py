#!/usr/bin/env python3
"""Line and branch coverage per top-level folder of src/, from gcovr's JSON summary.

usage: scripts/coverage-folders.py SUMMARY.json [--ran FILE...]
Prints a Markdown table (the one README.md shows): folder, lines, branches, and a total row.
With --ran, fails unless each FILE (src/...) has lines counted: code that only runs in child
processes, so a lost flush of their counters shows (src/platform/coverage.h).
"""
import json
import sys
from collections import defaultdict


def percent(covered, total):
    return f"{100.0 * covered / total:.1f} %" if total else "-"


def main():
    if len(sys.argv) < 2 or (len(sys.argv) > 2 and sys.argv[2] != "--ran"):
        sys.exit(__doc__.strip())
    with open(sys.argv[1]) as f:
        summary = json.load(f)
    covered = {entry["filename"]: entry["line_covered"] for entry in summary["files"]}
    lost = [name for name in sys.argv[3:] if covered.get(name, 0) == 0]
    folders = defaultdict(lambda: [0, 0, 0, 0])
    for entry in summary["files"]:
        parts = entry["filename"].split("/")
        if len(parts) < 3 or parts[0] != "src":
            continue
        counts = folders[parts[1]]
        counts[0] += entry["line_covered"]
        counts[1] += entry["line_total"]
        counts[2] += entry["branch_covered"]
        counts[3] += entry["branch_total"]
    print("| src/ folder | lines | branches |")
    print("|---|---|---|")
    total = [0, 0, 0, 0]
    for name in sorted(folders):
        c = folders[name]
        total = [a + b for a, b in zip(total, c)]
        print(f"| {name} | {percent(c[0], c[1])} ({c[0]}/{c[1]}) "
              f"| {percent(c[2], c[3])} ({c[2]}/{c[3]}) |")
    print(f"| **all** | {percent(total[0], total[1])} ({total[0]}/{total[1]}) "
          f"| {percent(total[2], total[3])} ({total[2]}/{total[3]}) |")
    if lost:
        sys.exit("coverage-folders: no line counted in " + ", ".join(lost) +
                 ": the counters of child processes were lost")


if __name__ == "__main__":
    main()
