"""--output tap:FILE: TAP version 14, checked by the third-party tap-parser in strict mode."""
import signal
import subprocess
import time

from conftest import (_marked_processes, leftover_processes, marked, plugin, run_runner,
                      start_runner, validate_ctrf, validate_tap)


def points_at(parsed, depth):
    return [point for point in parsed["points"] if point["depth"] == depth]


def test_suites_are_subtests_with_a_point_per_test_and_diagnostics(tmp_path, suite_file):
    suite = suite_file(f"""<suite name="alpha # one">
  <test>{plugin("passing_test")}</test>
  <test>{plugin("failing_test")}</test>
  <test name="a # b \\ c">{plugin("passing_test")}</test>
  <test>{plugin("nasty_text_test")}</test>
</suite>""")
    out = tmp_path / "r.tap"
    run = run_runner("-s", suite.name, "-t", plugin("printing_test"), "-o", f"tap:{out.name}",
                     cwd=tmp_path)
    assert run.returncode == 1, run
    text = out.read_text()
    assert text.startswith("TAP version 14\n1..2\n"), text
    assert "# Subtest: alpha \\# one\n" in text, text
    parsed = validate_tap(out)
    assert parsed["plan"]["end"] == 2 and parsed["count"] == 2, parsed
    top = points_at(parsed, 0)
    # Tests given with --test make a suite of their own, "tests".
    assert sorted((p["ok"], p["name"]) for p in top) == [(False, "alpha # one"), (True, "tests")]
    inner = [p for p in points_at(parsed, 1) if p["name"] != "printing_test.so"]
    assert [p["ok"] for p in inner] == [True, False, True, False], inner
    assert inner[2]["name"] == "a # b \\ c", inner
    failing = inner[1]
    assert failing["name"] == "failing_test.so", failing  # its id (docs/reference/test-ids.md)
    assert failing["diag"]["severity"] == "fail", failing
    assert "two and two make five" in failing["diag"]["message"], failing
    assert failing["diag"]["at"]["file"].endswith("failing_test.cpp"), failing
    assert failing["diag"]["at"]["line"] > 0, failing
    nasty = inner[3]
    assert "<script>" in nasty["diag"]["message"], nasty
    assert "printed <b>bold</b>" in nasty["diag"]["output"], nasty


def test_output_type_tap_and_the_default_file_name(tmp_path):
    run = run_runner("-t", plugin("passing_test"), "--output-type", "tap", cwd=tmp_path)
    assert run.returncode == 0, run
    parsed = validate_tap(tmp_path / "result.tap")
    assert parsed["ok"] and parsed["pass"] == 1, parsed

    out = tmp_path / "plain"
    run = run_runner("-t", plugin("passing_test"), "-o", out.name, "--output-type", "tap",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert validate_tap(out)["pass"] == 1


def test_skipped_tests_carry_the_reason_and_a_failed_fixture_bails_out(tmp_path, suite_file):
    log = tmp_path / "fixtures.log"
    broken = suite_file(f"""<suite name="broken world">
  <fixture param="--log {log} --name B --fail-setup">{plugin("order_fixture")}</fixture>
  <test>{plugin("passing_test")}</test>
  <test>{plugin("passing_test")}</test>
</suite>""", name="broken.xml")
    fine = suite_file(f"""<suite name="fine">
  <test>{plugin("passing_test")}</test>
</suite>""", name="fine.xml")
    out = tmp_path / "r.tap"
    run = run_runner("-s", broken.name, "-s", fine.name, "-o", f"tap:{out.name}", cwd=tmp_path)
    assert run.returncode == 1, run
    parsed = validate_tap(out)
    inner = points_at(parsed, 1)
    assert [bool(p["skip"]) for p in inner] == [True, True, False], inner
    # The reason is said once, by the suite's point (and the bail-out); each skipped point
    # refers to it in a line (issue 38, friction 9).
    # (with the reason's first line, so a point read alone says why).
    said = "the suite's fixture failed (see the suite's error): fixture "
    assert all(p["skip"].startswith(said) and "setup returned false" in p["skip"]
               for p in inner[:2]), inner
    assert "setup returned false" in out.read_text().split("not ok 1 - broken world", 1)[1]
    # Every result is there before the bail-out: the suite after the broken one too.
    assert [(p["ok"], p["name"]) for p in points_at(parsed, 0)] == [(False, "broken world"),
                                                                    (True, "fine")]
    assert "broken world" in parsed["bailout"], parsed
    assert out.read_text().rstrip().splitlines()[-1].startswith("Bail out! "), out.read_text()


def test_crashes_and_bytes_that_are_not_utf8_stay_valid_tap(tmp_path):
    out = tmp_path / "r.tap"
    run = run_runner("-t", plugin("crash_segv"), "-t", plugin("bad_bytes_test"),
                     "-o", f"tap:{out.name}", cwd=tmp_path)
    assert run.returncode == 1, run
    out.read_bytes().decode("utf-8")  # strict: no stray byte left
    parsed = validate_tap(out)
    crash, bad = points_at(parsed, 1)
    assert not crash["ok"] and crash["diag"]["severity"] == "crash", crash
    assert "SIGSEGV" in crash["diag"]["message"], crash
    # Described by its id (docs/reference/test-ids.md), not by the bytes it names itself with; a '#'
    # and a '\\' of a description are escaped (test_suites_are_subtests_...).
    assert bad["name"] == "bad_bytes_test.so", bad
    assert "\ufffd" in bad["diag"]["message"], bad


def test_unknown_output_type_lists_the_known_ones(tmp_path):
    run = run_runner("-t", plugin("passing_test"), "-o", "xml:r.xml", cwd=tmp_path)
    assert run.returncode == 2, run
    assert "unknown output type 'xml'" in run.stderr, run
    assert "(expected text, junit, tap, json" in run.stderr, run
    run = run_runner("--help", cwd=tmp_path)
    assert "text, junit, tap, json" in run.stdout, run


def test_a_run_quit_at_once_still_writes_every_result(tmp_path, marker):
    """A second Ctrl-C quits at once: the streaming TAP report closes the open test as
    interrupted, the cumulative JSON one has it too; both stay valid."""
    suite = tmp_path / "suite.xml"
    suite.write_text(f'''<suite name="stubborn">
  <test name="first">{plugin("passing_test")}</test>
  <test name="stubborn" param="--hang">{plugin("fork_sleeper")}</test>
</suite>''')
    tap = tmp_path / "r.tap"
    ctrf = tmp_path / "r.json"
    proc = start_runner("--isolation", "none", "--suite", suite.name, "--output", "tap:r.tap",
                        "--output", "json:r.json", cwd=tmp_path, env=marked(marker))
    deadline = time.monotonic() + 20
    while len(_marked_processes(marker)) < 2 and time.monotonic() < deadline:
        time.sleep(0.05)
    proc.send_signal(signal.SIGINT)
    time.sleep(0.3)
    proc.send_signal(signal.SIGINT)
    try:
        proc.communicate(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
        raise
    assert proc.returncode == 130
    parsed = validate_tap(tap)
    assert [(p["ok"], p["name"]) for p in points_at(parsed, 1)] == [(True, "first"),
                                                                    (False, "stubborn")]
    assert points_at(parsed, 1)[1]["diag"]["severity"] == "interrupted", parsed
    states = {t["name"]: t["rawStatus"] for t in validate_ctrf(ctrf)["results"]["tests"]}
    assert states == {"first": "passed", "stubborn": "interrupted"}, states
    assert leftover_processes(marker) == []
