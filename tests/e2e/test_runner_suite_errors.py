"""A malformed suite file stops the runner before anything runs: exit 2, FILE:LINE: why."""
import pytest

from conftest import plugin, run_runner

CASES = {
    "bad xml": ("<suite name='s'>\n<test>a.so</test>\n<test>b.so</tset>\n</suite>", 3,
                "malformed XML"),
    "unknown element": ("<suite name='s'>\n\n<tset>a.so</tset>\n</suite>", 3,
                        "unknown element <tset>"),
    "unknown attribute": ("<suite name='s'>\n<test parm='x'>a.so</test>\n</suite>", 2,
                          "unknown attribute 'parm' on <test>"),
    "repetition abc": ("<suite name='s'>\n<test>a.so</test>\n\n<test repetition=\"abc\">a.so</test>"
                       "\n</suite>", 4, 'repetition="abc"'),
    "repetition zero": ("<suite name='s'>\n<test repetition='0'>a.so</test></suite>", 2,
                        'repetition="0"'),
    "negative timeout": ("<suite name='s'>\n<test timeout='-3'>a.so</test></suite>", 2,
                         "timeout"),
    "empty plug-in name": ("<suite name='s'>\n<test type='dll'>  </test>\n</suite>", 2,
                           "<test> without a plug-in"),
    "unknown type": ("<suite name='s'>\n<test type='cobol'>a.cbl</test>\n</suite>", 2,
                     "unknown test type 'cobol'"),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_malformed_suite_exits_two_naming_file_and_line(tmp_path, suite_file, case):
    text, line, what = CASES[case]
    suite = suite_file(text)
    run = run_runner("-s", suite.name, cwd=tmp_path)
    assert run.returncode == 2, run
    assert f"suite.xml:{line}: " in run.stderr, run
    assert what in run.stderr, run
    assert "passed" not in run.stdout, run   # nothing ran


def test_malformed_suite_among_good_ones_runs_nothing(tmp_path, suite_file):
    good = suite_file(f"<suite name='good'><test>{plugin('passing_test')}</test></suite>",
                      name="good.xml")
    bad = suite_file("<suite name='bad'><tests/></suite>", name="bad.xml")
    run = run_runner("-s", good.name, "-s", bad.name, cwd=tmp_path)
    assert run.returncode == 2, run
    assert "bad.xml:1: unknown element <tests>" in run.stderr, run
    assert "PassingTest" not in run.stdout, run


def test_unreadable_suite_exits_two(tmp_path):
    run = run_runner("-s", "missing.xml", cwd=tmp_path)
    assert run.returncode == 2, run
    assert "missing.xml: cannot read the suite file" in run.stderr, run


def test_old_suit_root_is_accepted_with_a_warning(tmp_path, suite_file):
    suite = suite_file(f"<suit name='old'>\n<test>{plugin('passing_test')}</test>\n</suit>",
                       name="old.xml")
    run = run_runner("-s", suite.name, cwd=tmp_path)
    assert run.returncode == 0, run
    assert "old.xml:1: warning" in run.stderr and "<suit>" in run.stderr, run
    assert "1 passed, 0 failed" in run.stdout, run
