"""Suites for the shard tests: exec scripts that pass, fail, or fail when a CI engine's shard
variable reaches them, and the normalisation that compares merged reports with one run."""
import json
import os
import xml.etree.ElementTree as ET
from pathlib import Path

SHARD_VARIABLES = ["TEST_SHARD_INDEX", "TEST_TOTAL_SHARDS", "TEST_SHARD_STATUS_FILE",
                   "XML_OUTPUT_FILE", "GTEST_SHARD_INDEX", "GTEST_TOTAL_SHARDS", "CI_NODE_INDEX",
                   "CI_NODE_TOTAL", "JOB_COMPLETION_INDEX", "RTF_SHARD_COUNT"]

# A test that fails when any shard variable reached it.
CLEAN_ENV = "#!/bin/sh\nfor v in " + " ".join(SHARD_VARIABLES) + """; do
  if env | grep -q "^$v="; then echo "$v reached the test"; exit 1; fi
done
exit 0
"""


def write_script(path, body):
    path.write_text(body)
    path.chmod(0o755)
    return path


def make_suites(folder, count=7, failing=(2,), broken_fixture=()):
    """`count` suites in `folder` (suite-00.xml ...), two exec tests each; the suites of
    `failing` have a failing test, those of `broken_fixture` a fixture that cannot be loaded.
    Returns the folder."""
    folder.mkdir(parents=True, exist_ok=True)
    write_script(folder / "ok.sh", "#!/bin/sh\necho fine\nexit 0\n")
    write_script(folder / "bad.sh", "#!/bin/sh\necho broken\nexit 1\n")
    write_script(folder / "clean_env.sh", CLEAN_ENV)
    for i in range(count):
        tests = ['  <test type="exec" name="clean">clean_env.sh</test>',
                 f'  <test type="exec" name="{"bad" if i in failing else "ok"}">'
                 f'{"bad" if i in failing else "ok"}.sh</test>']
        if i in broken_fixture:
            tests.insert(0, "  <fixture>no_such_fixture</fixture>")
        (folder / f"suite-{i:02d}.xml").write_text(
            f'<suite name="s{i:02d}">\n' + "\n".join(tests) + "\n</suite>\n")
    return folder


def normal_junit(path):
    """The JUnit report without what differs between runs (times, dates, host)."""
    root = ET.parse(path).getroot()
    for element in root.iter():
        for attribute in ("time", "timestamp", "hostname"):
            element.attrib.pop(attribute, None)
        # Indentation is layout, not content.
        if element.text is not None and not element.text.strip():
            element.text = None
        element.tail = None
    return ET.tostring(root, encoding="unicode")


def normal_ctrf(path):
    """The CTRF report without what differs between runs (times, dates, execution ids)."""
    report = json.loads(Path(path).read_text())
    report.pop("timestamp")
    summary = report["results"]["summary"]
    for key in ("start", "stop", "duration"):
        summary.pop(key)
    for test in report["results"]["tests"]:
        for key in ("start", "stop", "duration", "executionId"):
            test.pop(key)
        for message in test["extra"]["robotology.rtf"].get("reports", []):
            message.pop("time")
    for suite in report["results"]["extra"]["robotology.rtf"]["suites"]:
        suite.pop("duration")
        for message in suite.get("messages", []):
            message.pop("time")
    return report


def engine_env(**variables):
    """The environment of a run with `variables` and none of the shard variables of the machine
    the tests run on."""
    env = {k: v for k, v in os.environ.items() if k not in SHARD_VARIABLES}
    env.update({k: str(v) for k, v in variables.items()})
    return env
