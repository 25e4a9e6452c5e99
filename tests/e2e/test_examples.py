"""The examples (examples/) run as the README says: each example suite through the real runner
(C++, scripts, the robot's world), all three at once as `./run.sh example` runs them, the C++
test plug-in alone with params, and the program using the library from its own main().
Every run is marked with an environment variable its processes inherit, so a process left
behind (the MQTT broker, the simulated robot) is found by its mark. The runner starts in a copy
of the build tree's examples folder and is given relative paths, as the README's
`cd examples && robottestingframework-testrunner --suite example.xml`; only the quick start run
starts elsewhere, with absolute paths, as `./run.sh example` does."""
import json
import os
import re
import shutil
import socket
import subprocess
import time
import uuid

import pytest

from conftest import (BUILD_DIR, SOURCE_DIR, run_runner, validate_ctrf, validate_junit,
                      validate_tap)

EXAMPLES = BUILD_DIR / "examples"
MY_TEST = EXAMPLES / "libMyTest.so"

# Suite file -> the tests it must pass, by the name each gives itself (shown beside its id).
SUITES = {
    "example.xml": ["MyTest", "MyTest"],
    "scripts.xml": ["python example", "lua example", "ruby example", "tap example"],
    "robot/robot.xml": ["JointStatesTest", "JointLimits"],
}


def marked_processes(mark):
    """(pid, command line) of the live processes whose environment holds RTF_E2E_MARK=mark."""
    found = []
    needle = f"RTF_E2E_MARK={mark}".encode()
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                if f.read().rsplit(")", 1)[1].split()[0] == "Z":
                    continue  # a zombie holds nothing; its parent reaps it
            with open(f"/proc/{entry}/environ", "rb") as f:
                if needle not in f.read().split(b"\0"):
                    continue
            with open(f"/proc/{entry}/cmdline", "rb") as f:
                found.append((int(entry), f.read().replace(b"\0", b" ").decode(errors="replace")))
        except (OSError, IndexError):
            continue  # gone meanwhile, or not ours to read
    return found


@pytest.fixture
def mark():
    """A fresh mark; after the test, no process carrying it may be alive."""
    value = uuid.uuid4().hex
    yield value
    deadline = time.monotonic() + 5  # the runner has exited; give the kernel a moment
    left = marked_processes(value)
    while left and time.monotonic() < deadline:
        time.sleep(0.05)
        left = marked_processes(value)
    for pid, _ in left:
        try:
            os.kill(pid, 9)
        except OSError:
            pass
    assert not left, f"processes left behind: {left}"


def examples_copy(tmp_path):
    """A copy of the build tree's examples folder (what a user's build leaves there), so that
    the results, logs and attachments of a run from it land under tmp_path."""
    folder = tmp_path / "examples"
    shutil.copytree(EXAMPLES, folder, ignore=shutil.ignore_patterns(
        "rtf-logs", "rtf-attachments", "result.txt", "CMakeFiles", "cmake_install.cmake"))
    return folder


def ports_file(folder, copies=1):
    """A resource file like examples/robot/ports.json, with free ports (other runs share the
    machine): `copies` items in each pool."""
    pools = {"broker_port": [{"id": str(free_port())} for _ in range(copies)],
             "robot_port": [{"id": str(free_port())} for _ in range(copies)]}
    path = folder / "ports.json"
    path.write_text(json.dumps({"version": {"major": 1, "minor": 0}, "local": [pools]}))
    return path


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def check_passed(run, junit, names):
    """Each name passed (console and JUnit), as many times as listed; nothing else ran."""
    assert run.returncode == 0, run
    for name in set(names):
        # "passed  ID (NAME)  (0.1 s)", or "passed  NAME  (0.1 s)" when the id is the name.
        lines = re.findall(rf"^\s*passed\s+(?:\S+/)?(?:.*? \()?{re.escape(name)}\)?\s+\(", run.stdout,
                           re.MULTILINE)
        assert len(lines) == names.count(name), f"{name}: {lines}\n{run}"
    assert re.search(rf"^{len(names)} passed, 0 failed$", run.stdout, re.MULTILINE), run
    validate_junit(junit)
    xml = junit.read_text()
    assert xml.count("<testcase") == len(names), xml
    for name in set(names):
        # The id's name="...", or the display name's <property name="rtf.name.S.T" value="...">.
        assert xml.count(f'name="{name}"') + xml.count(f'value="{name}"') >= names.count(name), xml
    assert "<failure" not in xml and "<error" not in xml and "<skipped" not in xml, xml


@pytest.mark.parametrize("isolation", ["none", "process"])
@pytest.mark.parametrize("suite", list(SUITES))
def test_example_suite_passes(tmp_path, mark, suite, isolation):
    examples = examples_copy(tmp_path)
    junit = examples / "junit.xml"
    run = run_runner("--suite", suite, "--isolation", isolation, "--verbose",
                     "--resources", ports_file(examples).name,
                     "--output", "junit:junit.xml", cwd=examples, timeout=60,
                     env={"RTF_E2E_MARK": mark})
    check_passed(run, junit, SUITES[suite])


@pytest.mark.parametrize("isolation", ["none", "process"])
def test_the_robot_example_takes_its_ports_from_variables(tmp_path, mark, isolation):
    broker, robot = free_port(), free_port()
    examples = examples_copy(tmp_path)
    junit = examples / "junit.xml"
    run = run_runner("--suite", "robot/robot.xml", "--isolation", isolation,
                     "--resources", ports_file(examples).name,
                     "--verbose", "--var", f"robot_port={robot}", "--var",
                     f"broker_port={broker}", "--output", "junit:junit.xml", cwd=examples,
                     timeout=60, env={"RTF_E2E_MARK": mark})
    check_passed(run, junit, SUITES["robot/robot.xml"])
    assert f"TCP port 127.0.0.1:{robot}" in run.output, run
    assert f"TCP port 127.0.0.1:{broker}" in run.output, run
    assert "not used" not in run.stderr, run
    # Its real measurements, with limits, and the plot it attaches (issue 22).
    xml = junit.read_text()
    assert "[[PROPERTY|joint tracking error=" in xml, xml
    assert "[[PROPERTY|joint state rate=" in xml and "[[PROPERTY|message rate=" in xml, xml
    plots = list((examples / "rtf-attachments").glob("*-elbow-tracking.svg"))
    assert len(plots) == 1 and "<polyline" in plots[0].read_text(), plots
    assert f"[[ATTACHMENT|{plots[0]}]]" in xml, xml


def test_the_quick_start_example_run(tmp_path, mark):
    """The three suites in one run with a report of each type, as `./run.sh example` runs
    them: from a folder of reports, the suites in the build tree named by absolute paths (on
    purpose: the one example run that starts outside the suites' folder)."""
    started = time.monotonic()
    run = run_runner(*[arg for suite in SUITES for arg in ("--suite", EXAMPLES / suite)],
                     "--resources", ports_file(tmp_path).name, "--verbose", "--output",
                     "text:example.txt", "--output",
                     "junit:example.xml", "--output", "tap:example.tap", "--output",
                     "json:example.json", "--output", "html:example.html", cwd=tmp_path,
                     timeout=60, env={"RTF_E2E_MARK": mark})
    elapsed = time.monotonic() - started
    check_passed(run, tmp_path / "example.xml", [n for names in SUITES.values() for n in names])
    assert elapsed < 30, f"the example run took {elapsed:.1f} s"
    total = sum(len(names) for names in SUITES.values())
    assert validate_tap(tmp_path / "example.tap")["count"] == len(SUITES)
    assert validate_ctrf(tmp_path / "example.json")["results"]["summary"]["passed"] == total
    assert "tap example" in (tmp_path / "example.html").read_text()
    text = (tmp_path / "example.txt").read_text()
    for name in ("example", "scripts", "robot", "JointLimits", "tap example"):
        assert name in text, text
    # What the fixtures did: the C++ and Python fixtures report, the process fixture waited
    # for the broker and the calibration, and kept each process's output in its log.
    assert "starting example-bot" in run.output, run
    assert "starting the world: --world empty" in run.output, run
    assert re.search(r"'simulated robot' is ready after", run.output), run
    logs = tmp_path / "rtf-logs" / "robot"
    assert "mosquitto" in (logs / "mqtt_broker.log").read_text()
    assert "calibrated" in (logs / "simulated_robot.log").read_text()
    # The scripts received their param and the suite's environment.
    assert "param: --joints 6" in run.output, run
    assert "arguments '--speed 3', environment '--robot example-bot'" in run.output, run


def test_two_copies_of_the_robot_example_run_side_by_side_on_ports_of_a_pool(tmp_path, mark):
    examples = examples_copy(tmp_path)
    ports = ports_file(examples, copies=2)
    pools = json.loads(ports.read_text())["local"][0]
    junit = examples / "junit.xml"
    robot = "robot/robot.xml"
    run = run_runner("-j", "2", "--resources", ports.name, "--suite", robot, "--suite", robot,
                     "--verbose", "--output", "junit:junit.xml", cwd=examples, timeout=90,
                     env={"RTF_E2E_MARK": mark})
    assert run.returncode == 0, run
    assert re.search(r"^4 passed, 0 failed$", run.stdout, re.MULTILINE), run
    validate_junit(junit)
    assert junit.read_text().count("<testcase") == 4
    for pool in ("broker_port", "robot_port"):  # each copy on ports of its own
        for item in pools[pool]:
            assert f"TCP port 127.0.0.1:{item['id']}" in run.output, run


def test_example_plugin_reads_its_param(tmp_path):
    examples = examples_copy(tmp_path)
    ok = run_runner("--test", MY_TEST.name, "--param", "--speed 30", "--no-output",
                    cwd=examples)
    assert ok.returncode == 0, ok
    # 90 degrees at 0.001 deg/s takes longer than the test allows.
    slow = run_runner("--test", MY_TEST.name, "--param", "--speed 0.001", "--no-output",
                      cwd=examples)
    assert slow.returncode == 1, slow
    assert "too slow" in slow.output, slow
    # Without --speed its setup reports an error.
    missing = run_runner("--test", MY_TEST.name, "--no-output", cwd=examples)
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


def test_the_robot_example_runs_as_written_from_its_folder(tmp_path, mark):
    """`cd examples/robot && robottestingframework-testrunner --suite robot.xml`, no flag: the
    ports come from the suite's <resource pool=... default=...>. A copy of the build tree's
    folder, so the result file and the world's logs land under tmp_path."""
    folder = tmp_path / "robot"
    shutil.copytree(EXAMPLES / "robot", folder,
                    ignore=shutil.ignore_patterns("rtf-logs", "result.txt", "CMakeFiles"))
    run = run_runner("--suite", "robot.xml", cwd=folder, timeout=90,
                     env={"RTF_E2E_MARK": mark})
    assert run.returncode == 0, run
    assert re.search(r"^2 passed, 0 failed$", run.stdout, re.MULTILINE), run
    assert (folder / "rtf-logs" / "robot" / "simulated_robot.log").is_file()


def test_configuring_the_build_for_the_examples_needs_no_npm_and_no_pypi(tmp_path):
    """`./run.sh example` configures and builds: that must not reach the npm registry or PyPI.
    An `npm` first on PATH records any call; configuring a fresh build tree must not call it,
    nor make the readers' virtual environment (the report checkers are the end-to-end tests'
    CTest fixtures, e2e.node_tools and e2e.python_tools)."""
    fake = tmp_path / "fake-bin"
    fake.mkdir()
    calls = tmp_path / "npm-calls.txt"
    (fake / "npm").write_text(f'#!/bin/sh\necho "npm $*" >> "{calls}"\nexit 1\n')
    (fake / "npm").chmod(0o755)
    env = {**os.environ, "PATH": f"{fake}:{os.environ['PATH']}"}
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    configured = subprocess.run(
        ["cmake", "-S", str(SOURCE_DIR), "-B", str(tmp_path / "build"), *generator,
         "-DRTF_BUILD_BENCH=OFF"], capture_output=True, text=True, timeout=240, env=env)
    assert configured.returncode == 0, configured.stdout + configured.stderr
    assert not calls.exists(), calls.read_text()
    assert not (tmp_path / "build" / "python-tools").exists()
    # The fixtures are there for the tests.
    listed = subprocess.run(["ctest", "--test-dir", str(tmp_path / "build"), "-N", "-R",
                             "^e2e.(node|python)_tools$"], capture_output=True, text=True,
                            timeout=60)
    assert "e2e.node_tools" in listed.stdout, listed.stdout
    assert "e2e.python_tools" in listed.stdout, listed.stdout
