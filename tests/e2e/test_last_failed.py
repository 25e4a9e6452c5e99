"""The cache folder, --lf/--last-failed, --ff/--failed-first, --cache-dir, --no-cache, and
--rerun-failed with a --history file (issue 38, friction 3), as pytest's .pytest_cache, --lf
and --ff. Through the installed runner, from the suite's folder, every file named relatively."""
import json

import pytest

from conftest import run_runner


def project(folder):
    """robot: a, b; arm: c, d. A test fails while a file FAIL-<name> is in the folder."""
    script = folder / "check.sh"
    script.write_text('#!/bin/sh\nif [ -e "FAIL-$1" ]; then echo "failing $1" >&2; exit 1; fi\n')
    script.chmod(0o755)
    for suite, tests in (("robot", "ab"), ("arm", "cd")):
        body = "\n".join(f'  <test type="exec" name="{t}" param="{t}">./check.sh</test>'
                         for t in tests)
        (folder / f"{suite}.xml").write_text(f'<suite name="{suite}">\n{body}\n</suite>\n')
    return ["--suite", "robot.xml", "--suite", "arm.xml", "-o", "json:r.json"]


def fail(folder, *names):
    for path in folder.glob("FAIL-*"):
        path.unlink()
    for name in names:
        (folder / f"FAIL-{name}").write_text("")


def ran(folder):
    """The tests of the last run, in the order they ran, with their status."""
    report = json.loads((folder / "r.json").read_text())
    return [(t["name"], t["status"]) for t in report["results"]["tests"]]


def cached(folder, cache=".rtf_cache"):
    return (folder / cache / "lastfailed").read_text().splitlines()


def test_lf_reruns_the_last_runs_failures_and_the_cache_follows_each_run(tmp_path):
    suites = project(tmp_path)
    fail(tmp_path, "b", "d")
    run = run_runner(*suites, cwd=tmp_path)
    assert run.returncode == 1, run
    # As pytest's .pytest_cache: ignored by git, and saying what it is.
    assert (tmp_path / ".rtf_cache" / ".gitignore").read_text().splitlines()[-1] == "*"
    assert "--lf" in (tmp_path / ".rtf_cache" / "README.md").read_text()
    assert cached(tmp_path) == ["arm/d", "robot/b"]  # the ids every option uses

    fail(tmp_path, "d")  # b is fixed
    run = run_runner(*suites, "--lf", cwd=tmp_path)
    assert run.returncode == 1, run
    assert "--lf: running the 2 test(s) that failed in the last run" in run.stdout, run
    assert ran(tmp_path) == [("b", "passed"), ("d", "failed")], run
    assert cached(tmp_path) == ["arm/d"]

    run = run_runner(*suites, "--last-failed", cwd=tmp_path)
    assert ran(tmp_path) == [("d", "failed")], run

    fail(tmp_path)
    run = run_runner(*suites, "--lf", cwd=tmp_path)
    assert run.returncode == 0 and ran(tmp_path) == [("d", "passed")], run
    assert cached(tmp_path) == []
    # Nothing failed last time: every test runs, as pytest does, and it says so.
    run = run_runner(*suites, "--lf", cwd=tmp_path)
    assert run.returncode == 0, run
    assert "--lf: no test failed in the last run (.rtf_cache): running every selected test" \
        in run.stdout, run
    assert [name for name, _ in ran(tmp_path)] == ["a", "b", "c", "d"], run


def test_lf_keeps_the_failures_of_tests_another_selection_left_out(tmp_path):
    suites = project(tmp_path)
    fail(tmp_path, "a", "c")
    assert run_runner(*suites, cwd=tmp_path).returncode == 1
    fail(tmp_path)
    run = run_runner(*suites, "--filter", "robot/*", cwd=tmp_path)
    assert run.returncode == 0, run
    assert cached(tmp_path) == ["arm/c"]  # robot/a passed; arm/c was not run
    # -k and --lf: the last failures among the selected; none selected: every selected test.
    run = run_runner(*suites, "--lf", "-k", "robot", cwd=tmp_path)
    assert "none of the last run's 1 failed test(s) is selected" in run.stdout, run
    assert [name for name, _ in ran(tmp_path)] == ["a", "b"], run


def test_ff_runs_the_failures_first_then_the_rest(tmp_path):
    suites = project(tmp_path)
    fail(tmp_path, "d")
    assert run_runner(*suites, cwd=tmp_path).returncode == 1
    run = run_runner(*suites, "--ff", cwd=tmp_path)
    assert "--ff: the 1 test(s) that failed in the last run first" in run.stdout, run
    assert [name for name, _ in ran(tmp_path)] == ["d", "c", "a", "b"], run


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_passing_run_leaves_no_cache_and_list_never_writes_it(tmp_path, jobs):
    suites = project(tmp_path)
    run = run_runner(*suites, "-j", jobs, cwd=tmp_path)
    assert run.returncode == 0, run
    assert not (tmp_path / ".rtf_cache").exists()
    fail(tmp_path, "a", "d")
    run = run_runner(*suites, "--list", cwd=tmp_path)
    assert run.returncode == 0 and not (tmp_path / ".rtf_cache").exists(), run
    run = run_runner(*suites, "-j", jobs, cwd=tmp_path)
    assert run.returncode == 1 and cached(tmp_path) == ["arm/d", "robot/a"], run


def test_cache_dir_moves_it_and_no_cache_turns_it_off(tmp_path):
    suites = project(tmp_path)
    fail(tmp_path, "c")
    run = run_runner(*suites, "--no-cache", cwd=tmp_path)
    assert run.returncode == 1 and not (tmp_path / ".rtf_cache").exists(), run
    run = run_runner(*suites, "--cache-dir", "build/cache", cwd=tmp_path)
    assert run.returncode == 1 and not (tmp_path / ".rtf_cache").exists(), run
    assert cached(tmp_path, "build/cache") == ["arm/c"]
    run = run_runner(*suites, "--cache-dir", "build/cache", "--lf", cwd=tmp_path)
    assert ran(tmp_path) == [("c", "failed")], run
    run = run_runner(*suites, "--lf", "--no-cache", cwd=tmp_path)
    assert run.returncode == 2, run
    assert "--lf reads the cache folder, which --no-cache turns off" in run.stderr, run
    run = run_runner(*suites, "--lf", "--rerun-failed", "r.json", cwd=tmp_path)
    assert run.returncode == 2 and "give one" in run.stderr, run


def test_shards_run_one_after_the_other_in_one_folder_keep_both_failures(tmp_path):
    suites = project(tmp_path)
    fail(tmp_path, "a", "c")
    for index in ("0", "1"):
        run = run_runner(*suites, "--shard-index", index, "--shard-count", "2", cwd=tmp_path)
        assert run.returncode == 1, run
    assert cached(tmp_path) == ["arm/c", "robot/a"]
    run = run_runner(*suites, "--lf", cwd=tmp_path)
    assert [name for name, _ in ran(tmp_path)] == ["a", "c"], run


def test_rerun_failed_takes_a_history_file_and_reruns_its_last_runs_failures(tmp_path):
    suites = project(tmp_path)
    fail(tmp_path, "a", "b", "c")
    assert run_runner(*suites, "--history", "h.db", "--no-cache", cwd=tmp_path).returncode == 1
    fail(tmp_path, "b")
    assert run_runner(*suites, "--history", "h.db", "--no-cache", cwd=tmp_path).returncode == 1
    run = run_runner(*suites, "--rerun-failed", "h.db", "--no-cache", cwd=tmp_path)
    assert run.returncode == 1, run
    assert ran(tmp_path) == [("b", "failed")], run  # the last run's failure only
    fail(tmp_path)
    assert run_runner(*suites, "--history", "h.db", "--no-cache", cwd=tmp_path).returncode == 0
    run = run_runner(*suites, "--rerun-failed", "h.db", cwd=tmp_path)
    assert run.returncode == 0 and "h.db has no failed test: nothing to rerun" in run.stdout, run
