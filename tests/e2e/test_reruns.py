"""--retries, flaky tests, --fail-on-flaky, --rerun-failed and --repeat-until-fail, through the
real runner, run as users run it: from the suite's folder, every file named relatively."""
import json
import xml.etree.ElementTree as ET

import pytest

from conftest import junit_state, run_runner, validate_ctrf, validate_junit, validate_tap
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
    """Writes suite.xml beside the scripts, naming each as `./NAME`; returns its name, for a
    runner started in `folder`."""
    body = "\n".join(f'  <test type="exec" name="{name}">./{path.name}</test>'
                     for name, path in tests)
    suite = folder / "suite.xml"
    suite.write_text(f'<suite name="reruns">\n{body}\n</suite>\n')
    return suite.name


def test_a_test_passing_on_its_second_attempt_is_flaky(tmp_path, isolation):
    flaky, counter = counting_script(tmp_path, "flaky", 1)
    steady, _ = counting_script(tmp_path, "steady", 0)
    suite = suite_of(tmp_path, [("flaky", flaky), ("steady", steady)])
    junit, ctrf, tap = tmp_path / "r.xml", tmp_path / "r.json", tmp_path / "r.tap"
    r = run_runner("--isolation", isolation, "--suite", suite, "--retries", "2",
                   "-o", "junit:r.xml", "-o", "json:r.json", "-o", "tap:r.tap", cwd=tmp_path)
    assert r.returncode == 0, r
    assert counter.read_text().strip() == "2", r
    assert "flaky" in r.stdout, r
    validate_junit(junit)
    cases = ET.parse(junit).getroot().findall(".//testcase")
    assert [c.get("name") for c in cases] == ["flaky", "steady"]
    assert junit_state(cases[0]) == "flaky"
    earlier = cases[0].findall("flakyFailure")
    assert len(earlier) == 1 and "status 3" in earlier[0].get("message"), ET.tostring(cases[0])
    assert cases[0].find("failure") is None and cases[0].find("rerunFailure") is None
    # As Surefire writes an attempt (Jenkins shows its <stackTrace>): no text of its own.
    assert [child.tag for child in earlier[0]] == ["stackTrace", "system-out"], ET.tostring(cases[0])
    assert "status 3" in earlier[0].find("stackTrace").text, ET.tostring(cases[0])
    assert "run 1" in earlier[0].find("system-out").text, ET.tostring(cases[0])
    assert not (earlier[0].text or "").strip(), ET.tostring(cases[0])
    properties = ET.parse(junit).getroot().find("testsuite/properties")
    assert [(p.get("name"), p.get("value")) for p in properties
            if p.get("name").startswith("rtf.state.")] == [("rtf.state.1.1", "flaky")]
    assert ET.parse(junit).getroot().get("failures") == "0"
    report = validate_ctrf(ctrf)
    tests = {t["name"]: t for t in report["results"]["tests"]}
    assert tests["flaky"]["flaky"] is True and tests["flaky"]["retries"] == 1
    # CTRF's retryAttempts: one entry per earlier attempt, numbered from 1; retries counts them.
    (attempt,) = tests["flaky"]["retryAttempts"]
    assert attempt["attempt"] == 1 and attempt["status"] == "failed", attempt
    assert "status 3" in attempt["message"] and "status 3" in attempt["trace"], attempt
    assert "run 1" in attempt["stdout"] and attempt["duration"] >= 0, attempt
    assert "retryAttempts" not in tests["steady"]
    # The extension key is namespaced (CTRF 4.6.1), and the same in every extra.
    assert list(tests["flaky"]["extra"]) == ["robotology.rtf"], tests["flaky"]
    assert list(attempt["extra"]) == ["robotology.rtf"], attempt
    assert tests["flaky"]["status"] == "passed"
    assert tests["steady"]["flaky"] is False and tests["steady"]["retries"] == 0
    parsed = validate_tap(tap)
    assert parsed["ok"] is True, parsed
    assert "flaky: true" in tap.read_text()
    assert tap.read_text().count("- flaky") == 1


def test_fail_on_flaky_makes_a_flaky_test_fail_the_run(tmp_path):
    flaky, _ = counting_script(tmp_path, "flaky", 1)
    r = run_runner("--no-output", "--suite", suite_of(tmp_path, [("flaky", flaky)]),
                   "--retries", "1", "--fail-on-flaky", cwd=tmp_path)
    assert r.returncode == 1, r


def test_a_test_that_always_fails_carries_its_reruns(tmp_path, isolation):
    broken, counter = counting_script(tmp_path, "broken", 1000)
    junit, ctrf, tap = tmp_path / "r.xml", tmp_path / "r.json", tmp_path / "r.tap"
    r = run_runner("--isolation", isolation, "--suite", suite_of(tmp_path, [("broken", broken)]),
                   "--retries", "2", "-o", "junit:r.xml", "-o", "json:r.json",
                   "-o", "tap:r.tap", cwd=tmp_path)
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
    assert [a["attempt"] for a in test["retryAttempts"]] == [1, 2], test
    assert all(a["status"] == "failed" and a["stdout"] for a in test["retryAttempts"]), test
    for rerun in cases[0].findall("rerunFailure"):
        assert "status 3" in rerun.find("stackTrace").text, ET.tostring(cases[0])
    parsed = validate_tap(tap)
    assert parsed["fail"] == 1 and parsed["count"] == 1, parsed


@pytest.mark.parametrize("value", ["-1", "abc", "101"])
def test_invalid_retries_exit_2_with_the_limits(tmp_path, value):
    steady, _ = counting_script(tmp_path, "steady", 0)
    r = run_runner("--no-output", "--test", f"./{steady.name}", "--retries", value, cwd=tmp_path)
    assert r.returncode == 2, r
    assert "100" in r.stderr and "--retries" in r.stderr, r


@pytest.mark.parametrize("kind", ["junit", "json"])
def test_rerun_failed_runs_only_what_failed_in_a_report(tmp_path, kind, isolation):
    broken, broken_count = counting_script(tmp_path, "broken", 1)
    steady, steady_count = counting_script(tmp_path, "steady", 0)
    suite = suite_of(tmp_path, [("broken", broken), ("steady", steady)])
    report = tmp_path / f"first.{kind}"
    first = run_runner("--isolation", isolation, "--suite", suite, "-o", f"{kind}:{report.name}",
                       cwd=tmp_path)
    assert first.returncode == 1, first
    again = run_runner("--isolation", isolation, "--suite", suite, "--rerun-failed", report.name,
                       "--no-output", cwd=tmp_path)
    assert again.returncode == 0, again
    assert broken_count.read_text().strip() == "2", again
    assert steady_count.read_text().strip() == "1", again
    assert "1 passed, 0 failed" in again.stdout, again


def _with_old_extension_key(value):
    """A CTRF report as earlier versions wrote it: the extensions under "extra" -> "rtf"."""
    if isinstance(value, dict):
        return {("rtf" if key == "robotology.rtf" else key): _with_old_extension_key(item)
                for key, item in value.items()}
    if isinstance(value, list):
        return [_with_old_extension_key(item) for item in value]
    return value


def test_a_json_report_of_an_earlier_version_is_still_read(tmp_path):
    broken, broken_count = counting_script(tmp_path, "broken", 1)
    steady, steady_count = counting_script(tmp_path, "steady", 0)
    suite = suite_of(tmp_path, [("broken", broken), ("steady", steady)])
    report = tmp_path / "first.json"
    assert run_runner("--suite", suite, "-o", "json:first.json", cwd=tmp_path).returncode == 1
    old = _with_old_extension_key(json.loads(report.read_text()))
    assert "rtf" in old["results"]["tests"][0]["extra"], old
    report.write_text(json.dumps(old))
    again = run_runner("--suite", suite, "--rerun-failed", "first.json", "--no-output",
                       cwd=tmp_path)
    assert again.returncode == 0 and "1 passed, 0 failed" in again.stdout, again
    assert broken_count.read_text().strip() == "2" and steady_count.read_text().strip() == "1"
    r = run_runner("--suite", suite, "--durations", "first.json", "--shard-index", "0",
                   "--shard-count", "1", "--no-output", cwd=tmp_path)
    assert r.returncode == 0, r
    merged = tmp_path / "merged.json"
    r = run_runner("--merge", "json:merged.json", "first.json", cwd=tmp_path)
    assert r.returncode == 0, r
    tests = validate_ctrf(merged)["results"]["tests"]
    assert [t["extra"]["robotology.rtf"]["state"] for t in tests] == ["failed", "passed"], tests


@pytest.mark.parametrize("kind", ["junit", "json"])
def test_rerun_failed_with_no_failure_has_nothing_to_rerun(tmp_path, kind):
    steady, steady_count = counting_script(tmp_path, "steady", 0)
    suite = suite_of(tmp_path, [("steady", steady)])
    report = tmp_path / f"first.{kind}"
    assert run_runner("--suite", suite, "-o", f"{kind}:{report.name}",
                      cwd=tmp_path).returncode == 0
    again = run_runner("--suite", suite, "--rerun-failed", report.name, "--no-output",
                       cwd=tmp_path)
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
    report = tmp_path / "earlier-run.report"
    if content is not None:
        report.write_text(content)
    r = run_runner("--suite", suite_of(tmp_path, [("steady", steady)]), "--rerun-failed",
                   report.name, "--no-output", cwd=tmp_path)
    assert r.returncode == 2, r
    assert why in r.stderr and report.name in r.stderr, r


def test_repeat_until_fail_stops_at_the_first_failing_round(tmp_path, isolation):
    third, counter = counting_script(tmp_path, "third", 0)
    # Passes twice, fails on its 3rd run.
    third.write_text(third.read_text().replace("-le 0", "-eq 3"))
    r = run_runner("--isolation", isolation, "--no-output",
                   "--suite", suite_of(tmp_path, [("third", third)]), "--repeat-until-fail", "10",
                   cwd=tmp_path)
    assert r.returncode == 1, r
    assert counter.read_text().strip() == "3", r
    assert "round 3 of 10 failed" in r.output or "round 3 failed" in r.output, r


def test_repeat_until_fail_runs_n_rounds_when_all_pass(tmp_path):
    steady, counter = counting_script(tmp_path, "steady", 0)
    r = run_runner("--no-output", "--suite", suite_of(tmp_path, [("steady", steady)]),
                   "--repeat-until-fail", "4", cwd=tmp_path)
    assert r.returncode == 0, r
    assert counter.read_text().strip() == "4", r


@pytest.mark.parametrize("value,limit", [("0", ">= 1"), ("x", ">= 1"),
                                         ("1000000001", "at most 1000000000")])
def test_invalid_repeat_until_fail_exits_2_with_the_limits(tmp_path, value, limit):
    steady, _ = counting_script(tmp_path, "steady", 0)
    r = run_runner("--no-output", "--test", f"./{steady.name}", "--repeat-until-fail", value,
                   cwd=tmp_path)
    assert r.returncode == 2, r
    assert limit in r.stderr and "--repeat-until-fail" in r.stderr, r


def test_fail_fast_waits_for_the_last_attempt(tmp_path):
    flaky, _ = counting_script(tmp_path, "flaky", 1)
    steady, steady_count = counting_script(tmp_path, "steady", 0)
    r = run_runner("--no-output", "--suite", suite_of(tmp_path, [("flaky", flaky),
                                                                   ("steady", steady)]),
                   "--retries", "1", "--fail-fast", cwd=tmp_path)
    assert r.returncode == 0, r
    assert steady_count.read_text().strip() == "1", r


def test_flaky_is_its_own_state_on_the_console_and_in_html(tmp_path):
    flaky, _ = counting_script(tmp_path, "flaky", 1)
    html = tmp_path / "r.html"
    r = run_runner("--suite", suite_of(tmp_path, [("flaky", flaky)]), "--retries", "1",
                   "-o", "html:r.html", cwd=tmp_path)
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
                   "--suite", suite_of(tmp_path, [("flaky", flaky), ("broken", broken)]),
                   cwd=tmp_path)
    assert r.returncode == 1, r
    words = [line.split()[0] for line in r.stdout.splitlines()
             if line.startswith("  ") and not line.startswith("   ")
             and line.split()[0] in ("RETRY", "FAILED", "FLAKY", "passed", "flaky")
             and line.rstrip().endswith(" s)")]
    # flaky: one retried attempt then its final line; broken: two retried, then FAILED once.
    assert words == ["RETRY", "FLAKY", "RETRY", "RETRY", "FAILED"], r.stdout
