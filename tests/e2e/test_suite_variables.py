"""Suite variables, --var, --var-file, --list-vars and test files (issue 10, items 1 and 2),
through the real runner."""
import shutil
import sys
from pathlib import Path

import pytest

from conftest import marked, plugin, run_runner

ECHO = plugin("echo_test")
ACTOR = Path(__file__).parent / "world" / "actor.py"


@pytest.fixture(params=["process", "none"])
def isolation(request):
    return request.param


def write(path, text):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


# --- 1. Suite variables ----------------------------------------------------------------------

def test_a_suite_variable_reaches_plugin_param_environment_and_timeout(tmp_path, isolation):
    suite = write(tmp_path / "suite.xml", f"""<suite name="arm">
  <variable name="robot">icubSim</variable>
  <variable name="plugins">{Path(ECHO).parent}</variable>
  <environment>--robot ${{robot}}</environment>
  <test param="--expect-param ${{robot}} --expect-env ${{robot}}"
        timeout="${{limit}}">${{plugins}}/echo_test.so</test>
  <variable name="limit">30</variable>
</suite>
""")
    run = run_runner("--suite", suite.name, "--isolation", isolation, "-v", "--no-output",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert "[--expect-param] [icubSim]" in run.output, run
    assert "environment [--robot icubSim]" in run.output, run

    run = run_runner("--suite", suite.name, "--isolation", isolation, "-v", "--no-output",
                     "--var", "robot=icub", cwd=tmp_path)
    assert run.returncode == 0, run
    assert "[--expect-param] [icub]" in run.output, run
    assert "warning: --var" not in run.stderr, run  # the variable was read


def test_var_beats_var_files_which_beat_the_suite(tmp_path):
    suite = write(tmp_path / "suite.xml", f"""<suite name="s">
  <variable name="a">suite</variable>
  <variable name="b">suite</variable>
  <variable name="c">suite</variable>
  <variable name="d">suite</variable>
  <test param="${{a}}-${{b}}-${{c}}-${{d}}">{ECHO}</test>
</suite>
""")
    first = write(tmp_path / "first.env", "# first\nb=first\nc=first\nd=first\n")
    second = write(tmp_path / "second.env", "c = second\nd=second\n")
    args = ["--suite", suite.name, "--var-file", first.name, "--var-file", second.name, "--var",
            "d=cli"]
    run = run_runner(*args, "--list", cwd=tmp_path)
    assert run.returncode == 0, run
    assert "param suite-first-second-cli" in run.stdout, run

    run = run_runner(*args, "--list-vars", cwd=tmp_path)
    assert run.returncode == 0, run
    assert f"a = suite  ({suite.name}:2)" in run.stdout, run
    assert f"b = first  ({first.name}:2)" in run.stdout, run
    assert f"c = second  ({second.name}:1)" in run.stdout, run
    assert "d = cli  (--var)" in run.stdout, run


def test_environment_and_literal_dollar_braces(tmp_path):
    suite = write(tmp_path / "suite.xml", f"""<suite name="s">
  <test param="--home ${{env:RTF_E2E_HOME}} $${{kept}} ${{{{also}}">{ECHO}</test>
</suite>
""")
    run = run_runner("--suite", suite.name, "--list", cwd=tmp_path, env={"RTF_E2E_HOME": "/home/r"})
    assert run.returncode == 0, run
    assert "param --home /home/r ${kept} ${also}" in run.stdout, run


def world_saying_speed(tmp_path):
    return write(tmp_path / "world.xml", f"""<world name="w" logdir="logs">
  <variable name="speed">1</variable>
  <process name="p" command="{sys.executable} {ACTOR} --say v=${{speed}}">
    <ready timeout="10s"><output>^v=</output></ready>
  </process>
</world>
""")


def test_a_suite_variable_reaches_the_world_file_and_var_beats_it(tmp_path, isolation, marker):
    world = world_saying_speed(tmp_path)
    suite = write(tmp_path / "suite.xml", f"""<suite name="s">
  <variable name="speed">7</variable>
  <fixture type="process">{world.name}</fixture>
  <test>{plugin("passing_test")}</test>
</suite>
""")
    log = tmp_path / "logs" / "p.log"
    run = run_runner("--suite", suite.name, "--isolation", isolation, "--no-output", cwd=tmp_path,
                     env=marked(marker), timeout=60)
    assert run.returncode == 0, run
    assert "v=7" in log.read_text(), run

    run = run_runner("--suite", suite.name, "--isolation", isolation, "--no-output", "--var",
                     "speed=9", cwd=tmp_path, env=marked(marker), timeout=60)
    assert run.returncode == 0, run
    assert "v=9" in log.read_text(), run
    assert "not used" not in run.stderr, run


def test_the_pool_items_of_the_suite_reach_the_world_file(tmp_path, isolation, marker):
    # Issue 39, 2: ${resource.NAME} in a world file reached the process as the runner's
    # internal placeholder ("\x1eresource.slot\x1e"), silently.
    world = write(tmp_path / "world.xml", f"""<world name="w" logdir="logs">
  <process name="p" command="{sys.executable} {ACTOR} --say slot=${{resource.slot}}">
    <ready timeout="10s"><output>^slot=</output></ready>
  </process>
</world>
""")
    suite = write(tmp_path / "suite.xml", f"""<suite name="s">
  <resource pool="slot" count="2" default="7 8"/>
  <fixture type="process">{world.name}</fixture>
  <test>{plugin("passing_test")}</test>
</suite>
""")
    run = run_runner("--suite", suite.name, "--isolation", isolation, "--no-output", cwd=tmp_path,
                     env=marked(marker), timeout=60)
    assert run.returncode == 0, run
    assert (tmp_path / "logs" / "p.log").read_text().splitlines()[0] == "slot=7,8", run


def test_a_pool_the_suite_does_not_take_in_a_world_file_names_file_and_line(tmp_path, marker):
    world = write(tmp_path / "world.xml", f"""<world name="w" logdir="logs">
  <process name="p" command="{sys.executable} {ACTOR} --say slot=${{resource.other}}">
    <ready timeout="10s"><output>^slot=</output></ready>
  </process>
</world>
""")
    suite = write(tmp_path / "suite.xml", f"""<suite name="s">
  <resource pool="slot" default="7"/>
  <fixture type="process">{world.name}</fixture>
  <test>{plugin("passing_test")}</test>
</suite>
""")
    run = run_runner("--suite", suite.name, "--no-output", cwd=tmp_path, env=marked(marker),
                     timeout=60)
    # A configuration error before the run: the world file is read with the plan.
    assert run.returncode == 2, run
    assert ("world.xml:2: ${resource.other} but the suite takes no item of pool other (add "
            '<resource pool="other"/> to the suite)') in run.stdout + run.stderr, run
    assert not (tmp_path / "logs" / "p.log").exists(), run


def test_an_undefined_variable_names_file_line_and_the_close_ones(tmp_path):
    suite = write(tmp_path / "suite.xml", f"""<suite name="s">
  <variable name="robot_port">10001</variable>
  <variable name="camera">left</variable>
  <test param="--port ${{robot_prot}}">{ECHO}</test>
</suite>
""")
    run = run_runner("--suite", suite.name, "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert f"{suite.name}:4: undefined variable ${{robot_prot}}; did you mean ${{robot_port}}?" \
        in run.stderr, run


def test_a_variable_that_refers_to_itself_names_the_cycle(tmp_path):
    suite = write(tmp_path / "suite.xml", f"""<suite name="s">
  <variable name="a">x${{b}}</variable>
  <variable name="b">${{a}}</variable>
  <test>{ECHO}</test>
</suite>
""")
    run = run_runner("--suite", suite.name, "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert f"{suite.name}:2: variable ${{a}} refers to itself: a -> b -> a" in run.stderr, run


@pytest.mark.parametrize("value, expected", [
    ("robot", "--var robot: no '=' in 'robot'"),
    ("=icub", "no name before '=' at column 1"),
    ("1robot=x", "'1' at column 1 of '1robot=x'"),
    ("ro bot=x", "' ' at column 3 of 'ro bot=x'"),
])
def test_a_malformed_var_is_a_usage_error_with_the_position(tmp_path, value, expected):
    run = run_runner("--test", ECHO, "--var", value, "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert expected in run.stderr, run


def test_a_malformed_var_file_line_names_file_line_and_column(tmp_path):
    bad = write(tmp_path / "robot.env", "# ok\nrobot=icub\nport 10001\n")
    run = run_runner("--test", ECHO, "--var-file", bad.name, "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert f"--var-file {bad.name}:3: no '=' in 'port 10001'" in run.stderr, run
    run = run_runner("--test", ECHO, "--var-file", "none.env", "--no-output",
                     cwd=tmp_path)
    assert run.returncode == 2, run
    assert "none.env: cannot read the variable file" in run.stderr, run


# --- 2. Test files ---------------------------------------------------------------------------

def left_arm(tmp_path):
    """tests/left_arm.xml, its plug-in beside it in tests/lib/ (a path relative to the file)."""
    lib = tmp_path / "tests" / "lib"
    lib.mkdir(parents=True)
    shutil.copy(ECHO, lib / "echo_test.so")
    return write(tmp_path / "tests" / "left_arm.xml", """<test name="left arm" timeout="5"
      param="--expect-param ${robot} --part ${part}" tags="arm">
  <variable name="part">left_arm</variable>
  lib/echo_test.so
</test>
""")


def test_one_test_file_runs_with_each_suites_variables(tmp_path, isolation):
    left_arm(tmp_path)
    sim = write(tmp_path / "sim.xml", """<suite name="sim">
  <variable name="robot">icubSim</variable>
  <test file="tests/left_arm.xml"/>
</suite>
""")
    real = write(tmp_path / "real.xml", """<suite name="real">
  <variable name="robot">icub</variable>
  <variable name="part">right_arm</variable>
  <test file="tests/left_arm.xml" timeout="9" name="right arm"/>
</suite>
""")
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    run = run_runner("--suite", sim, "--suite", real, "--list", cwd=elsewhere)
    assert run.returncode == 0, run
    lib = tmp_path / "tests" / "lib" / "echo_test.so"
    assert f"sim/left arm\n      type dll, plug-in {lib}\n" \
           "      param --expect-param icubSim --part left_arm\n      tags arm\n" \
           "      timeout 5s\n" in run.stdout, run
    assert "real/right arm\n" in run.stdout and \
           "param --expect-param icub --part right_arm\n" in run.stdout and \
           "timeout 9s\n" in run.stdout, run

    run = run_runner("--suite", sim, "--suite", real, "--isolation", isolation, "-v",
                     "--no-output", cwd=elsewhere)
    assert run.returncode == 0, run
    assert "[--expect-param] [icubSim] [--part] [left_arm]" in run.output, run
    assert "[--expect-param] [icub] [--part] [right_arm]" in run.output, run


def test_a_missing_test_file_names_the_path_and_the_suite_line(tmp_path):
    suite = write(tmp_path / "suite.xml", """<suite name="s">

  <test file="tests/nope.xml"/>
</suite>
""")
    run = run_runner("--suite", suite.name, "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    # The test file is named from the suite's folder, as given (here the run's folder).
    assert f"{suite.name}:3: <test file=\"tests/nope.xml\">: ./tests/nope.xml: cannot read " \
           "the test file" in run.stderr, run


def test_a_file_that_is_not_a_test_names_the_path_and_the_suite_line(tmp_path):
    other = write(tmp_path / "other.xml", "<suite name='x'><test>a.so</test></suite>\n")
    suite = write(tmp_path / "suite.xml", '<suite name="s">\n  <test file="other.xml"/>\n'
                                          '</suite>\n')
    run = run_runner("--suite", suite.name, "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert f"{suite.name}:2: in the test file named here: ./{other.name}:1: the root element " \
           "is <suite>; a test file holds one <test>" in run.stderr, run


def test_an_undefined_variable_in_a_test_file_names_both_files(tmp_path):
    left_arm(tmp_path)
    suite = write(tmp_path / "suite.xml", '<suite name="s">\n  <test file="tests/left_arm.xml"/>'
                                          '\n</suite>\n')
    run = run_runner("--suite", suite.name, "--no-output", cwd=tmp_path)
    assert run.returncode == 2, run
    assert f"{suite.name}:2: in the test file named here: ./tests/left_arm.xml:1: " \
           "undefined variable ${robot}" in run.stderr, run


def test_a_var_read_only_by_a_test_file_is_not_called_unused(tmp_path):
    left_arm(tmp_path)
    suite = write(tmp_path / "suite.xml", '<suite name="s">\n  <variable name="robot">r'
                                          '</variable>\n  <test file="tests/left_arm.xml"/>\n'
                                          '</suite>\n')
    run = run_runner("--suite", suite.name, "--var", "part=wrist", "--var", "nobody=1", "--list",
                     cwd=tmp_path)
    assert run.returncode == 0, run
    assert "param --expect-param r --part wrist\n" in run.stdout, run
    assert "--var part=wrist is not used" not in run.stderr, run
    assert "--var nobody=1 is not used" in run.stderr, run
