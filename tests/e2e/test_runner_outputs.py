"""Result files: text and JUnit (valid against schemas/junit.xsd), what tests print."""
import xml.etree.ElementTree as ET

from conftest import junit_display_names, plugin, run_runner, validate_junit


def test_default_output_is_result_txt_unless_no_output(tmp_path):
    run = run_runner("-t", plugin("passing_test"), cwd=tmp_path)
    assert run.returncode == 0, run
    text = (tmp_path / "result.txt").read_text()
    assert "PassingTest" in text and "1 passed, 0 failed" in text, text

    other = tmp_path / "quiet"
    other.mkdir()
    run = run_runner("-t", plugin("passing_test"), "--no-output", cwd=other)
    assert run.returncode == 0, run
    assert list(other.iterdir()) == [], list(other.iterdir())


def test_text_output_and_no_summary(tmp_path):
    out = tmp_path / "out.txt"
    run = run_runner("-t", plugin("failing_test"), "-o", out.name, "--output-type", "text",
                     cwd=tmp_path)
    assert run.returncode == 1, run
    text = out.read_text()
    assert "FailingTest" in text and "two and two make five" in text, text
    assert "0 passed, 1 failed" in text, text

    bare = tmp_path / "bare.txt"
    run = run_runner("-t", plugin("failing_test"), "-o", bare.name, "--no-summary", cwd=tmp_path)
    assert run.returncode == 1, run
    assert "FailingTest" in bare.read_text(), bare.read_text()
    assert "Summary" not in bare.read_text(), bare.read_text()


def test_junit_output_validates_and_carries_failures_and_output(tmp_path):
    out = tmp_path / "results.xml"
    run = run_runner("-t", plugin("passing_test"), "-t", plugin("failing_test"),
                     "-t", plugin("printing_test"), "-t", plugin("nasty_text_test"),
                     "-o", f"junit:{out.name}", cwd=tmp_path)
    assert run.returncode == 1, run
    validate_junit(out)
    root = ET.parse(out).getroot()
    # By the name each gives itself, kept beside the id as the suite's rtf.name.S.T property.
    cases = {name: case for case, name in junit_display_names(root).items()}
    assert set(cases) >= {"PassingTest", "FailingTest", "PrintingTest"}, cases.keys()
    assert cases["FailingTest"].find("failure") is not None
    assert cases["PassingTest"].find("failure") is None
    printed = cases["PrintingTest"].findtext("system-out") or ""
    assert "printf line from the test" in printed, printed
    assert "iostream line from the test" in printed, printed
    nasty = next(case for name, case in cases.items() if name.startswith("NastyTextTest"))
    assert nasty.find("failure") is not None
    # What the test printed did not reach the console.
    assert "printf line from the test" not in run.stdout, run


def test_output_type_junit_with_plain_file_name(tmp_path):
    out = tmp_path / "r.xml"
    run = run_runner("-t", plugin("passing_test"), "--output", out.name, "--output-type", "junit",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    validate_junit(out)


def test_several_outputs_at_once(tmp_path):
    run = run_runner("-t", plugin("passing_test"), "-o", "junit:a.xml", "-o", "text:b.txt",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    validate_junit(tmp_path / "a.xml")
    assert "PassingTest" in (tmp_path / "b.txt").read_text()


def test_verbose_console_shows_what_the_test_printed(tmp_path):
    run = run_runner("-t", plugin("printing_test"), "-v", cwd=tmp_path)
    assert run.returncode == 0, run
    assert "printf line from the test" in run.stdout, run
    assert "stderr line from the test" in run.stdout, run


def test_unwritable_output_is_reported_and_exits_two(tmp_path):
    # A missing folder is made (issue 40); one under a file cannot be, which is said before
    # the run.
    (tmp_path / "no").write_text("a file\n")
    run = run_runner("-t", plugin("passing_test"), "-o", "no/such/dir.txt", cwd=tmp_path)
    assert run.returncode == 2, run
    assert "--output text:no/such/dir.txt: cannot create the folder no/such" in run.stderr, run
    assert "passed" not in run.stdout, run


def test_no_summary_keeps_the_closing_line_on_the_console(tmp_path):
    full = run_runner("-t", plugin("passing_test"), "--no-output", cwd=tmp_path)
    assert "Summary" in full.stdout, full
    bare = run_runner("-t", plugin("passing_test"), "--no-output", "--no-summary", cwd=tmp_path)
    assert bare.returncode == 0, bare
    assert "Summary" not in bare.stdout, bare
    assert bare.stdout.rstrip().splitlines()[-1] == "1 passed, 0 failed", bare
