"""--retries, flaky tests, --fail-on-flaky, --rerun-failed and --repeat-until-fail, through the
real runner."""
import xml.etree.ElementTree as ET

import pytest

from conftest import run_runner, validate_ctrf, validate_junit, validate_tap
from lang_cases import ISOLATIONS


@pytest.fixture(params=ISOLATIONS)
def isolation(request):
    return request.param


def counting_script(folder, name, fail_until):
    """An exec test that counts its runs in a file and fails its first `fail_until` runs."""
    counter = folder / (name + ".count")
    path = folder / name
    path.write_text(f"""#!/bin/sh
n=$(cat '{counter}' 2>/dev/null || echo 0)
n=$((n + 1))
echo $n > '{counter}'
echo "run $n"
if [ $n -le {fail_until} ]; then echo "failing run $n" >&2; exit 3; fi
exit 0
""")
    path.chmod(0o755)
    return path, counter


def suite_of(folder, tests):
    body = "\n".join(f'  <test type="exec" name="{name}">{path}</test>' for name, path in tests)
    suite = folder / "suite.xml"
    suite.write_text(f'<suite name="reruns">\n{body}\n</suite>\n')
    return suite


def test_a_test_passing_on_its_second_attempt_is_flaky(tmp_path, isolation):
    flaky, counter = counting_script(tmp_path, "flaky", 1)
    steady, _ = counting_script(tmp_path, "steady", 0)
    suite = suite_of(tmp_path, [("flaky", flaky), ("steady", steady)])
    junit, ctrf, tap = tmp_path / "r.xml", tmp_path / "r.json", tmp_path / "r.tap"
    r = run_runner("--isolation", isolation, "--suite", suite, "--retries", "2",
                   "-o", f"junit:{junit}", "-o", f"json:{ctrf}", "-o", f"tap:{tap}")
    assert r.returncode == 0, r
    assert counter.read_text().strip() == "2", r
    assert "flaky" in r.stdout, r
    validate_junit(junit)
    cases = ET.parse(junit).getroot().findall(".//testcase")
    assert [c.get("name") for c in cases] == ["flaky", "steady"]
    assert cases[0].get("status") == "flaky"
    earlier = cases[0].findall("flakyFailure")
    assert len(earlier) == 1 and "status 3" in earlier[0].get("message"), ET.tostring(cases[0])
    assert cases[0].find("failure") is None and cases[0].find("rerunFailure") is None
    assert ET.parse(junit).getroot().get("failures") == "0"
    report = validate_ctrf(ctrf)
    tests = {t["name"]: t for t in report["results"]["tests"]}
    assert tests["flaky"]["flaky"] is True and tests["flaky"]["retries"] == 1
    assert tests["flaky"]["status"] == "passed"
    assert tests["steady"]["flaky"] is False and tests["steady"]["retries"] == 0
    parsed = validate_tap(tap)
    assert parsed["ok"] is True, parsed
    assert "flaky: true" in tap.read_text()
    assert tap.read_text().count("- flaky") == 1


def test_fail_on_flaky_makes_a_flaky_test_fail_the_run(tmp_path):
    flaky, _ = counting_script(tmp_path, "flaky", 1)
    r = run_runner("--no-output", "--suite", suite_of(tmp_path, [("flaky", flaky)]),
                   "--retries", "1", "--fail-on-flaky")
    assert r.returncode == 1, r


def test_a_test_that_always_fails_carries_its_reruns(tmp_path, isolation):
    broken, counter = counting_script(tmp_path, "broken", 1000)
    junit, ctrf, tap = tmp_path / "r.xml", tmp_path / "r.json", tmp_path / "r.tap"
    r = run_runner("--isolation", isolation, "--suite", suite_of(tmp_path, [("broken", broken)]),
                   "--retries", "2", "-o", f"junit:{junit}", "-o", f"json:{ctrf}",
                   "-o", f"tap:{tap}")
    assert r.returncode == 1, r
    assert counter.read_text().strip() == "3", r
    validate_junit(junit)
    cases = ET.parse(junit).getroot().findall(".//testcase")
    assert len(cases) == 1, ET.tostring(ET.parse(junit).getroot())
    assert cases[0].find("failure") is not None
    assert len(cases[0].findall("rerunFailure")) == 2
    assert cases[0].find("flakyFailure") is None
    test = validate_ctrf(ctrf)["results"]["tests"][0]
    assert test["status"] == "failed" and test["retries"] == 2 and test["flaky"] is False
    parsed = validate_tap(tap)
    assert parsed["fail"] == 1 and parsed["count"] == 1, parsed


@pytest.mark.parametrize("value", ["-1", "abc", "101"])
def test_invalid_retries_exit_2_with_the_limits(tmp_path, value):
    steady, _ = counting_script(tmp_path, "steady", 0)
    r = run_runner("--no-output", "--test", steady, "--retries", value)
    assert r.returncode == 2, r
    assert "100" in r.stderr and "--retries" in r.stderr, r


@pytest.mark.parametrize("kind", ["junit", "json"])
def test_rerun_failed_runs_only_what_failed_in_a_report(tmp_path, kind, isolation):
    broken, broken_count = counting_script(tmp_path, "broken", 1)
    steady, steady_count = counting_script(tmp_path, "steady", 0)
    suite = suite_of(tmp_path, [("broken", broken), ("steady", steady)])
    report = tmp_path / f"first.{kind}"
    first = run_runner("--isolation", isolation, "--suite", suite, "-o", f"{kind}:{report}")
    assert first.returncode == 1, first
    again = run_runner("--isolation", isolation, "--suite", suite, "--rerun-failed", report,
                       "--no-output")
    assert again.returncode == 0, again
    assert broken_count.read_text().strip() == "2", again
    assert steady_count.read_text().strip() == "1", again
    assert "1 passed, 0 failed" in again.stdout, again


@pytest.mark.parametrize("kind", ["junit", "json"])
def test_rerun_failed_with_no_failure_has_nothing_to_rerun(tmp_path, kind):
    steady, steady_count = counting_script(tmp_path, "steady", 0)
    suite = suite_of(tmp_path, [("steady", steady)])
    report = tmp_path / f"first.{kind}"
    assert run_runner("--suite", suite, "-o", f"{kind}:{report}").returncode == 0
    again = run_runner("--suite", suite, "--rerun-failed", report, "--no-output")
    assert again.returncode == 0, again
    assert "nothing to rerun" in again.output, again
    assert steady_count.read_text().strip() == "1", again


@pytest.mark.parametrize("content,why", [
    (None, "cannot read"),
    ("<testsuites name='other'/>", "not a JUnit output of this runner"),
    ('{"reportFormat": "CTRF", "generatedBy": "jest", "results": {"tests": []}}',
     "not a JSON (CTRF) output of this runner"),
    ("<testsuites", "not valid XML"),
    ("{", "not valid JSON"),
    ("TAP version 14\n1..0\n", "not a JUnit (XML) or JSON (CTRF)"),
    # Found by fuzzing (tests/fuzz-regressions/rerun_report/): a number too large for a double.
    ('{"reportFormat": "CTRF", "results": {"tests": []}, "x": 1e999}', "not valid JSON"),
    # Found by fuzzing (tests/fuzz-regressions/rerun_report/): a bare JSON type error.
    ('{"reportFormat": "CTRF", "generatedBy": "robottestingframework-testrunner", '
     '"results": {"tests": [{"name": "a", "extra": {"rtf": {"state": 3}}}]}}',
     "results.tests[0]: expected a test"),
    ('{"reportFormat": "CTRF", "generatedBy": "robottestingframework-testrunner", '
     '"results": {"tests": [{"name": "a", "testId": "1.1", "duration": 1, "status": "failed", '
     '"extra": {"rtf": {"state": "failed"}}}, 7]}}',
     "results.tests[1]: expected a test"),
    ('{"reportFormat": {}, "generatedBy": "robottestingframework-testrunner", '
     '"results": {"tests": []}}', "not a JSON (CTRF) output of this runner"),
])
def test_rerun_failed_on_a_missing_or_foreign_report_exits_2(tmp_path, content, why):
    steady, _ = counting_script(tmp_path, "steady", 0)
    report = tmp_path / "report"
    if content is not None:
        report.write_text(content)
    r = run_runner("--suite", suite_of(tmp_path, [("steady", steady)]), "--rerun-failed",
                   report, "--no-output")
    assert r.returncode == 2, r
    assert why in r.stderr and str(report) in r.stderr, r


def test_repeat_until_fail_stops_at_the_first_failing_round(tmp_path, isolation):
    third, counter = counting_script(tmp_path, "third", 0)
    # Passes twice, fails on its 3rd run.
    third.write_text(third.read_text().replace("-le 0", "-eq 3"))
    r = run_runner("--isolation", isolation, "--no-output",
                   "--suite", suite_of(tmp_path, [("third", third)]), "--repeat-until-fail", "10")
    assert r.returncode == 1, r
    assert counter.read_text().strip() == "3", r
    assert "round 3 of 10 failed" in r.output or "round 3 failed" in r.output, r


def test_repeat_until_fail_runs_n_rounds_when_all_pass(tmp_path):
    steady, counter = counting_script(tmp_path, "steady", 0)
    r = run_runner("--no-output", "--suite", suite_of(tmp_path, [("steady", steady)]),
                   "--repeat-until-fail", "4")
    assert r.returncode == 0, r
    assert counter.read_text().strip() == "4", r


@pytest.mark.parametrize("value,limit", [("0", ">= 1"), ("x", ">= 1"),
                                         ("1000000001", "at most 1000000000")])
def test_invalid_repeat_until_fail_exits_2_with_the_limits(tmp_path, value, limit):
    steady, _ = counting_script(tmp_path, "steady", 0)
    r = run_runner("--no-output", "--test", steady, "--repeat-until-fail", value)
    assert r.returncode == 2, r
    assert limit in r.stderr and "--repeat-until-fail" in r.stderr, r


def test_fail_fast_waits_for_the_last_attempt(tmp_path):
    flaky, _ = counting_script(tmp_path, "flaky", 1)
    steady, steady_count = counting_script(tmp_path, "steady", 0)
    r = run_runner("--no-output", "--suite", suite_of(tmp_path, [("flaky", flaky),
                                                                   ("steady", steady)]),
                   "--retries", "1", "--fail-fast")
    assert r.returncode == 0, r
    assert steady_count.read_text().strip() == "1", r


def test_flaky_is_its_own_state_on_the_console_and_in_html(tmp_path):
    flaky, _ = counting_script(tmp_path, "flaky", 1)
    html = tmp_path / "r.html"
    r = run_runner("--suite", suite_of(tmp_path, [("flaky", flaky)]), "--retries", "1",
                   "-o", f"html:{html}")
    assert r.returncode == 0, r
    assert "FLAKY" in r.stdout and "1 flaky" in r.stdout, r
    assert "retry: attempt 1 of 2 failed" in r.stdout, r
    page = html.read_text()
    assert '"state":"flaky"' in page and '"flaky":1' in page


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_retried_attempt_is_shown_as_retry_and_only_the_last_line_decides(tmp_path, isolation,
                                                                            jobs):
    # -j2 has a console of its own (one line per test as it ends, from any suite).
    flaky, _ = counting_script(tmp_path, "flaky", 1)
    broken, _ = counting_script(tmp_path, "broken", 99)
    r = run_runner("--isolation", isolation, "--no-output", "--retries", "2", "-j", jobs,
                   "--suite", suite_of(tmp_path, [("flaky", flaky), ("broken", broken)]))
    assert r.returncode == 1, r
    words = [line.split()[0] for line in r.stdout.splitlines()
             if line.startswith("  ") and not line.startswith("   ")
             and line.split()[0] in ("RETRY", "FAILED", "FLAKY", "passed", "flaky")
             and line.rstrip().endswith(" s)")]
    # flaky: one retried attempt then its final line; broken: two retried, then FAILED once.
    assert words == ["RETRY", "FLAKY", "RETRY", "RETRY", "FAILED"], r.stdout
