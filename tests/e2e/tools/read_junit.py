"""Reads a JUnit report with the third-party readers junitparser and xunitparser (installed by
scripts/python-tools.sh into the build tree) and checks that their counts equal the report's
own. Prints what they read of each file as a JSON list and exits 0, or prints the
disagreements and exits 1.
Usage: BUILD/python-tools/bin/python read_junit.py FILE..."""
import json
import sys
import xml.etree.ElementTree as ET

import junitparser
import xunitparser

KINDS = ("tests", "failures", "errors", "skipped")


def written(path):
    """The counts the report itself states: each suite's, and the root's totals."""
    root = ET.parse(path).getroot()
    suites = [{kind: int(suite.get(kind, "0")) for kind in KINDS}
              for suite in root.findall("testsuite")]
    totals = {kind: sum(suite[kind] for suite in suites) for kind in KINDS}
    stated = {kind: int(root.get(kind)) for kind in KINDS if root.get(kind) is not None}
    return suites, totals, stated


def by_junitparser(path):
    """Each suite's counts as junitparser recounts them from the test cases, and the totals of
    a merge (what `junitparser merge` writes)."""
    document = junitparser.JUnitXml.fromfile(path)
    suites = []
    for suite in document:
        suite.update_statistics()
        suites.append({kind: int(getattr(suite, kind) or 0) for kind in KINDS})
    merged = junitparser.JUnitXml()
    for suite in junitparser.JUnitXml.fromfile(path):
        merged.add_testsuite(suite)
    merged.update_statistics()
    return suites, {kind: int(getattr(merged, kind) or 0) for kind in KINDS}


def by_xunitparser(path):
    """The totals xunitparser reads (it asserts the root's own against its count)."""
    with open(path, "rb") as f:
        suite, result = xunitparser.parse(f)
    return {"tests": result.testsRun, "failures": len(result.failures),
            "errors": len(result.errors), "skipped": len(result.skipped)}


def check(path):
    """What the readers read of `path`, and the disagreements (empty when they agree)."""
    problems = []
    suites, totals, stated = written(path)
    for kind, value in stated.items():
        if value != totals[kind]:
            problems.append(f"<testsuites {kind}={value}> but its suites add up to {totals[kind]}")
    jp_suites, jp_merged = by_junitparser(path)
    if jp_suites != suites:
        problems.append(f"junitparser recounts the suites as {jp_suites}, the report says {suites}")
    if jp_merged != totals:
        problems.append(f"junitparser merge totals {jp_merged}, the report's are {totals}")
    try:
        xp = by_xunitparser(path)
    except (AssertionError, KeyError, ValueError) as e:
        problems.append(f"xunitparser cannot read it: {type(e).__name__} {e}")
        xp = None
    if xp is not None and xp != totals:
        problems.append(f"xunitparser reads {xp}, the report's totals are {totals}")
    return {"suites": suites, "totals": totals, "junitparser": jp_suites,
            "xunitparser": xp}, problems


def main(paths):
    read = []
    failed = False
    for path in paths:
        counts, problems = check(path)
        read.append(counts)
        if problems:
            failed = True
            print(f"{path}:\n  " + "\n  ".join(problems), file=sys.stderr)
    print(json.dumps(read))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
