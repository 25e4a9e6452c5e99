"""CTest, one world per suite: robottestingframework_discover_tests over suites with worlds
(ctest_worlds_project/, copied under the build tree with the build tree's robot example and
built against the installed tree). Each suite's world starts once for all its tests (a
world:up test sets it up in a keeper, a world:down test stops it), tests of one suite never
clash, suites in private networks bind one port side by side, `ctest -R` of one test brings
its world along, a world that fails fails its tests with its reason, and ctest killed while a
test runs leaves no process behind. Suites that share a world (scope="run") share one keeper:
one start for all of them (docs/how-to/ctest-shared-worlds.md). Each world counts its starts in a
file."""
import os
import re
import shutil
import signal
import socket
import subprocess
import time
import uuid
from pathlib import Path

import pytest

from conftest import BUILD_DIR

PROJECT = Path(__file__).parent / "ctest_worlds_project"
ROBOT = BUILD_DIR / "examples" / "robot"


def run(args, timeout=180, cwd=None, env=None):
    return subprocess.run([str(a) for a in args], capture_output=True, text=True,
                          timeout=timeout, cwd=cwd, env=env)


def check(args, timeout=300):
    result = run(args, timeout)
    assert result.returncode == 0, f"{args}\n{result.stdout}\n{result.stderr}"
    return result


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def private_networks_work():
    """A private network needs user namespaces (or root); the runner's probe says."""
    return Path("/proc/self/ns/net").exists() and run(
        ["unshare", "--user", "--net", "--map-root-user", "true"], timeout=10).returncode == 0


@pytest.fixture(scope="module")
def prefix(tmp_path_factory):
    """A fresh install of the build tree."""
    folder = tmp_path_factory.mktemp("prefix")
    check(["cmake", "--install", BUILD_DIR, "--prefix", folder])
    return folder


@pytest.fixture(scope="module")
def project(tmp_path_factory, prefix):
    """The build folder of ctest_worlds_project built against a fresh install."""
    source = tmp_path_factory.mktemp("worlds") / "source"
    shutil.copytree(PROJECT, source)
    shutil.copytree(ROBOT, source / "robot", ignore=shutil.ignore_patterns(
        "rtf-logs", "rtf-attachments", "result.txt", "CMakeFiles", "cmake_install.cmake"))
    # Ports of their own: other runs share the machine.
    (source / "robot" / "ports.json").write_text(
        '{"version": {"major": 1, "minor": 0}, "local": [{'
        f'"broker_port": [{{"id": "{free_port()}"}}], '
        f'"robot_port": [{{"id": "{free_port()}"}}]}}]}}')
    build = source.parent / "build"
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    check(["cmake", "-S", source, "-B", build, *generator, "-Wdev",
           f"-DCMAKE_PREFIX_PATH={prefix}", f"-DFIXED_PORT={free_port()}",
           f"-DSHARED_PORT={free_port()}",
           "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON"], timeout=120)
    return build


def ctest(build, *args, timeout=180):
    return run(["ctest", "--test-dir", build, "--output-on-failure", *args], timeout)


def starts(build, name):
    path = build / "starts" / name
    return path.read_text().count("started") if path.exists() else 0


def robot_starts(build, output):
    """Starts of the robot's world: in the tests' output (--verbose) and the keepers' logs."""
    logs = "".join(p.read_text() for p in build.glob("rtf_discover_*_world/keeper.log"))
    return (output + logs).count("starting 'simulated robot'")


def test_the_robot_example_starts_its_world_once_under_ctest(project):
    for log in project.glob("rtf_discover_*_world/keeper.log"):
        log.unlink()
    result = ctest(project, "-j", "2", "-V", "-R", r"^PER_SUITE\.")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "100% tests passed, 0 tests failed out of 4" in result.stdout, result.stdout
    assert robot_starts(project, result.stdout) == 1, result.stdout
    # One world per test, as before (WORLD PER_TEST): one start per test.
    for log in project.glob("rtf_discover_*_world/keeper.log"):
        log.unlink()
    per_test = ctest(project, "-j", "2", "-V", "-R", r"^PER_TEST\.")
    assert per_test.returncode == 0, per_test.stdout + per_test.stderr
    assert robot_starts(project, per_test.stdout) == 2, per_test.stdout


def test_three_tests_of_a_fixed_port_world_share_it(project):
    before = starts(project, "fixed")
    result = ctest(project, "-j", "3", "-R", r"^host\.")
    assert result.returncode == 0, result.stdout
    assert "100% tests passed, 0 tests failed out of 5" in result.stdout, result.stdout
    assert starts(project, "fixed") - before == 1


@pytest.mark.skipif(not private_networks_work(), reason="no user namespaces here")
def test_two_private_suites_on_one_port_run_side_by_side(project):
    before = starts(project, "a"), starts(project, "b")
    result = ctest(project, "-j", "4", "-R", r"^private\.")
    assert result.returncode == 0, result.stdout
    assert "100% tests passed, 0 tests failed out of 8" in result.stdout, result.stdout
    assert (starts(project, "a") - before[0], starts(project, "b") - before[1]) == (1, 1)


def test_ctest_R_brings_the_world_of_one_test(project):
    before = starts(project, "fixed")
    result = ctest(project, "-R", r"^host\.fixed/two$")
    assert result.returncode == 0, result.stdout
    names = re.findall(r"Test +#\d+: (\S+)", result.stdout)
    assert names == ["host.fixed/world:up", "host.fixed/two", "host.fixed/world:down"], names
    assert starts(project, "fixed") - before == 1


def test_a_world_that_fails_fails_its_tests_with_its_reason(project):
    result = ctest(project, "-R", r"^broken\.")
    assert result.returncode != 0, result.stdout
    assert re.search(r"broken\.broken/world:up \.+\*+Failed", result.stdout), result.stdout
    assert "no licence for the simulator" in result.stdout, result.stdout
    assert "process 'simulator' exited with status 3 before it was ready" in result.stdout
    for test in ("one", "two"):
        assert re.search(rf"broken\.broken/{test} \.+\*+Not Run", result.stdout), result.stdout
    assert "Failed test dependencies: broken.broken/world:up" in result.stdout


def marked(mark):
    """{pid: (command line, carries a world's RTF_PROCESS_FIXTURE_ variable)} of the live
    processes whose environment holds RTF_E2E_MARK=mark."""
    found = {}
    needle = f"RTF_E2E_MARK={mark}".encode()
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                if f.read().rsplit(")", 1)[1].split()[0] == "Z":
                    continue
            with open(f"/proc/{entry}/environ", "rb") as f:
                environment = f.read().split(b"\0")
            if needle not in environment:
                continue
            with open(f"/proc/{entry}/cmdline", "rb") as f:
                command = f.read().replace(b"\0", b" ").decode(errors="replace")
            world = any(v.startswith(b"RTF_PROCESS_FIXTURE_") for v in environment)
            found[int(entry)] = (command, world)
        except (OSError, IndexError):
            continue
    return found


def kill_ctest_while_a_test_runs(project, how, running, jobs, pattern):
    """Starts ctest on the tests `pattern` selects, waits for the test that touches `running`,
    checks that exactly one keeper and a world's server are up, stops ctest with SIGKILL or
    Ctrl-C (SIGINT to its group, as a terminal's foreground job gets it) and checks that no
    process carrying this run's mark is left after 10 s."""
    mark = uuid.uuid4().hex
    running.unlink(missing_ok=True)
    ctest_run = subprocess.Popen(["ctest", "--test-dir", str(project), "-j", jobs, "-R", pattern],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                 env={**os.environ, "RTF_E2E_MARK": mark},
                                 start_new_session=True)
    try:
        deadline = time.monotonic() + 60
        while not running.exists() and time.monotonic() < deadline:
            time.sleep(0.05)
        assert running.exists(), "the test never ran"
        alive = marked(mark)
        keepers = [pid for pid, (command, _) in alive.items() if "--world-up" in command]
        assert len(keepers) == 1, alive
        assert any(world for _, world in alive.values()), alive  # the world's server
        if how == "SIGKILL":
            os.kill(ctest_run.pid, signal.SIGKILL)
        else:
            os.killpg(ctest_run.pid, signal.SIGINT)
        ctest_run.wait(timeout=20)
        deadline = time.monotonic() + 10
        left = marked(mark)
        while left and time.monotonic() < deadline:
            time.sleep(0.1)
            left = marked(mark)
        assert not left, f"left behind: {left}"
    finally:
        if ctest_run.poll() is None:
            ctest_run.kill()
            ctest_run.wait()
        for pid in marked(mark):
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass


@pytest.mark.skipif(not private_networks_work(), reason="no user namespaces here")
@pytest.mark.parametrize("how", ["SIGKILL", "Ctrl-C"])
def test_ctest_killed_while_a_test_runs_leaves_nothing_behind(project, how):
    kill_ctest_while_a_test_runs(project, how, project / "running", "2", r"^hang\.")


def test_the_world_options_say_what_is_wrong(project, prefix):
    runner = prefix / "bin" / "robottestingframework-testrunner"
    suites = project.parent / "source"
    shown = run([runner, "--help"])
    for option in ("--world-up DIR", "--world DIR", "--world-down DIR", "--shared-worlds DIR"):
        assert option in shown.stdout, shown.stdout
    alone = run([runner, "--suite", "fixed/fixed.xml", "--shared-worlds", project / "x"],
                cwd=suites)
    assert alone.returncode == 2 and "only with --world-up" in alone.stderr, alone
    nowhere = project / "no_keeper_here"
    for option in (["--filter", "fixed/one", "--world"], ["--world-down"]):
        missing = run([runner, "--suite", "fixed/fixed.xml", "--no-output", *option, nowhere],
                      cwd=suites)
        assert missing.returncode == 2, missing
        assert "no world keeper answers" in missing.stderr and str(nowhere) in missing.stderr
    world = project / "fixed_by_hand"
    up = run([runner, "--suite", "fixed/fixed.xml", "--no-output", "--var", f"port={free_port()}",
              "--world-up", world], cwd=suites)
    try:
        assert up.returncode == 0, up
        assert "the world of suite fixed is up" in up.stdout, up.stdout
        again = run([runner, "--suite", "fixed/fixed.xml", "--world-up", world], cwd=suites)
        assert again.returncode == 2 and "already runs there" in again.stderr, again
        other = run([runner, "--suite", "broken/broken.xml", "--no-output", "--world", world],
                    cwd=suites)
        assert other.returncode == 2, other
        assert "keeps the world of suite fixed, not of suite broken" in other.stderr, other
    finally:
        down = run([runner, "--suite", "fixed/fixed.xml", "--world-down", world], cwd=suites)
    assert down.returncode == 0, down
    assert "is down" in down.stdout, down.stdout
    both = run([runner, "--suite", "fixed/fixed.xml", "--world", world, "--world-down", world],
               cwd=suites)
    assert both.returncode == 2 and "one at a time" in both.stderr, both


def test_a_world_that_collapses_fails_the_running_test_and_its_world_down(project):
    result = ctest(project, "-R", r"^crash\.")
    assert result.returncode != 0, result.stdout
    assert re.search(r"crash\.crash/world:up \.+ +Passed", result.stdout), result.stdout
    for test in ("kills_the_world", "world:down"):
        assert re.search(rf"crash\.crash/{test} \.+\*+Failed", result.stdout), result.stdout
    assert "the world collapsed" in result.stdout, result.stdout
    assert "process 'fragile server' exited with status 3" in result.stdout, result.stdout
    assert "its tear-down failed" in result.stdout, result.stdout


def test_three_suites_sharing_a_world_start_it_once(project):
    before = starts(project, "shared")
    result = ctest(project, "-j", "3", "-R", r"^shared\.|^world:server:")
    assert result.returncode == 0, result.stdout
    # 3 suites x 2 tests, and the shared world's up and down.
    assert "100% tests passed, 0 tests failed out of 8" in result.stdout, result.stdout
    assert re.search(r"world:server:up \.+ +Passed", result.stdout), result.stdout
    assert starts(project, "shared") - before == 1
    listed = ctest(project, "-N")
    assert listed.stdout.count("world:server:up") == 1, listed.stdout  # one fixture, not 4


def test_ctest_R_brings_the_shared_world_of_one_test(project):
    before = starts(project, "shared")
    result = ctest(project, "-R", r"^shared\.shared_2/two$")
    assert result.returncode == 0, result.stdout
    names = re.findall(r"Test +#\d+: (\S+)", result.stdout)
    assert names == ["world:server:up", "shared.shared_2/two", "world:server:down"], names
    assert starts(project, "shared") - before == 1


@pytest.mark.parametrize("how", ["SIGKILL", "Ctrl-C"])
def test_ctest_killed_in_a_shared_world_leaves_nothing_behind(project, how):
    # One keeper: the shared world's, no suite's own.
    kill_ctest_while_a_test_runs(project, how, project / "shared_running", "3",
                                 r"^shared\.|^shared_hang\.")


def own_starts(build):
    """Starts of the mixed suite's own world: its keeper's log (made again at each world:up)."""
    return sum(log.read_text().count("starting 'own'")
               for log in build.glob("rtf_discover_mixed_*_world/keeper.log"))


def test_a_suite_with_a_world_of_its_own_joins_the_shared_world(project):
    before = starts(project, "shared")
    result = ctest(project, "-j", "3", "-R", r"^shared\.|^mixed\.")
    assert result.returncode == 0, result.stdout
    # 4 suites x 2 tests, the shared world's up and down, the mixed suite's own up and down.
    assert "100% tests passed, 0 tests failed out of 12" in result.stdout, result.stdout
    assert (starts(project, "shared") - before, own_starts(project)) == (1, 1)
    alone = ctest(project, "-R", r"^mixed\.shared_mixed/one$")
    assert alone.returncode == 0, alone.stdout
    names = re.findall(r"Test +#\d+: (\S+)", alone.stdout)
    assert names == ["world:server:up", "mixed.shared_mixed/world:up", "mixed.shared_mixed/one",
                     "mixed.shared_mixed/world:down", "world:server:down"], names
    assert (starts(project, "shared") - before, own_starts(project)) == (2, 1)
