"""The examples (examples/) run as the README says: the example suite through the runner, the
C++ test plug-in alone with params, and the program using the library from its own main()."""
import re
import subprocess

from conftest import BUILD_DIR, run_runner, validate_junit

EXAMPLES = BUILD_DIR / "examples"
SUITE = EXAMPLES / "example.xml"
MY_TEST = EXAMPLES / "libMyTest.so"


def test_example_suite_passes_and_writes_junit(tmp_path):
    junit = tmp_path / "example.xml"
    run = run_runner("--suite", SUITE, "--verbose", "--output", junit, "--output-type", "junit")
    assert run.returncode == 0, run
    assert re.search(r"\b2 passed, 0 failed\b", run.stdout), run
    # The fixture plug-in was found by its bare name and set up the world.
    assert "starting example-bot" in run.output, run
    validate_junit(junit)
    xml = junit.read_text()
    assert xml.count("<testcase") == 2, xml
    assert "MyTest" in xml


def test_example_plugin_reads_its_param():
    ok = run_runner("--test", MY_TEST, "--param", "--speed 30", "--no-output")
    assert ok.returncode == 0, ok
    # 90 degrees at 0.001 deg/s takes longer than the test allows.
    slow = run_runner("--test", MY_TEST, "--param", "--speed 0.001", "--no-output")
    assert slow.returncode == 1, slow
    assert "too slow" in slow.output, slow
    # Without --speed its setup reports an error.
    missing = run_runner("--test", MY_TEST, "--no-output")
    assert missing.returncode == 1, missing
    assert "--speed" in missing.output, missing


def test_library_example_writes_its_report(tmp_path):
    report = tmp_path / "report.txt"
    result = subprocess.run([str(EXAMPLES / "library_example"), str(report)],
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stdout + result.stderr
    text = report.read_text()
    assert "SumTest" in text and "StringTest" in text, text
    assert f"report written to {report}" in result.stdout
