"""The RTF 2.x options, short and long, reaching the tests; usage errors exit 2. The runner
starts in the suite's folder and is given the suite by its name, as users run it."""
import re

import pytest

from conftest import plugin, run_runner


def test_param_and_environment_reach_the_test(tmp_path, suite_file):
    suite = suite_file(f"""<suite name="s">
  <environment>--robot icubSim</environment>
  <test>{plugin("echo_test")}</test>
  <test param="--expect-param --own">{plugin("echo_test")}</test>
</suite>""")
    run = run_runner("-s", suite.name, "-v", "-p", "--expect-param --cli --expect-env --extra",
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
    run = run_runner("--suite", suite.name, "--environment", "--other", cwd=tmp_path)
    assert run.returncode == 1, run
    assert "environment holds --missing" in run.stdout, run


def test_repetition_runs_each_test_n_times_and_the_suite_wins(tmp_path, suite_file):
    suite = suite_file(f"""<suite name="s">
  <test name="many">{plugin("echo_test")}</test>
  <test name="two" repetition="2">{plugin("echo_test")}</test>
</suite>""")
    run = run_runner("-s", suite.name, "--repetition", "3", "--verbose", cwd=tmp_path)
    assert run.returncode == 0, run
    many, two = re.split(r"run         \S+/two", run.stdout)
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
                   "--network", "--timeout", "--fail-fast"):
        assert option in run.stdout, (option, run)


@pytest.mark.parametrize("flag", ["-?", "-h", "--help"])
def test_rtf2_help_flags_print_the_help(tmp_path, flag):
    # RTF 2.x's documentation lists `-?, --help`; -? was refused as an unexpected argument.
    run = run_runner(flag, cwd=tmp_path)
    assert run.returncode == 0, run
    assert "-h,-?,--help" in run.stdout and "--suite" in run.stdout, run


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


# --- Empty values (RTF 2.x's CMake helper writes `-p ${PARAM} -e "${ENV}"`) ---

def reported_argv(stdout):
    """The argv echo_test reported (its report ends with the source file and line)."""
    match = re.search(r"report: argv (.*) \[[^\[\]]*echo_test\.cpp:\d+\]$", stdout, re.M)
    assert match, stdout
    return match.group(1)


def value_options(folder):
    """Every option of --help that takes a value: {long name: value word}."""
    run = run_runner("--help", cwd=folder)
    assert run.returncode == 0, run
    found = {}
    for line in run.stdout.splitlines():
        match = re.match(r"  (?:-\w,)?(--[\w-]+) ([A-Z]\S*)", line)
        if match:
            found[match.group(1)] = match.group(2)
    return found


# What an empty value does, option by option: a free text (param, environment) takes it;
# anything else that takes a value says the value is empty, naming the option (an empty FILE,
# N, MODE, ... is never valid).
TAKES_EMPTY = {"--param", "--environment"}
REFUSES_EMPTY = {
    "--test", "--tests", "--suite", "--suites", "--repetition", "--output", "--output-type",
    "--web-port", "--web-host", "--web-linger", "--isolation", "--network", "--timeout",
    "--retries",
    "--rerun-failed", "--repeat-until-fail", "--var", "--var-file", "--tag", "--exclude-tag",
    "--filter", "--keyword", "--cache-dir", "--shard-index", "--shard-count", "--durations", "--durations-from", "--merge",
    "--expect-shards",
    "--jobs", "--resources", "--plugin-path", "--color", "--history", "--history-report",
    "--history-html", "--world-up", "--world", "--world-down", "--shared-worlds",
}


def test_the_table_covers_every_option_of_help_that_takes_a_value(tmp_path):
    assert set(value_options(tmp_path)) == TAKES_EMPTY | REFUSES_EMPTY


@pytest.mark.parametrize("option", sorted(TAKES_EMPTY | REFUSES_EMPTY))
@pytest.mark.parametrize("form", ["separate", "equals"])
def test_an_empty_value_is_taken_by_every_option(tmp_path, option, form):
    given = [option, ""] if form == "separate" else [option + "="]
    run = run_runner("-v", "--no-output", *given, "--test", plugin("echo_test"), cwd=tmp_path)
    if option in TAKES_EMPTY:
        assert run.returncode == 0, run
        assert reported_argv(run.stdout) == "[EchoTest]", run  # no param words
        assert "environment []" in run.stdout, run
    else:
        assert run.returncode == 2, run
        assert f"{option}: the value is empty" in run.stderr, run


@pytest.mark.parametrize("isolation", ["process", "none"])
@pytest.mark.parametrize("args,param,environment", [
    # RTF 2.x's helper with an empty PARAM: the unquoted value vanishes.
    (["-p", "-e", "", "--test", "ECHO"], "", ""),
    (["-p", "-e", "--extra yes", "--test", "ECHO"], "", "--extra yes"),
    (["-p", "--expect-param --cli", "-e", "", "--test", "ECHO"], "--expect-param --cli", ""),
    (["--test", "ECHO", "-e", ""], "", ""),
    (["--test", "ECHO", "--environment", "", "--param", ""], "", ""),
    (["--param=", "--environment=", "--test", "ECHO"], "", ""),
    (["-p", "--test", "ECHO", "-e", "--robot sim"], "", "--robot sim"),
    (["-p", "-d", "-e", "robot=x", "--test", "ECHO"], "", "robot=x"),
], ids=["p-then-e", "p-then-e-value", "p-value-e-empty", "e-empty-last", "long-forms",
        "equals-forms", "p-then-test", "p-then-flag"])
def test_rtf2_helper_command_lines_run_with_an_empty_param_or_environment(
        tmp_path, isolation, args, param, environment):
    args = [plugin("echo_test") if a == "ECHO" else a for a in args]
    run = run_runner("-v", "--no-output", "--no-summary", "--isolation", isolation, *args,
                     cwd=tmp_path)
    assert run.returncode == 0, run
    words = "".join(f" [{w}]" for w in param.split())
    assert reported_argv(run.stdout) == f"[EchoTest]{words}", run
    assert f"environment [{environment}]" in run.stdout, run


@pytest.mark.parametrize("args,says", [
    (["-p", "a", "-p", "b", "-t", "ECHO"], "--param"),
    (["-e", "", "-e", "x", "-t", "ECHO"], "--environment"),
    (["-t", "ECHO", "--web-port", "1", "--web-port", "2"], "--web-port"),
    (["-t", "ECHO", "-e"], "--environment"),
    (["-t", "ECHO", "-p"], "--param"),
    (["-t", "ECHO", "--output"], "--output"),
    (["-t", "ECHO", "--colour", "red"], "--colour"),
    (["--test", ""], "--test: the value is empty"),
    (["--suite", ""], "--suite: the value is empty"),
    (["--test="], "--test: the value is empty"),
], ids=["param-twice", "environment-twice", "port-twice", "environment-at-end",
        "param-at-end", "output-at-end", "unknown", "empty-test", "empty-suite",
        "empty-test-equals"])
def test_bad_command_lines_exit_two_naming_the_option(tmp_path, args, says):
    args = [plugin("echo_test") if a == "ECHO" else a for a in args]
    run = run_runner(*args, cwd=tmp_path)
    assert run.returncode == 2, run
    assert says in run.stderr, run
