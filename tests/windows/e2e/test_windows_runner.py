"""The Windows runner on a real suite, from the suite's folder with relative paths, in its own
process (--isolation none): passing and failing plug-ins, a fixture, every report format read
back on Linux; and what the Windows build does not have, said clearly."""
import xml.etree.ElementTree as ET

from conftest import (copy_plugins, run_runner, validate_ctrf, validate_junit, validate_tap,
                      windows_path)

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


def test_history_says_it_is_not_built_in(tmp_path):
    copy_plugins(tmp_path, "passing_test.dll")
    run = run_runner("-t", "passing_test.dll", "--isolation", "none", "--history", "h.db",
                     cwd=tmp_path)
    assert run.returncode == 2, run
    assert "--history h.db: the run history is not built into this runner" in run.stderr, run
    assert not (tmp_path / "h.db").exists()
