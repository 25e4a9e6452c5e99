"""The RTF 2.x options, short and long, reaching the tests; usage errors exit 2."""
import re

import pytest

from conftest import plugin, run_runner


def test_param_and_environment_reach_the_test(tmp_path, suite_file):
    suite = suite_file(f"""<suite name="s">
  <environment>--robot icubSim</environment>
  <test>{plugin("echo_test")}</test>
  <test param="--expect-param --own">{plugin("echo_test")}</test>
</suite>""")
    run = run_runner("-s", suite, "-v", "-p", "--expect-param --cli --expect-env --extra",
                     "-e", "--extra yes", cwd=tmp_path)
    assert run.returncode == 0, run
    # The first test has no param of its own: -p reaches it, split like a shell would.
    assert "argv [EchoTest] [--expect-param] [--cli] [--expect-env] [--extra]" in run.stdout, run
    # The second keeps its own param.
    assert "argv [EchoTest] [--expect-param] [--own]" in run.stdout, run
    # The suite's environment first, then the command line's.
    assert "environment [--robot icubSim --extra yes]" in run.stdout, run


def test_param_check_fails_when_the_param_is_not_given(tmp_path, suite_file):
    suite = suite_file(f"""<suite name="s">
  <test param="--expect-env --missing">{plugin("echo_test")}</test>
</suite>""")
    run = run_runner("--suite", suite, "--environment", "--other", cwd=tmp_path)
    assert run.returncode == 1, run
    assert "environment holds --missing" in run.stdout, run


def test_repetition_runs_each_test_n_times_and_the_suite_wins(tmp_path, suite_file):
    suite = suite_file(f"""<suite name="s">
  <test name="many">{plugin("echo_test")}</test>
  <test name="two" repetition="2">{plugin("echo_test")}</test>
</suite>""")
    run = run_runner("-s", suite, "--repetition", "3", "--verbose", cwd=tmp_path)
    assert run.returncode == 0, run
    many, two = run.stdout.split("run         two")
    assert "run number 3" in many and "run number 4" not in many, run
    assert "run number 2" in two and "run number 3" not in two, run


def test_detail_shows_checks(tmp_path):
    plain = run_runner("-t", plugin("passing_test"), cwd=tmp_path)
    assert "arithmetic holds" not in plain.stdout, plain
    detail = run_runner("-t", plugin("passing_test"), "-d", cwd=tmp_path)
    assert detail.returncode == 0, detail
    assert re.search(r"check ok.*arithmetic holds", detail.stdout), detail
    detail = run_runner("-t", plugin("passing_test"), "--detail", cwd=tmp_path)
    assert "arithmetic holds" in detail.stdout, detail


def test_verbose_shows_reports(tmp_path):
    plain = run_runner("-t", plugin("passing_test"), cwd=tmp_path)
    assert "passing test is running" not in plain.stdout, plain
    for flag in ("-v", "--verbose"):
        verbose = run_runner("-t", plugin("passing_test"), flag, cwd=tmp_path)
        assert verbose.returncode == 0, verbose
        assert "passing test is running" in verbose.stdout, verbose


def test_version(tmp_path):
    run = run_runner("--version", cwd=tmp_path)
    assert run.returncode == 0, run
    assert re.match(r"robottestingframework-testrunner \d+\.\d+\.\d+", run.stdout), run


def test_help_lists_every_option(tmp_path):
    run = run_runner("--help", cwd=tmp_path)
    assert run.returncode == 0, run
    for option in ("-t,--test", "--tests", "-s,--suite", "--suites", "-r,--recursive",
                   "-p,--param", "-e,--environment", "--repetition", "-o,--output",
                   "--output-type", "--no-output", "--no-summary", "-w,--web-reporter",
                   "--web-port", "--web-host", "--web-linger", "-d,--detail", "-v,--verbose", "--version", "--isolation",
                   "--timeout", "--fail-fast"):
        assert option in run.stdout, (option, run)


@pytest.mark.parametrize("args,says", [
    (["--frobnicate"], "--frobnicate"),
    ([], "nothing to run"),
    (["-t"], "--test"),
    (["-t", "x.so", "--repetition", "zero"], "--repetition: 'zero' is not a whole number of runs >= 1"),
    (["-t", "x.so", "--output-type", "pdf"], "unknown output type 'pdf'"),
    (["-t", "x.so", "--isolation", "thread"], "isolation"),
    (["-t", "x.so", "--timeout", "-2"], "--timeout: '-2' is not a number of seconds >= 0"),
])
def test_usage_errors_exit_two(tmp_path, args, says):
    run = run_runner(*args, cwd=tmp_path)
    assert run.returncode == 2, run
    assert says in run.stderr, run
    assert "--help" in run.stderr, run


def test_web_reporter_serves_the_run_and_exits_with_it(tmp_path):
    run = run_runner("-t", plugin("passing_test"), "-w", "--web-port", "0", cwd=tmp_path,
                     timeout=60)
    assert run.returncode == 0, run
    assert "live web page at http://127.0.0.1:" in run.stdout, run
    assert "not built yet" not in run.stderr, run


def test_var_is_accepted_and_one_nothing_reads_is_a_warning(tmp_path):
    run = run_runner("-t", plugin("passing_test"), "--var", "robot=icub", cwd=tmp_path)
    assert run.returncode == 0, run
    assert "warning: --var robot=icub is not used" in run.stderr, run
