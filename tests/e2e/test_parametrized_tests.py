"""Parametrized tests (issue 38 item 15, docs/how-to/parametrized-tests.md): a <test> with
<parametrize name="speed">10, 20</parametrize> children runs once per value, and several make a
matrix. Each instance has its own id, seen by --list, --filter (and -k, which matches the same ids), the JUnit report,
--rerun-failed and the history. Run from the suite's folder with relative paths."""
import json
import sqlite3
import xml.etree.ElementTree as ET

from conftest import run_runner

SUITE = """<suite name="robot">
  <test type="exec" param="--speed ${speed}">drive.sh
    <parametrize name="speed">10, 20, 30</parametrize>
  </test>
  <test type="exec" param="${mode} ${arm}">grip.sh
    <parametrize name="mode">soft, hard</parametrize>
    <parametrize name="arm">left, right</parametrize>
  </test>
  <test type="exec">${tool}.sh<parametrize name="tool">env, grip</parametrize></test>
  <test type="exec" param="--speed 5">drive.sh</test>
</suite>
"""
IDS = ["robot/drive.sh[--speed 10]", "robot/drive.sh[--speed 20]",
       "robot/drive.sh[--speed 30]",
       "robot/grip.sh[soft left]", "robot/grip.sh[soft right]",
       "robot/grip.sh[hard left]", "robot/grip.sh[hard right]",
       "robot/env.sh[tool=env]", "robot/grip.sh[tool=grip]",
       "robot/drive.sh"]  # the one plain drive.sh: unique as it is


def layout(tmp_path):
    """drive.sh fails at --speed 20 when FAIL is set; grip.sh passes; env.sh passes."""
    for name, body in {
        "drive.sh": '#!/bin/sh\n[ -z "$FAIL" ] || [ "$2" != 20 ]\n',
        "grip.sh": "#!/bin/sh\nexit 0\n",
        "env.sh": "#!/bin/sh\nexit 0\n",
    }.items():
        (tmp_path / name).write_text(body)
        (tmp_path / name).chmod(0o755)
    (tmp_path / "robot.xml").write_text(SUITE)
    return tmp_path


def listed_ids(folder, *args):
    run = run_runner("--suite", "robot.xml", "--list", "--output", "json:-", *args, cwd=folder)
    assert run.returncode == 0, run
    return [t["id"] for s in json.loads(run.stdout)["suites"] for t in s["tests"]]


def test_each_instance_is_listed_run_and_reported(tmp_path):
    folder = layout(tmp_path)
    assert listed_ids(folder) == IDS
    text = run_runner("--suite", "robot.xml", "--list", cwd=folder)
    assert "drive.sh[--speed 20]" in text.stdout, text
    run = run_runner("--suite", "robot.xml", "--output", "junit:r.xml", cwd=folder)
    assert run.returncode == 0 and "10 passed, 0 failed" in run.stdout, run
    cases = ET.parse(folder / "r.xml").getroot().iter("testcase")
    assert len(list(cases)) == len(IDS)


def test_filter_rerun_failed_and_history_see_each_instance(tmp_path):
    folder = layout(tmp_path)
    assert listed_ids(folder, "--filter", "robot/drive.sh[--speed 20]") == \
        ["robot/drive.sh[--speed 20]"]
    assert listed_ids(folder, "--tag", "none-such", "--allow-empty") == []

    failed = run_runner("--suite", "robot.xml", "--output", "junit:r.xml", "--history", "h.db",
                        cwd=folder, env={"FAIL": "1"})
    assert failed.returncode == 1 and "9 passed, 1 failed" in failed.stdout, failed
    with sqlite3.connect(folder / "h.db") as db:
        names = sorted(row[0] for row in db.execute("SELECT name FROM tests"))
    assert names == sorted(IDS), names
    assert listed_ids(folder, "--rerun-failed", "r.xml") == ["robot/drive.sh[--speed 20]"]
    again = run_runner("--suite", "robot.xml", "--rerun-failed", "r.xml", "--no-output",
                       cwd=folder)
    assert again.returncode == 0 and "1 passed, 0 failed" in again.stdout, again


def test_a_name_with_the_value_names_each_instance(tmp_path):
    (tmp_path / "t.sh").write_text("#!/bin/sh\nexit 0\n")
    (tmp_path / "t.sh").chmod(0o755)
    (tmp_path / "robot.xml").write_text(
        '<suite name="robot"><test type="exec" name="drive at ${v}">t.sh'
        '<parametrize name="v">1, 2</parametrize></test>'
        '<test type="exec" name="grip">t.sh<parametrize name="v">1, 2</parametrize></test>'
        '</suite>')
    assert listed_ids(tmp_path) == ["robot/drive at 1", "robot/drive at 2",
                                    "robot/grip[v=1]", "robot/grip[v=2]"]


def test_bad_parametrize_exits_2_naming_file_and_line(tmp_path):
    cases = {
        '<parametrize name="speed"></parametrize>': "without values",
        '<parametrize name="1x">1</parametrize>': "a name is letters",
        '<parametrize>1</parametrize>': "a name is letters",
        '<parametrize name="a">1</parametrize><parametrize name="a">2</parametrize>':
            "given twice",
        '<parametrize name="a" values="1">1</parametrize>': "unknown attribute 'values'",
        '<parametrize name="a">1</parametrize><other/>': "<other> inside <test>",
        '<parametrize name="a">' + ",".join(map(str, range(101))) + '</parametrize>'
        '<parametrize name="b">' + ",".join(map(str, range(101))) + '</parametrize>':
            "more than 10000 instances",
    }
    for body, expected in cases.items():
        (tmp_path / "bad.xml").write_text(
            '<suite name="bad">\n<test type="exec" param="${a}">\nt.sh\n' + body +
            "\n</test>\n</suite>\n")
        run = run_runner("--suite", "bad.xml", "--list", cwd=tmp_path)
        assert run.returncode == 2, (body, run)
        assert "bad.xml:" in run.stderr and expected in run.stderr, (body, run.stderr)
    (tmp_path / "bad.xml").write_text(
        '<suite name="bad">\n<test type="exec" param="${speed}">t.sh'
        '<parametrize name="a">1</parametrize></test>\n</suite>\n')
    run = run_runner("--suite", "bad.xml", "--list", cwd=tmp_path)
    assert run.returncode == 2 and "bad.xml:2" in run.stderr and "speed" in run.stderr, run


def test_rtf2_files_without_parametrize_are_unchanged(tmp_path):
    (tmp_path / "t.sh").write_text("#!/bin/sh\nexit 0\n")
    (tmp_path / "t.sh").chmod(0o755)
    (tmp_path / "robot.xml").write_text(
        '<suite name="robot"><test type="exec" param="--speed 1">t.sh</test>'
        '<test type="exec" param="--speed 2">t.sh</test><test type="exec">t.sh</test></suite>')
    assert listed_ids(tmp_path) == ["robot/t.sh[--speed 1]", "robot/t.sh[--speed 2]",
                                    "robot/t.sh"]
