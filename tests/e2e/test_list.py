"""--list and --list --output json:FILE (issue 10, item 4): what would run, with nothing loaded
or started."""
import json
import sys
from pathlib import Path

from conftest import marked, plugin, run_runner

ACTOR = Path(__file__).parent / "world" / "actor.py"


def suite_that_would_leave_traces(tmp_path):
    """A suite whose world touches world.touched and whose Python test touches loaded.touched
    when its file is loaded: --list must leave neither."""
    world = tmp_path / "world.xml"
    world.write_text(f"""<world name="w" logdir="logs">
  <process name="p" command="{sys.executable} {ACTOR} --touch {tmp_path / 'world.touched'}">
    <ready timeout="10s"><file>{tmp_path / 'world.touched'}</file></ready>
  </process>
</world>
""")
    script = tmp_path / "camera.py"
    script.write_text(f"open({str(tmp_path / 'loaded.touched')!r}, 'w').close()\n"
                      "class TestCase:\n    def run(self):\n        pass\n")
    suite = tmp_path / "suite.xml"
    suite.write_text(f"""<suite name="robot">
  <variable name="robot">icubSim</variable>
  <timeout>20</timeout>
  <fixture type="process">{world}</fixture>
  <test param="--robot ${{robot}}" tags="camera,slow" timeout="3">camera.py</test>
  <test name="encoders" type="dll">{plugin("passing_test")}</test>
</suite>
""")
    return suite


def test_list_prints_what_would_run_and_starts_nothing(tmp_path, marker):
    suite = suite_that_would_leave_traces(tmp_path)
    run = run_runner("--suite", suite.name, "--list", "--var", "robot=icub", "--param", "--fast",
                     cwd=tmp_path, env=marked(marker))
    assert run.returncode == 0, run
    assert f"suite robot ({suite.name})\n" in run.stdout, run
    assert (f"  robot/camera.py\n      type python, plug-in {tmp_path / 'camera.py'}\n"
            "      param --robot icub\n      tags camera,slow\n      timeout 3s\n") \
        in run.stdout, run
    # The suite's <timeout> and --param apply as they would in the run.
    assert (f"  robot/encoders\n      type dll, plug-in {plugin('passing_test')}\n"
            "      param --fast\n      timeout 20s\n") in run.stdout, run
    assert "2 tests in 1 suite\n" in run.stdout, run
    assert not (tmp_path / "loaded.touched").exists()
    assert not (tmp_path / "world.touched").exists()
    assert not (tmp_path / "logs").exists()
    assert not (tmp_path / "result.txt").exists()


def test_list_writes_json(tmp_path, marker):
    suite = suite_that_would_leave_traces(tmp_path)
    out = tmp_path / "list.json"
    run = run_runner("--suite", suite.name, "--list", "--output", "json:list.json", cwd=tmp_path,
                     env=marked(marker))
    assert run.returncode == 0, run
    listed = json.loads(out.read_text())
    [robot] = listed["suites"]
    assert robot["name"] == "robot" and robot["file"] == suite.name
    assert robot["fixtures"][0]["type"] == "process"
    camera, encoders = robot["tests"]
    assert camera["id"] == "robot/camera.py"
    assert camera["type"] == "python"
    assert camera["path"] == str(tmp_path / "camera.py")
    assert camera["param"] == "--robot icubSim"
    assert camera["tags"] == ["camera", "slow"]
    assert camera["timeout"] == 3
    assert encoders["id"] == "robot/encoders" and encoders["timeout"] == 20
    assert not (tmp_path / "loaded.touched").exists()
    assert not (tmp_path / "world.touched").exists()


def test_list_shows_the_locks_pools_and_exclusive_a_suite_takes(tmp_path):
    (tmp_path / "pools.json").write_text(
        '{"version": {"major": 1, "minor": 0}, "local": [{"ros_domain": [{"id": "7"}]}]}')
    (tmp_path / "arm.xml").write_text(f"""<suite name="arm" exclusive="true">
  <resource lock="robot:left-arm"/>
  <resource pool="ros_domain" count="1"/>
  <test name="reach" type="dll">{plugin("passing_test")}</test>
</suite>
""")
    (tmp_path / "plain.xml").write_text(
        f'<suite name="plain"><test type="dll">{plugin("passing_test")}</test></suite>')
    out = tmp_path / "list.json"
    run = run_runner("--suite", "arm.xml", "--suite", "plain.xml", "--resources", "pools.json",
                     "--list", "--output", "json:list.json", cwd=tmp_path)
    assert run.returncode == 0, run
    assert ("  takes lock robot:left-arm, 1 of pool ros_domain, the machine alone (exclusive)\n"
            "  arm/reach\n") in run.stdout, run
    assert run.stdout.count("  takes ") == 1, run  # nothing said of a suite that takes nothing
    arm, plain = json.loads(out.read_text())["suites"]
    assert arm["resources"] == [{"lock": "robot:left-arm"}, {"pool": "ros_domain", "count": 1}]
    assert arm["exclusive"] is True
    assert plain["resources"] == [] and plain["exclusive"] is False


def test_list_of_a_bad_suite_is_a_configuration_error(tmp_path):
    suite = tmp_path / "suite.xml"
    suite.write_text("<suite><test param='${nope}'>a.so</test></suite>\n")
    run = run_runner("--suite", suite.name, "--list", cwd=tmp_path)
    assert run.returncode == 2, run
    assert f"{suite.name}:1: undefined variable ${{nope}}" in run.stderr, run
