"""Executables as test cases, with and without TAP, through the real runner (SPEC 3.2), run
from their folder as users run them (`--test ./check`)."""
import shutil
import subprocess

import pytest

from lang_cases import ISOLATIONS, run_isolated


@pytest.fixture(params=ISOLATIONS)
def isolation(request):
    return request.param


def program(folder, name, text):
    path = folder / name
    path.write_text(text)
    path.chmod(0o755)
    return path


def shell(folder, body, name="check"):
    return program(folder, name, "#!/bin/sh\n" + body)


def test_exit_zero_passes_and_its_output_is_shown(tmp_path, isolation):
    path = shell(tmp_path, "echo 'moving the arm'\necho 'warning: slow' >&2\nexit 0\n")
    r = run_isolated(isolation, "--test", f"./{path.name}", "-v", cwd=tmp_path)
    assert r.returncode == 0, r
    assert "moving the arm" in r.output and "warning: slow" in r.output, r
    assert "1 passed, 0 failed" in r.stdout, r


def test_exit_77_skips(tmp_path, isolation):
    path = shell(tmp_path, "echo 'no robot attached' >&2\nexit 77\n")
    r = run_isolated(isolation, "--test", f"./{path.name}", "-v", cwd=tmp_path)
    assert r.returncode == 0, r
    assert "1 skipped" in r.stdout, r
    # The kind's word once: it read "skipped: skipped (exit status 77): ..." (issue 38,
    # friction 9).
    assert "      skipped: exit status 77: no robot attached" in r.stdout, r
    assert "skipped: skipped" not in r.stdout, r


def test_a_plan_of_nothing_skips_saying_it_once(tmp_path, isolation):
    path = shell(tmp_path, "echo 'TAP version 14'\necho '1..0'\n")
    r = run_isolated(isolation, "--test", f"./{path.name}", cwd=tmp_path)
    assert r.returncode == 0, r
    assert "1 skipped" in r.stdout, r
    assert "      skipped: the plan is 1..0" in r.stdout, r
    assert "skipped: skipped" not in r.stdout, r


def test_other_exit_status_fails(tmp_path, isolation):
    path = shell(tmp_path, "echo 'motor 3 stalled' >&2\nexit 3\n")
    r = run_isolated(isolation, "--test", f"./{path.name}", "-v", cwd=tmp_path)
    assert r.returncode == 1, r
    assert "exited with status 3" in r.output, r
    assert "motor 3 stalled" in r.output, r


def test_param_is_argv_and_environment_is_RTF_ENVIRONMENT(tmp_path, isolation, suite_file):
    shell(tmp_path, 'echo "argc=$# first=[$1] second=[$2]"\necho "env=[$RTF_ENVIRONMENT]"\n',
          name="probe")
    suite = suite_file("""<suite name="exec">
  <environment>--robot sim</environment>
  <test type="exec" param="--part 'left arm'">probe</test>
</suite>""")
    r = run_isolated(isolation, "--suite", suite.name, "-v", cwd=tmp_path)
    assert r.returncode == 0, r
    assert "argc=2 first=[--part] second=[left arm]" in r.output, r
    assert "env=[--robot sim]" in r.output, r


def test_repetition_runs_the_program_again(tmp_path, isolation, suite_file):
    counter = tmp_path / "count"
    shell(tmp_path, f"echo run >> {counter}\n", name="again")
    suite = suite_file("""<suite name="exec">
  <test repetition="3">again</test>
</suite>""")
    r = run_isolated(isolation, "--suite", suite.name, cwd=tmp_path)
    assert r.returncode == 0, r
    assert counter.read_text().count("run") == 3


def test_tap_points_are_checks(tmp_path, isolation):
    path = shell(tmp_path, """cat <<'TAP'
TAP version 13
1..3
ok 1 - gripper opens
not ok 2 - gripper closes
  ---
  force: 0.2
  ...
ok 3 - wrist # SKIP no wrist
TAP
exit 1
""")
    r = run_isolated(isolation, "--test", f"./{path.name}", "-v", "-d", cwd=tmp_path)
    assert r.returncode == 1, r
    assert "ok 1 - gripper opens" in r.output, r
    assert "not ok 2 - gripper closes" in r.output, r
    assert "force: 0.2" in r.output, r
    assert "ok 3 - wrist # SKIP no wrist" in r.output, r


def test_failing_todo_point_does_not_fail(tmp_path, isolation):
    path = shell(tmp_path, "echo '1..2'\necho 'ok 1'\necho 'not ok 2 - walks # TODO later'\n")
    r = run_isolated(isolation, "--test", f"./{path.name}", cwd=tmp_path)
    assert r.returncode == 0, r


def test_tap_plan_mismatch_fails(tmp_path, isolation):
    path = shell(tmp_path, "echo '1..3'\necho 'ok 1'\necho 'ok 2'\n")
    r = run_isolated(isolation, "--test", f"./{path.name}", "-v", cwd=tmp_path)
    assert r.returncode == 1, r
    assert "planned 3 test(s) but ran 2" in r.output, r


def test_tap_bail_out_is_an_error(tmp_path, isolation):
    path = shell(tmp_path, "echo '1..2'\necho 'ok 1'\necho 'Bail out! robot unplugged'\n")
    r = run_isolated(isolation, "--test", f"./{path.name}", "-v", cwd=tmp_path)
    assert r.returncode == 1, r
    assert "Bail out! robot unplugged" in r.output, r
    assert "1 error" in r.output, r


def test_tap_skip_all_skips(tmp_path, isolation):
    path = shell(tmp_path, "echo '1..0 # SKIP no camera'\n")
    r = run_isolated(isolation, "--test", f"./{path.name}", "-v", cwd=tmp_path)
    assert r.returncode == 0, r
    assert "1 skipped" in r.stdout, r
    assert "no camera" in r.output, r


def test_killed_by_a_signal_is_reported_with_its_name(tmp_path, isolation):
    path = shell(tmp_path, "kill -ABRT $$\n")
    r = run_isolated(isolation, "--test", f"./{path.name}", "-v", cwd=tmp_path)
    assert r.returncode == 1, r
    assert "SIGABRT" in r.output, r


def test_type_exec_overrides_the_extension(tmp_path, isolation, suite_file):
    # An executable .py run as a program: its TAP counts, not a class TestCase.
    program(tmp_path, "tool.py", "#!/usr/bin/python3\nprint('1..1')\nprint('not ok 1 - as exec')\n")
    suite = suite_file("""<suite name="exec">
  <test type="exec">tool.py</test>
</suite>""")
    r = run_isolated(isolation, "--suite", suite.name, "-v", cwd=tmp_path)
    assert r.returncode == 1, r
    assert "not ok 1 - as exec" in r.output, r


@pytest.mark.skipif(subprocess.run(["perl", "-MTest::More", "-e", "1"],
                                   capture_output=True).returncode != 0,
                    reason="perl with Test::More is not installed")
class TestPerlTestMore:
    SCRIPT = """#!/usr/bin/perl
use strict;
use warnings;
use Test::More tests => 4;
ok(1, 'connects');
is(2 + 2, {sum}, 'adds');
subtest 'arm' => sub {{
    plan tests => 2;
    ok(1, 'shoulder');
    ok(1, 'elbow');
}};
SKIP: {{
    skip 'no camera', 1;
    ok(0, 'camera');
}}
"""

    def test_passing(self, tmp_path, isolation):
        path = program(tmp_path, "robot.t", self.SCRIPT.format(sum=4))
        r = run_isolated(isolation, "--test", f"./{path.name}", "-v", "-d", cwd=tmp_path)
        assert r.returncode == 0, r
        assert "arm > ok 1 - shoulder" in r.output, r
        assert "ok 4 # SKIP no camera" in r.output, r

    def test_failing(self, tmp_path, isolation):
        path = program(tmp_path, "robot.t", self.SCRIPT.format(sum=5))
        r = run_isolated(isolation, "--test", f"./{path.name}", "-v", cwd=tmp_path)
        assert r.returncode == 1, r
        assert "not ok 2 - adds" in r.output, r
        assert "Failed test 'adds'" in r.output, r  # Test::More's diagnostics, on stderr


@pytest.mark.skipif(shutil.which("node") is None, reason="node is not installed")
class TestNodeTestRunner:
    SPEC = """import {{ test, describe, it }} from 'node:test';
import assert from 'node:assert';
test('adds', () => {{ assert.strictEqual(1 + 1, {sum}); }});
describe('arm', () => {{
  it('moves', () => {{}});
  it('stops', () => {{}});
}});
test('camera', {{ skip: 'no camera' }}, () => {{}});
"""

    def write(self, folder, total):
        (folder / "robot.test.mjs").write_text(self.SPEC.format(sum=total))
        return shell(folder, 'exec node --test --test-reporter=tap "$(dirname "$0")/robot.test.mjs"\n',
                     name="node-tests")

    def test_passing(self, tmp_path, isolation):
        r = run_isolated(isolation, "--test", f"./{self.write(tmp_path, 2).name}", "-v", "-d",
                         cwd=tmp_path)
        assert r.returncode == 0, r
        assert "arm > ok 2 - stops" in r.output, r
        assert "ok 3 - camera # SKIP no camera" in r.output, r

    def test_failing(self, tmp_path, isolation):
        r = run_isolated(isolation, "--test", f"./{self.write(tmp_path, 3).name}", "-v",
                         cwd=tmp_path)
        assert r.returncode == 1, r
        assert "not ok 1 - adds" in r.output, r
        assert "Expected values to be strictly equal" in r.output, r
