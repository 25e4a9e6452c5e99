"""One id per test (docs/reference/test-ids.md): made from the suite file alone, the same on the console,
in every output, in --list, --filter and --rerun-failed, and in a moved copy of the workspace.
Run from the suite's own folder with relative paths, as users do."""
import json
import re
import shutil
import xml.etree.ElementTree as ET

import pytest

from conftest import junit_display_names, run_runner, validate_ctrf, validate_junit, validate_tap

# Fails when its param says --fail (or, with --break-on K, on its K-th run in the process).
CHECK = """import robottestingframework
class TestCase:
    def setup(self, param):
        self.words = param.split()
        self.k = 0
        return True
    def run(self):
        self.k += 1
        robottestingframework.testCheck("--fail" not in self.words, "asked to fail")
        robottestingframework.testCheck(" ".join(self.words[-2:]) != "--break-on %d" % self.k,
                                        "broken on run %d" % self.k)
"""

# Names itself: its display name, never its id.
RENAMING = """import robottestingframework
class TestCase:
    def setup(self, param):
        robottestingframework.setName("joint limits")
        return True
    def run(self):
        robottestingframework.testCheck(False, "the limits are exceeded")
"""

SUITE = """<suite name="arm-bench">
  <variable name="tools">{tools}</variable>
  <test type="python">../tests/../tests/limits.py</test>
  <test type="python" name="gripper">${{tools}}/check.py</test>
  <test type="python" param="--speed 1">../tests/check.py</test>
  <test type="python" param="--speed 2 --fail">../tests/check.py</test>
  <test type="python">../tests/check.py</test>
  <test type="python">../tests/check.py</test>
  <test type="python" repetition="3" param="--break-on 2">${{tools}}/repeated.py</test>
</suite>
"""

IDS = ["arm-bench/tests/limits.py", "arm-bench/gripper",
       "arm-bench/tests/check.py[--speed 1]", "arm-bench/tests/check.py[--speed 2 --fail]",
       "arm-bench/tests/check.py", "arm-bench/tests/check.py[2]", "arm-bench/repeated.py"]
FAILED = {"arm-bench/tests/limits.py", "arm-bench/tests/check.py[--speed 2 --fail]",
          "arm-bench/repeated.py"}


def workspace(root):
    """proj/suites/arm.xml, proj/tests/*.py, and a tools folder outside the project given by
    an absolute path (as a build tree's would be)."""
    (root / "proj" / "suites").mkdir(parents=True)
    (root / "proj" / "tests").mkdir()
    tools = root / "tools"
    tools.mkdir()
    (root / "proj" / "tests" / "limits.py").write_text(RENAMING)
    (root / "proj" / "tests" / "check.py").write_text(CHECK)
    (tools / "check.py").write_text(CHECK)
    (tools / "repeated.py").write_text(CHECK)
    (root / "proj" / "suites" / "arm.xml").write_text(SUITE.format(tools=tools))
    return root / "proj" / "suites"


def listed_ids(folder, *args):
    r = run_runner("--suite", "arm.xml", "--list", "--output", "json:list.json", *args,
                   cwd=folder)
    assert r.returncode == 0, r
    tests = json.loads((folder / "list.json").read_text())["suites"]
    return [t["id"] for s in tests for t in s["tests"]], r


def test_every_output_names_a_test_by_its_one_id(tmp_path):
    folder = workspace(tmp_path)
    ids, listing = listed_ids(folder)
    assert ids == IDS, ids

    r = run_runner("--suite", "arm.xml", "-o", "junit:r.xml", "-o", "json:r.json",
                   "-o", "tap:r.tap", "-o", "html:r.html", "-o", "text:r.txt", cwd=folder)
    assert r.returncode == 1, r
    local = [i.split("/", 1)[1] for i in IDS]
    # The console: the id as --filter takes it, then the name the test gives itself.
    assert "FAILED      arm-bench/tests/limits.py (joint limits)  (" in r.stdout, r.stdout
    # A script's default name (its absolute path) is not shown beside the id.
    assert "passed      arm-bench/tests/check.py[--speed 1]  (" in r.stdout, r.stdout
    assert "FAILED      arm-bench/repeated.py  (" in r.stdout, r.stdout
    result_lines = [line for line in r.stdout.splitlines() if re.match(r"^  (passed|FAILED) ", line)]
    assert len(result_lines) == 7 and not any(str(tmp_path) in line for line in result_lines), \
        r.stdout
    assert "tests/limits.py (joint limits)" in (folder / "r.txt").read_text()

    validate_junit(folder / "r.xml")
    root = ET.parse(folder / "r.xml").getroot()
    cases = list(root.iter("testcase"))
    assert [(c.get("classname"), c.get("name")) for c in cases] == [
        ("arm-bench", name) for name in local]
    assert junit_display_names(root).get(cases[0]) == "joint limits", ET.tostring(root)

    report = validate_ctrf(folder / "r.json")
    tests = report["results"]["tests"]
    assert [(t["suite"], t["name"], t["extra"]["robotology.rtf"]["id"]) for t in tests] == [
        (["arm-bench"], name, full) for name, full in zip(local, IDS)]
    assert tests[0]["extra"]["robotology.rtf"]["name"] == "joint limits"
    assert [p["name"] for p in tests[6]["extra"]["robotology.rtf"]["repetitions"]] == [
        "arm-bench/repeated.py#1", "arm-bench/repeated.py#2", "arm-bench/repeated.py#3"]

    validate_tap(folder / "r.tap")
    points = re.findall(r"^\s+(?:not )?ok \d+ - (.*)$", (folder / "r.tap").read_text(), re.M)
    assert points == local, points

    html = (folder / "r.html").read_text()
    data = json.loads(html.split('id="report-data">', 1)[1].split("</script>", 1)[0])
    assert [t["name"] for t in data["suites"][0]["tests"]] == local
    assert data["suites"][0]["tests"][0]["shown"] == "joint limits"


def test_each_id_written_as_shown_selects_that_test_alone(tmp_path):
    folder = workspace(tmp_path)
    for test_id in IDS:
        ids, _ = listed_ids(folder, "--filter", test_id)
        assert ids == [test_id], (test_id, ids)
    # A hyphen of a pattern is written \-; unescaped it starts the negative patterns.
    ids, _ = listed_ids(folder, "--filter", r"arm\-bench/*check.py[\-\-speed*")
    assert ids == IDS[2:4], ids
    ids, _ = listed_ids(folder, "--filter", "arm-bench/*")
    assert ids == [], ids


def test_a_rerun_from_a_moved_workspace_runs_exactly_what_failed(tmp_path):
    folder = workspace(tmp_path / "first")
    first = run_runner("--suite", "arm.xml", "-o", "junit:r1.xml", "-o", "json:r1.json",
                       cwd=folder)
    assert first.returncode == 1, first
    moved = tmp_path / "moved"
    shutil.copytree(tmp_path / "first", moved)
    shutil.rmtree(tmp_path / "first")
    for report in ("r1.xml", "r1.json"):
        # The tools moved too: the build tree's path differs, the ids do not.
        again = run_runner("--suite", "arm.xml", "--rerun-failed", report, "-o", "json:r2.json",
                           "--var", f"tools={moved / 'tools'}", cwd=moved / "proj" / "suites")
        assert again.returncode == 1, again
        ran = validate_ctrf(moved / "proj" / "suites" / "r2.json")["results"]["tests"]
        assert {t["extra"]["robotology.rtf"]["id"] for t in ran} == FAILED, (report, ran)


def test_a_rerun_report_without_failures_runs_nothing_and_passes(tmp_path, suite_file):
    (tmp_path / "ok.py").write_text(CHECK)
    suite_file('<suite name="s"><test type="python">ok.py</test></suite>')
    assert run_runner("--suite", "suite.xml", "-o", "junit:r.xml", cwd=tmp_path).returncode == 0
    again = run_runner("--suite", "suite.xml", "--rerun-failed", "r.xml", cwd=tmp_path)
    assert again.returncode == 0, again
    assert "r.xml has no failed test: nothing to rerun" in again.stdout, again


def test_a_rerun_whose_failures_are_not_in_this_run_is_an_error(tmp_path, suite_file):
    (tmp_path / "bad.py").write_text(CHECK)
    suite_file('<suite name="s"><test type="python" param="--fail">bad.py</test></suite>')
    suite_file('<suite name="other"><test type="python">bad.py</test></suite>', "other.xml")
    assert run_runner("--suite", "suite.xml", "-o", "json:r.json", cwd=tmp_path).returncode == 1
    again = run_runner("--suite", "other.xml", "--rerun-failed", "r.json", cwd=tmp_path)
    assert again.returncode == 2, again
    assert "--rerun-failed r.json: none of its 1 failed test(s) is a test of this run (s/bad.py" \
        in again.stderr, again


@pytest.mark.edited_reports  # it cuts and forges reports on purpose
def test_a_truncated_or_foreign_rerun_report_is_an_error_naming_it(tmp_path, suite_file):
    (tmp_path / "bad.py").write_text(CHECK)
    suite_file('<suite name="s"><test type="python" param="--fail">bad.py</test></suite>')
    assert run_runner("--suite", "suite.xml", "-o", "junit:r.xml", cwd=tmp_path).returncode == 1
    text = (tmp_path / "r.xml").read_text()
    (tmp_path / "cut.xml").write_text(text[:len(text) // 2])
    (tmp_path / "pytest.xml").write_text(
        '<testsuites><testsuite name="pytest" tests="1"><testcase classname="s" name="bad.py">'
        '<failure message="x"/></testcase></testsuite></testsuites>')
    for report in ("cut.xml", "pytest.xml", "missing.xml"):
        again = run_runner("--suite", "suite.xml", "--rerun-failed", report, cwd=tmp_path)
        assert again.returncode == 2, again
        assert f"--rerun-failed {report}" in again.stderr, again


def test_an_empty_selection_exits_5_unless_allowed(tmp_path, suite_file):
    (tmp_path / "ok.py").write_text(CHECK)
    suite_file('<suite name="s"><test type="python">ok.py</test></suite>')
    r = run_runner("--suite", "suite.xml", "--filter", "s/nomatch", cwd=tmp_path)
    assert r.returncode == 5, r
    assert "no test is selected" in r.stderr and "--allow-empty" in r.stderr, r
    r = run_runner("--suite", "suite.xml", "--filter", "s/nomatch", "--allow-empty",
                   cwd=tmp_path)
    assert r.returncode == 0, r
    # A shard with no suite of its own is not an empty selection.
    r = run_runner("--suite", "suite.xml", "--shard-index", "1", "--shard-count", "2",
                   cwd=tmp_path)
    assert r.returncode == 0, r
    assert "has no suite to run" in r.stdout, r


def test_a_filter_that_cannot_parse_is_an_error_naming_it(tmp_path, suite_file):
    (tmp_path / "ok.py").write_text(CHECK)
    suite_file('<suite name="s"><test type="python">ok.py</test></suite>')
    for pattern in ("s/a::b", "s/ok\\"):
        r = run_runner("--suite", "suite.xml", "--filter", pattern, cwd=tmp_path)
        assert r.returncode == 2, r
        assert f"--filter {pattern}: " in r.stderr, r


def test_the_closing_line_counts_a_failed_fixture_as_failed(tmp_path, suite_file):
    (tmp_path / "ok.py").write_text(CHECK)
    suite_file("""<suite name="s">
  <fixture type="dll">no_such_fixture</fixture>
  <test type="python">ok.py</test>
  <test type="python" param="--x">ok.py</test>
</suite>""")
    r = run_runner("--suite", "suite.xml", "-o", "text:r.txt", cwd=tmp_path)
    assert r.returncode == 1, r
    assert "0 passed, 1 failed, 2 skipped" in r.stdout, r.stdout
    assert "0 passed, 1 failed, 2 skipped" in (tmp_path / "r.txt").read_text()
