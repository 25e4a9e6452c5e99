"""Tests that live beside the suite's folder (`../tests/gripper.sh` of robot/robot.xml, issue
38 item 10): no ".." in their ids. The id is the path from the folder the suite's folder and the
test share (`robot/tests/gripper.sh`), the same in --list, --filter, the reports,
--rerun-failed and the history (docs/reference/test-ids.md); CTest's names are checked in
test_discover_tests.py. Run from the suite's folder with relative paths."""
import json
import sqlite3

from conftest import run_runner

SUITE = """<suite name="robot">
  <test type="exec">../tests/gripper.sh</test>
  <test type="exec">../tests/arm/joint.sh</test>
  <test type="exec">local.sh</test>
  <test type="exec">tests/gripper.sh</test>
</suite>
"""
IDS = ["robot/tests/gripper.sh", "robot/tests/arm/joint.sh", "robot/local.sh",
       "robot/tests/gripper.sh[2]"]


def script(path, body):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(body)
    path.chmod(0o755)


def layout(tmp_path):
    """ws/robot/robot.xml and ws/tests/: gripper.sh fails when FAIL is set, joint.sh passes;
    robot/local.sh and robot/tests/gripper.sh (inside the suite's folder) pass."""
    suite = tmp_path / "robot"
    script(tmp_path / "tests" / "gripper.sh", '#!/bin/sh\n[ -z "$FAIL" ]\n')
    script(tmp_path / "tests" / "arm" / "joint.sh", "#!/bin/sh\nexit 0\n")
    script(suite / "local.sh", "#!/bin/sh\nexit 0\n")
    script(suite / "tests" / "gripper.sh", "#!/bin/sh\nexit 0\n")
    (suite / "robot.xml").write_text(SUITE)
    return suite


def listed_ids(folder, *args):
    run = run_runner("--suite", "robot.xml", "--list", "--output", "json:-", *args, cwd=folder)
    assert run.returncode == 0, run
    return [t["id"] for s in json.loads(run.stdout)["suites"] for t in s["tests"]]


def test_no_id_holds_dot_dot_and_each_stays_unique(tmp_path):
    folder = layout(tmp_path)
    assert listed_ids(folder) == IDS
    text = run_runner("--suite", "robot.xml", "--list", cwd=folder)
    assert ".." not in text.stdout.replace("../tests/", ""), text  # the paths, not the ids
    run = run_runner("--suite", "robot.xml", "--output", "json:r.json", cwd=folder)
    assert run.returncode == 0, run
    report = json.loads((folder / "r.json").read_text())
    ids = [t["extra"]["robotology.rtf"]["id"] for t in report["results"]["tests"]]
    assert ids == IDS, ids
    assert "/../" not in run.stdout, run


def test_filter_rerun_failed_and_history_name_the_same_id(tmp_path):
    folder = layout(tmp_path)
    assert listed_ids(folder, "--filter", "robot/tests/gripper.sh") == ["robot/tests/gripper.sh"]
    run = run_runner("--suite", "robot.xml", "--filter", "robot/tests/gripper.sh",
                     "--output", "json:one.json", cwd=folder)
    assert run.returncode == 0 and "1 passed, 0 failed" in run.stdout, run

    failed = run_runner("--suite", "robot.xml", "--output", "junit:r.xml", "--history", "h.db",
                        cwd=folder, env={"FAIL": "1"})
    assert failed.returncode == 1 and "3 passed, 1 failed" in failed.stdout, failed
    with sqlite3.connect(folder / "h.db") as db:
        names = sorted(row[0] for row in db.execute("SELECT name FROM tests"))
    assert names == sorted(IDS), names
    rerun = run_runner("--suite", "robot.xml", "--rerun-failed", "r.xml", "--list",
                       "--output", "json:-", cwd=folder)
    assert rerun.returncode == 0, rerun
    assert [t["id"] for s in json.loads(rerun.stdout)["suites"] for t in s["tests"]] == \
        ["robot/tests/gripper.sh"], rerun
    again = run_runner("--suite", "robot.xml", "--rerun-failed", "r.xml", "--no-output",
                       cwd=folder)
    assert again.returncode == 0 and "1 passed, 0 failed" in again.stdout, again
