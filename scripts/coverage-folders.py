#!/usr/bin/env python3
"""Line and branch coverage per top-level folder of src/, from gcovr's JSON summary.

usage: scripts/coverage-folders.py SUMMARY.json
Prints a Markdown table (the one README.md shows): folder, lines, branches, and a total row.
"""
import json
import sys
from collections import defaultdict


def percent(covered, total):
    return f"{100.0 * covered / total:.1f} %" if total else "-"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip())
    with open(sys.argv[1]) as f:
        summary = json.load(f)
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


if __name__ == "__main__":
    main()
