"""--output json:FILE: CTRF, validated against the schema the ctrf package publishes; several
outputs at once, each written whole or reported."""
from conftest import plugin, run_runner, validate_ctrf, validate_junit, validate_tap


def by_name(report):
    # By the name each test gives itself (extra["robotology.rtf"].name); "name" is its id (docs/reference/test-ids.md).
    return {test["extra"]["robotology.rtf"]["name"].split(" ")[0]: test for test in report["results"]["tests"]}


def test_ctrf_report_validates_with_states_messages_places_and_output(tmp_path, suite_file):
    suite = suite_file(f"""<suite name="alpha">
  <test>{plugin("passing_test")}</test>
  <test>{plugin("failing_test")}</test>
  <test>{plugin("nasty_text_test")}</test>
</suite>""")
    out = tmp_path / "r.json"
    run = run_runner("-s", suite.name, "-t", plugin("printing_test"), "-t", plugin("crash_segv"),
                     "-t", plugin("throw_int"), "-t", plugin("bad_bytes_test"),
                     "-o", "json:r.json", cwd=tmp_path)
    assert run.returncode == 1, run
    out.read_bytes().decode("utf-8")  # strict: no stray byte left
    report = validate_ctrf(out)
    assert report["reportFormat"] == "CTRF", report
    summary = report["results"]["summary"]
    assert (summary["tests"], summary["passed"], summary["failed"], summary["skipped"]) == \
        (7, 2, 5, 0), summary
    assert summary["extra"]["robotology.rtf"]["crashed"] == 1 and summary["extra"]["robotology.rtf"]["error"] == 1
    assert summary["stop"] >= summary["start"] > 1_600_000_000_000, summary
    tests = by_name(report)
    assert tests["PassingTest"]["status"] == "passed"
    assert tests["PassingTest"]["suite"] == ["alpha"], tests["PassingTest"]
    failing = tests["FailingTest"]
    assert failing["status"] == "failed" and "two and two make five" in failing["message"]
    assert failing["filePath"].endswith("failing_test.cpp") and failing["line"] > 0, failing
    assert failing["extra"]["robotology.rtf"]["state"] == "failed" and "error" not in failing["extra"]["robotology.rtf"]
    assert "printf line from the test" in tests["PrintingTest"]["stdout"], tests["PrintingTest"]
    assert tests["PrintingTest"]["suite"] == ["tests"], tests["PrintingTest"]
    crash = next(t for t in report["results"]["tests"] if t["rawStatus"] == "crashed")
    assert crash["extra"]["robotology.rtf"]["error"] is True and "SIGSEGV" in crash["extra"]["robotology.rtf"]["crash"]
    thrown = next(t for t in report["results"]["tests"] if t["rawStatus"] == "error")
    assert thrown["status"] == "failed" and thrown["extra"]["robotology.rtf"]["error"] is True, thrown
    nasty = tests["NastyTextTest"]
    assert "<script>alert(1)</script>" in nasty["message"], nasty
    bad = tests["BadBytesTest"]
    assert "\ufffd" in bad["extra"]["robotology.rtf"]["name"] and "\ufffd" in bad["message"], bad
    assert "</script>" in bad["message"], bad
    # '<' is escaped in the file, so the same text can sit inside an HTML page.
    assert "</script>" not in out.read_text(), "unescaped '<'"


def test_a_failed_fixture_and_its_skipped_tests(tmp_path, suite_file):
    log = tmp_path / "fixtures.log"
    suite = suite_file(f"""<suite name="broken world">
  <fixture param="--log {log} --name B --fail-setup">{plugin("order_fixture")}</fixture>
  <test>{plugin("passing_test")}</test>
</suite>""")
    out = tmp_path / "r.json"
    run = run_runner("-s", suite.name, "--output", "r.json", "--output-type", "json",
                     cwd=tmp_path)
    assert run.returncode == 1, run
    report = validate_ctrf(out)
    (test,) = report["results"]["tests"]
    # The reason is said once, by the suite's fixture failure; the skipped test refers to it
    # (issue 38, friction 9).
    assert test["status"] == "skipped", test
    assert test["message"].startswith("the suite's fixture failed (see the suite's error): "
                                      "fixture "), test
    assert test["message"].endswith("setup returned false after reporting: fixture B refuses "
                                    "to start"), test
    (fixture,) = report["results"]["extra"]["robotology.rtf"]["fixtureFailures"]
    assert fixture["suite"] == "broken world", fixture
    assert "setup returned false" in fixture["problems"], fixture
    assert report["results"]["summary"]["extra"]["robotology.rtf"]["suitesFailed"] == 1


def test_every_format_at_once_and_one_that_cannot_be_written(tmp_path):
    names = {kind: tmp_path / f"r.{kind}" for kind in ("text", "junit", "tap", "json", "html")}
    args = [arg for kind, path in names.items() for arg in ("-o", f"{kind}:{path.name}")]
    # /dev/full passes the checks before the run (a device is written through) and fails when
    # written. (A missing folder no longer fails: it is made before the run, issue 40.)
    run = run_runner("-t", plugin("passing_test"), "-t", plugin("failing_test"), *args,
                     "-o", "json:/dev/full", cwd=tmp_path)
    assert run.returncode == 2, run
    assert "cannot write the json output /dev/full" in run.stderr, run
    for kind, path in names.items():
        assert path.is_file(), kind
    assert "FailingTest" in names["text"].read_text()
    validate_junit(names["junit"])
    assert validate_tap(names["tap"])["fail"] == 1
    assert validate_ctrf(names["json"])["results"]["summary"]["failed"] == 1
    assert "FailingTest" in names["html"].read_text()
    # Nothing half-written is left beside them.
    assert sorted(p.name for p in tmp_path.iterdir() if p.is_file()) == \
        sorted(p.name for p in names.values())
