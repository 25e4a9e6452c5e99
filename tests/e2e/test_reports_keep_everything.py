"""Reports keep everything, always (issue 22, item 1): without -v, every report file (text,
CTRF/JSON, TAP, HTML, JUnit) holds every testReport message of every test and fixture, each
with its time; -v changes only the console. Run on the example suites, in both isolation
modes and under -j 2."""
import json
import re

import pytest

from conftest import BUILD_DIR, run_runner, validate_ctrf, validate_junit, validate_tap

EXAMPLES = BUILD_DIR / "examples"
# What the example tests and fixtures report (examples/cpp, examples/python).
TEST_REPORTS = ["the move takes", "param again: ", "back to the home position"]
FIXTURE_REPORTS = ["starting the world: --world empty"]


@pytest.mark.parametrize("mode", [["--isolation", "none"], ["--isolation", "process"],
                                  ["--isolation", "process", "-j", "2"]],
                         ids=["none", "process", "process-j2"])
def test_every_report_keeps_every_message_without_verbose(tmp_path, mode):
    outputs = {kind: tmp_path / f"report.{ext}" for kind, ext in
               [("text", "txt"), ("json", "json"), ("tap", "tap"), ("html", "html"),
                ("junit", "xml")]}
    args = [a for kind, path in outputs.items() for a in ("-o", f"{kind}:{path.name}")]
    run = run_runner("--suite", EXAMPLES / "example.xml", "--suite", EXAMPLES / "scripts.xml",
                     *mode, *args, cwd=tmp_path, timeout=120)
    assert run.returncode == 0, run
    # The console without -v: no reports (-v's job).
    assert "the move takes" not in run.stdout, run

    text = outputs["text"].read_text()
    for words in TEST_REPORTS + FIXTURE_REPORTS:
        # "[1.042 s] report: the move takes ..."
        assert re.search(r"\[\d+\.\d{3} s\] report: [^\n]*" + re.escape(words), text), (words, text)

    report = validate_ctrf(outputs["json"])
    messages = [m for t in report["results"]["tests"]
                for m in t["extra"]["robotology.rtf"]["reports"]]
    start, stop = report["results"]["summary"]["start"], report["results"]["summary"]["stop"]
    for words in TEST_REPORTS:
        found = [m for m in messages if words in m["message"]]
        assert found and all(start <= m["time"] <= stop for m in found), (words, messages)
    suites = report["results"]["extra"]["robotology.rtf"]["suites"]
    fixture = [m for s in suites for m in s["messages"]]
    for words in FIXTURE_REPORTS:
        assert any(words in m["message"] and m["kind"] == "report" for m in fixture), fixture

    validate_tap(outputs["tap"])
    tap = outputs["tap"].read_text()
    for words in TEST_REPORTS:
        # In its test's YAML block (indented as its subtest is).
        assert re.search(r' messages:\n( +- "[^\n]*\n)* +- "\[\d+\.\d{3} s\] report: [^\n]*'
                         + re.escape(words), tap), (words, tap)
    for words in FIXTURE_REPORTS:
        assert re.search(r"# \[\d+\.\d{3} s\] report: " + re.escape(words), tap), (words, tap)

    html = outputs["html"].read_text()
    data = json.loads(re.search(r'id="report-data">(.*?)</script>', html, re.S).group(1))
    html_messages = [m for s in data["suites"] for t in s["tests"] for m in t["messages"]]
    for words in TEST_REPORTS:
        assert any(words in m["text"] and m["label"] == "report" and m["time"] > 0
                   for m in html_messages), (words, html_messages)
    suite_messages = [m for s in data["suites"] for m in s["messages"]]
    for words in FIXTURE_REPORTS:
        assert any(words in m["text"] for m in suite_messages), suite_messages

    validate_junit(outputs["junit"])
    junit = outputs["junit"].read_text()
    for words in TEST_REPORTS + FIXTURE_REPORTS:
        assert words in junit, words


def test_verbose_changes_the_console_only(tmp_path):
    reports = {}
    for name, verbose in (("quiet", []), ("verbose", ["-v", "-d"])):
        run = run_runner("--suite", EXAMPLES / "example.xml", *verbose, "-o",
                         f"json:{name}.json", "-o", f"tap:{name}.tap", cwd=tmp_path, timeout=60)
        assert run.returncode == 0, run
        assert ("the move takes" in run.stdout) == bool(verbose), run
        report = json.loads((tmp_path / f"{name}.json").read_text())
        reports[name] = sorted((m["kind"], m["message"]) for t in report["results"]["tests"]
                               for m in t["extra"]["robotology.rtf"]["reports"])
    assert reports["quiet"] == reports["verbose"] and reports["quiet"], reports
