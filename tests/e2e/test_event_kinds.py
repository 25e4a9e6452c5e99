"""An event kind with nothing but its rows in the tables reaches every reporter through every
relay: ResultEvent::Kind::Probe, reserved for this test, is sent by the probe_event plug-in as
data (TestResult::publish). No relay, queue, writer or wire code names it, so it travels as any
kind added later would: in-process and isolated, one suite at a time and two at once. Its
table row gives it the state "failed" and the word "probe", so every output shows whether it
arrived: a relay that dropped it would leave the test passed there. The runner starts in the
suites' folder and is given relative paths, as users run it."""
import json
import re
import xml.etree.ElementTree as ET

import pytest

from conftest import plugin, run_runner, validate_ctrf, validate_junit, validate_tap
from web_run import WebRun, request

PROBE = "the probe arrived"


def suites(tmp_path, suite_file):
    """Two suites, each a probe test between two passing ones (two, so -j 2 runs them at once)."""
    paths = []
    for name in ("first", "second"):
        paths += ["--suite", suite_file(f"""<suite name="{name}">
  <test name="{name}-before">{plugin("passing_test")}</test>
  <test name="{name}-probe">{plugin("probe_event")}</test>
  <test name="{name}-after">{plugin("passing_test")}</test>
</suite>""", name=f"{name}.xml").name]
    return paths


@pytest.mark.parametrize("jobs", ["1", "2"])
@pytest.mark.parametrize("isolation", ["process", "none"])
def test_a_kind_with_only_its_table_rows_reaches_every_reporter(
        tmp_path, isolation, jobs, suite_file):
    args = ["--isolation", isolation, "-j", jobs, *suites(tmp_path, suite_file)]
    out = {kind: tmp_path / f"r.{kind}" for kind in ("txt", "xml", "tap", "json", "html")}
    r = run_runner(*args, "--output", "text:r.txt", "--output", "junit:r.xml",
                   "--output", "tap:r.tap", "--output", "json:r.json",
                   "--output", "html:r.html", cwd=tmp_path, timeout=90)
    assert r.returncode == 1, r
    probes = ["first-probe", "second-probe"]

    # The console (-j 1: the console listener; -j 2: the parallel console), under its word.
    for name in probes:
        assert re.search(rf"^  FAILED\s+(\S+/)?{name}  \(", r.stdout, re.M), r.stdout
    assert r.stdout.count(f"probe: {PROBE}") == 2, r.stdout
    assert "2 failed" in r.stdout, r.stdout

    # The text report.
    text = out["txt"].read_text()
    assert text.count(f"probe: {PROBE}") >= 2, text

    # JUnit: a failure element carrying the probe's message.
    validate_junit(out["xml"])
    cases = {c.get("name"): c for c in ET.parse(out["xml"]).getroot().iter("testcase")}
    for name in probes:
        assert cases[name].find("failure") is not None, ET.tostring(cases[name])
        assert PROBE in ET.tostring(cases[name], encoding="unicode")
    assert cases["first-before"].find("failure") is None

    # TAP: a failed point whose diagnostics carry the message.
    validate_tap(out["tap"])
    tap = out["tap"].read_text()
    for name in probes:
        assert re.search(rf"^\s+not ok \d+ - {name}$", tap, re.M), tap
    assert tap.count(f'message: "{PROBE}"') == 2, tap

    # CTRF JSON.
    validate_ctrf(out["json"])
    tests = {t["name"]: t for t in json.loads(out["json"].read_text())["results"]["tests"]}
    for name in probes:
        assert tests[name]["status"] == "failed", tests[name]
        assert tests[name]["message"].startswith(PROBE), tests[name]

    # The HTML report's data.
    html = out["html"].read_text()
    data = json.loads(html.split('id="report-data">', 1)[1].split("</script>", 1)[0])
    shown = {t["name"]: t for s in data["suites"] for t in s["tests"]}
    for name in probes:
        assert shown[name]["state"] == "failed", shown[name]
        assert any(PROBE in m["text"] for m in shown[name]["messages"]), shown[name]

    # The live web page.
    run = WebRun(*args, "--web-linger", "60", cwd=tmp_path)
    try:
        run.wait_for_line("final page stays")
        snapshot = json.loads(request(run.port, "/snapshot")[2])
        live = {t["name"]: t for s in snapshot["suites"] for t in s["tests"]}
        for name in probes:
            assert live[name]["state"] == "failed", live[name]
            assert any(PROBE in m["text"] for m in live[name]["messages"]), live[name]
        run.proc.send_signal(2)
        assert run.wait(timeout=10) == 1, run.output()
    finally:
        run.kill()
