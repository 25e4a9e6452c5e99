"""Attachments (issue 22, item 3) through the real runner: testAttach in every language (exec
tests through TAP YAML) copies the file into rtf-attachments/ beside the report outputs, and
every report links the copy; a missing file and a file or run over its limit are a clear error
of the test. In-process and isolated, one suite at a time and two at once (-j 2)."""
import os
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from conftest import plugin, run_runner, validate_ctrf, validate_junit, validate_tap

SCRIPTS = {
    "py": ("py", """class TestCase:
    def run(self):
        robottestingframework.testAttach("plot.svg", "the py plot")
"""),
    "lua": ("lua", """TestCase.run = function()
  robottestingframework.testAttach("plot.svg", "the lua plot")
end
"""),
    "rb": ("rb", """class TestCase
  def run
    RobotTestingFramework::testAttach("plot.svg", "the rb plot")
  end
end
"""),
    "exec": ("sh", """#!/bin/sh
echo 'TAP version 14'
echo '1..1'
echo 'ok 1 - plotted'
echo '  ---'
echo '  attachments:'
echo '    - path: plot.svg'
echo '      description: the exec plot'
echo '  ...'
"""),
}
SVG = '<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"><rect width="5" height="5"/></svg>\n'


def write_suites(tmp_path):
    """Two suites: C++ and Python; Lua, Ruby and exec. Each test is named <language>-attach."""
    (tmp_path / "plot.svg").write_text(SVG)
    first = [f'  <test name="cpp-attach" param="attach plot.svg">{plugin("measuring_test")}</test>']
    second = []
    for language, (ext, text) in SCRIPTS.items():
        path = tmp_path / f"{language}_attach.{ext}"
        path.write_text(text)
        path.chmod(0o755)
        (first if language == "py" else second).append(
            f'  <test name="{language}-attach">{path.name}</test>')
    for name, lines in (("first", first), ("second", second)):
        (tmp_path / f"{name}.xml").write_text(
            f'<suite name="{name}">\n' + "\n".join(lines) + "\n</suite>\n")
    return ["--suite", "first.xml", "--suite", "second.xml"]


@pytest.mark.parametrize("isolation,jobs", [("none", "1"), ("process", "1"), ("process", "2")])
def test_attachments_are_copied_and_linked_by_every_report(tmp_path, isolation, jobs):
    args = write_suites(tmp_path)
    (tmp_path / "reports").mkdir()
    r = run_runner("--isolation", isolation, "-j", jobs, *args, "-o", "junit:reports/r.xml",
                   "-o", "tap:reports/r.tap", "-o", "json:reports/r.json",
                   "-o", "html:reports/r.html", cwd=tmp_path, timeout=150)
    assert r.returncode == 0, r
    folder = tmp_path / "reports" / "rtf-attachments"
    copies = sorted(p.name for p in folder.iterdir() if p.name != ".lock")
    assert len(copies) == 5 and all(name.endswith("-plot.svg") for name in copies), copies
    for copy in copies:
        assert (folder / copy).read_text() == SVG

    # CTRF's own attachments array: name, contentType, path relative to the report's folder.
    report = validate_ctrf(tmp_path / "reports" / "r.json")
    tests = {t["name"]: t for t in report["results"]["tests"]}
    for language in ["cpp", *SCRIPTS]:
        attachments = tests[f"{language}-attach"]["attachments"]
        assert len(attachments) == 1, tests[f"{language}-attach"]
        assert attachments[0]["name"] == "plot.svg"
        assert attachments[0]["contentType"] == "image/svg+xml"
        assert (tmp_path / "reports" / attachments[0]["path"]).read_text() == SVG

    # JUnit: [[ATTACHMENT|absolute path]] alone on its line in <system-out>.
    validate_junit(tmp_path / "reports" / "r.xml")
    for case in ET.parse(tmp_path / "reports" / "r.xml").getroot().iter("testcase"):
        lines = case.find("system-out").text.splitlines()
        attached = [line[len("[[ATTACHMENT|"):-2] for line in lines
                    if line.startswith("[[ATTACHMENT|") and line.endswith("]]")]
        assert len(attached) == 1 and os.path.isabs(attached[0]), lines
        assert Path(attached[0]).read_text() == SVG

    # TAP: the YAML block of each point; HTML: the image shown inline from the copy.
    validate_tap(tmp_path / "reports" / "r.tap")
    tap = (tmp_path / "reports" / "r.tap").read_text()
    # The YAML blocks' keys, not the exec test's TAP text kept among its messages.
    assert len(re.findall(r"^\s*attachments:$", tap, re.M)) == 5, tap
    html = (tmp_path / "reports" / "r.html").read_text()
    assert html.count('"path":"rtf-attachments/') == 5, html
    assert "img-src data: 'self' file:" in html


def test_a_new_run_starts_with_an_empty_attachments_folder(tmp_path):
    write_suites(tmp_path)
    for _ in range(2):
        r = run_runner("--suite", "first.xml", "-o", "json:r.json", cwd=tmp_path)
        assert r.returncode == 0, r
    copies = [p for p in (tmp_path / "rtf-attachments").iterdir() if p.name != ".lock"]
    assert len(copies) == 2, copies  # this run's C++ and Python attachments only


@pytest.mark.parametrize("isolation", ["none", "process"])
def test_a_missing_file_is_an_error_of_the_test(tmp_path, isolation):
    r = run_runner("--isolation", isolation, "--test", plugin("measuring_test"), "--param",
                   "attach nowhere.log", "-o", "json:r.json", cwd=tmp_path)
    assert r.returncode == 1, r
    test = validate_ctrf(tmp_path / "r.json")["results"]["tests"][0]
    assert test["extra"]["robotology.rtf"]["state"] == "error", test
    assert "cannot attach 'nowhere.log'" in test["message"], test


@pytest.mark.parametrize("isolation", ["none", "process"])
def test_a_file_over_the_limit_is_an_error_naming_the_limit(tmp_path, isolation):
    big = tmp_path / "big.log"
    with open(big, "wb") as f:
        f.truncate(16 * 1024 * 1024 + 1)  # sparse: one byte over the default 16 MiB
    r = run_runner("--isolation", isolation, "--test", plugin("measuring_test"), "--param",
                   "attach big.log", "-o", "json:r.json", cwd=tmp_path)
    assert r.returncode == 1, r
    test = validate_ctrf(tmp_path / "r.json")["results"]["tests"][0]
    assert "16777217 bytes, more than the 16777216 bytes a file may have" in test["message"], test
    assert not (tmp_path / "rtf-attachments").exists()  # refused before anything is written


def test_the_run_limit_holds_across_workers_running_at_once(tmp_path):
    """Four 400-byte files against a run limit of 1000 bytes, two suites at once in worker
    processes: two are attached, the other two are errors naming the run's limit."""
    (tmp_path / "part.log").write_text("x" * 400)
    for name in ("a", "b"):
        (tmp_path / f"{name}.xml").write_text(
            f'<suite name="{name}">\n' + "\n".join(
                f'  <test name="{name}{i}" param="attach part.log">{plugin("measuring_test")}</test>'
                for i in (1, 2)) + "\n</suite>\n")
    r = run_runner("-j", "2", "--suite", "a.xml", "--suite", "b.xml", "-o", "json:r.json",
                   cwd=tmp_path, env={"RTF_ATTACHMENT_MAX_RUN": "1000"})
    assert r.returncode == 1, r
    tests = validate_ctrf(tmp_path / "r.json")["results"]["tests"]
    attached = [t for t in tests if t.get("attachments")]
    refused = [t for t in tests if "RTF_ATTACHMENT_MAX_RUN" in t.get("message", "")]
    assert len(attached) == 2 and len(refused) == 2, tests
    stored = sum(p.stat().st_size for p in (tmp_path / "rtf-attachments").iterdir()
                 if p.name != ".lock")
    assert stored == 800


@pytest.mark.parametrize("isolation", ["none", "process"])
def test_the_live_page_shows_measurements_as_they_come_and_links_attachments_at_the_end(
        tmp_path, isolation):
    import json

    from web_run import WebRun, poll, request

    (tmp_path / "plot.svg").write_text(SVG)
    test = tmp_path / "arm.sh"
    test.write_text("#!/bin/sh\n"
                    "printf 'TAP version 14\\n1..1\\nok 1 - tracks\\n  ---\\n  measurements:\\n"
                    "    - name: tracking error\\n      value: 0.012\\n      unit: rad\\n"
                    "  attachments:\\n    - path: plot.svg\\n  ...\\n'\n"
                    "i=0; while [ ! -e go ] && [ $i -lt 1200 ]; do sleep 0.05; i=$((i+1)); done\n")
    test.chmod(0o755)
    run = WebRun("--isolation", isolation, "--test", "arm.sh", "--web-linger", "60", cwd=tmp_path)
    try:
        def measured():
            snapshot = json.loads(request(run.port, "/snapshot")[2])
            tests = [t for s in snapshot["suites"] for t in s["tests"]]
            return tests and tests[0]["state"] == "running" and any(
                m["kind"] == "measurement" and m["text"] == "tracking error = 0.012 rad"
                for m in tests[0]["messages"]) and snapshot
        snapshot = poll(measured, what="the measurement while the test runs")
        assert "attachments" not in snapshot["run"], snapshot  # linked when the run ends
        (tmp_path / "go").write_text("")
        run.wait_for_line("final page stays")
        final = json.loads(request(run.port, "/snapshot")[2])["run"]
        assert [(a["name"], a["url"]) for a in final["attachments"]] == [
            ("plot.svg", "/attachments/0")], final
        status, headers, body = request(run.port, "/attachments/0")
        assert status == 200 and body == SVG and headers["Content-Type"] == "image/svg+xml"
        assert request(run.port, "/attachments/1")[0] == 404
        assert request(run.port, "/attachments/..%2fplot.svg")[0] == 404
        run.proc.send_signal(2)
        assert run.wait(timeout=10) == 0, run.output()
    finally:
        run.kill()
