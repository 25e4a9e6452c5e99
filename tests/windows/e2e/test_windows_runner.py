"""The Windows runner on a real suite, from the suite's folder with relative paths, in its own
process (--isolation none): passing and failing plug-ins, a fixture, every report format read
back on Linux; the run history (SQLite); and what the Windows build does not have, said
clearly."""
import json
import sqlite3
import xml.etree.ElementTree as ET

from conftest import (copy_plugins, run_runner, start_runner, stop_runner, validate_ctrf,
                      validate_junit, validate_tap, windows_path)

SUITE = """<?xml version="1.0" encoding="UTF-8"?>
<suite name="Windows suite">
    <fixture param="--log fixture.log --name arm">../plugins/order_fixture.dll</fixture>
    <test type="dll">../plugins/passing_test.dll</test>
    <test>failing_test</test>
</suite>
"""


def write_project(tmp_path):
    """suites/suite.xml naming ../plugins/ relatively, and failing_test by bare name (found
    beside the suite, with MinGW's lib prefix)."""
    copy_plugins(tmp_path / "plugins", "passing_test.dll", "order_fixture.dll")
    copy_plugins(tmp_path / "suites", "libfailing_test.dll")
    (tmp_path / "suites" / "suite.xml").write_text(SUITE)
    return tmp_path / "suites"


def test_suite_runs_and_every_report_is_written_and_reads_back(tmp_path):
    suites = write_project(tmp_path)
    (suites / "out").mkdir()
    run = run_runner("-s", "suite.xml", "--isolation", "none", "-o", "junit:out/r.xml",
                     "-o", "text:out/r.txt", "-o", "tap:out/r.tap", "-o", "json:out/r.json",
                     "-o", "html:out/r.html", cwd=suites)
    assert run.returncode == 1, run  # a test failed
    assert "1 passed, 1 failed" in run.stdout, run

    out = suites / "out"
    validate_junit(out / "r.xml")
    root = ET.parse(out / "r.xml").getroot()
    cases = root.findall(".//testcase")
    failed = [case for case in cases if case.find("failure") is not None]
    assert len(failed) == 1 and "two and two make five" in failed[0].find("failure").get(
        "message", "") + (failed[0].find("failure").text or ""), ET.tostring(root).decode()
    assert root.get("tests") == "2" and root.get("failures") == "1", root.attrib

    tap = validate_tap(out / "r.tap")
    assert tap["ok"] is False and tap["fail"] == 1, tap

    ctrf = validate_ctrf(out / "r.json")
    summary = ctrf["results"]["summary"]
    assert (summary["tests"], summary["passed"], summary["failed"]) == (2, 1, 1), summary

    text = (out / "r.txt").read_text()
    assert "PassingTest" in text and "FailingTest" in text and "1 passed, 1 failed" in text, text

    html = (out / "r.html").read_text()
    assert html.lstrip().lower().startswith("<!doctype html"), html[:200]
    assert "Windows suite" in html and "two and two make five" in html

    # The fixture was set up, checked before each test and torn down, in the suite's folder
    # (its relative --log).
    assert (suites / "fixture.log").read_text().splitlines() == [
        "setup arm", "check arm", "check arm", "teardown arm"], (suites / "fixture.log").read_text()


def test_what_a_test_prints_in_process_goes_to_the_reports_not_the_console(tmp_path):
    """Descriptors 1 and 2 pointed at the capture file (platform/output_file-windows.cpp) and
    read back per test: printf, iostream and stderr reach the JUnit <system-out> of the test
    that printed them, and the console only with -v."""
    copy_plugins(tmp_path, "printing_test.dll")
    run = run_runner("-t", "printing_test.dll", "--isolation", "none", "-o", "junit:r.xml",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    validate_junit(tmp_path / "r.xml")
    case = ET.parse(tmp_path / "r.xml").getroot().find(".//testcase")
    printed = case.findtext("system-out") or ""
    for line in ("printf line from the test", "iostream line from the test",
                 "stderr line from the test"):
        assert line in printed, printed
    assert "printf line from the test" not in run.stdout, run

    verbose = run_runner("-t", "printing_test.dll", "--isolation", "none", "-v", cwd=tmp_path)
    assert verbose.returncode == 0, verbose
    assert "stderr line from the test" in verbose.stdout, verbose


def test_plugin_path_is_a_semicolon_list_of_windows_folders(tmp_path):
    copy_plugins(tmp_path / "plugins", "passing_test.dll")
    suites = tmp_path / "suites"
    suites.mkdir()
    (suites / "suite.xml").write_text(
        '<suite name="path"><test>passing_test</test></suite>\n')
    # Split on ':' the first folder would end in ";C" and not be found.
    plugin_path = windows_path(tmp_path / "plugins") + ";C:\\no\\such\\folder"
    run = run_runner("-s", "suite.xml", "--isolation", "none", "--no-output", cwd=suites,
                     env={"RTF_PLUGIN_PATH": plugin_path})
    assert run.returncode == 0, run
    assert "1 passed, 0 failed" in run.stdout, run


def test_python_and_ruby_tests_say_they_are_not_built_for_windows(tmp_path):
    (tmp_path / "check.py").write_text("def test():\n    pass\n")
    (tmp_path / "check.rb").write_text("puts 1\n")
    for name, language in (("check.py", "Python"), ("check.rb", "Ruby")):
        run = run_runner("-t", name, "--isolation", "none", "--no-output", cwd=tmp_path)
        assert run.returncode != 0, run
        assert f"{language} tests are not built for Windows" in run.output, run


def history_rows(path):
    """(test, state) of every result in the history file, oldest run first: read on Linux with
    Python's own SQLite, so the file the Windows runner wrote is an ordinary SQLite database."""
    with sqlite3.connect(path) as db:
        return db.execute(
            "SELECT t.name, r.state FROM results r JOIN tests t ON t.id = r.test "
            "JOIN runs u ON u.id = r.run ORDER BY u.started, u.id, t.name").fetchall()


def report_data(html):
    text = html.read_text()
    return json.loads(text.split('id="report-data">', 1)[1].split("</script>", 1)[0])


def test_history_is_appended_reported_and_shown_in_the_html_report(tmp_path):
    """--history h.db on Windows: SQLite built from Debian's source package, statically."""
    suites = write_project(tmp_path)
    for _ in range(2):
        run = run_runner("-s", "suite.xml", "--isolation", "none", "--history", "h.db",
                         "-o", "html:r.html", cwd=suites)
        assert run.returncode == 1, run  # a test failed, each time
        assert "history" not in run.stderr, run

    # Test ids as on Linux: the suite's name, then the test as the suite names it, a plug-in
    # beside the suite's folder said from the folder both share (no ".." in an id).
    passing, failing = "Windows suite/plugins/passing_test.dll", "Windows suite/failing_test"
    assert history_rows(suites / "h.db") == [(failing, "failed"), (passing, "passed")] * 2

    report = run_runner("--history", "h.db", "--history-report", cwd=suites)
    assert report.returncode == 0, report
    assert "2 tests in the last 2 runs" in report.stdout, report
    # The same outcome both times: neither test is flaky.
    flakiest = report.stdout.split("Flakiest tests", 1)[1].split("Tests that failed", 1)[0]
    assert "Windows suite/" not in flakiest, report
    # The failing test failed both runs: listed as such, not as flaky.
    always = report.stdout.split("Tests that failed every run", 1)[1].split("Most slowed", 1)[0]
    assert failing in always and passing not in always, report

    html = suites / "r.html"
    assert "window.rtfTrends = " in html.read_text()  # trends.js, which draws the strips
    tests = report_data(html)["suites"][0]["tests"]
    strips = sorted((t["history"]["states"], t["history"]["flakyRate"]) for t in tests)
    assert strips == [(["failed", "failed"], 0), (["passed", "passed"], 0)], tests


def test_runs_at_the_same_time_append_to_one_history(tmp_path):
    """Three runners writing h.db at once: WAL and the busy timeout over Wine's file locks and
    shared memory, none of them failing with "database is locked"."""
    suites = write_project(tmp_path)
    runners = [start_runner("-s", "suite.xml", "--isolation", "none", "--history", "h.db",
                            "--no-output", cwd=suites) for _ in range(3)]
    try:
        for runner in runners:
            out, err = runner.communicate(timeout=120)
            assert runner.returncode == 1, out + err  # the failing test, not the history
            assert "history" not in err, err
    finally:
        for runner in runners:
            stop_runner(runner)
    with sqlite3.connect(suites / "h.db") as db:
        assert db.execute("PRAGMA journal_mode").fetchone() == ("wal",)
        assert db.execute("SELECT count(*) FROM runs").fetchone() == (3,)
        assert db.execute("SELECT count(*) FROM results").fetchone() == (6,)


def test_a_damaged_history_file_is_an_error_naming_it(tmp_path):
    suites = write_project(tmp_path)
    garbage = b"garbage, not a database" * 10
    (suites / "h.db").write_bytes(garbage)
    run = run_runner("-s", "suite.xml", "--isolation", "none", "--history", "h.db",
                     "-o", "junit:r.xml", cwd=suites)
    assert run.returncode == 2, run
    assert "--history h.db: not a history file" in run.stderr, run
    assert not (suites / "r.xml").exists()  # nothing ran, as on Linux
    assert (suites / "h.db").read_bytes() == garbage  # and the file is as it was
    report = run_runner("--history", "h.db", "--history-report", cwd=suites)
    assert report.returncode == 2 and "h.db" in report.stderr, report
