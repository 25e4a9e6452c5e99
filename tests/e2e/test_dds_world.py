"""A real middleware world: Cyclone DDS (tests/e2e/dds/, docs/how-to/dds-world.md), through the
installed runner, from the suites' own folder. The world publishes on a DDS topic; its test
subscribes for 1 s, measures the rate and the latency against limits, and checks that every
sample carries its own network namespace's token and comes from one writer. Three unedited
copies of the suite on one DDS domain, `-j 3 --network private`, each see only their own
world, while an intruder publishes on the same domain in this machine's network; the same suite
in the machine's network sees the intruder and fails, naming it. Loopback only (the suite's
Cyclone DDS configuration names `lo`); nothing is left behind."""
import os
import re
import shutil
import subprocess

import pytest

from conftest import (BUILD_DIR, RUNNER, SOURCE_DIR, leftover_processes, marked, run_runner,
                      runner_environment, validate_ctrf)

SUITE_DIR = SOURCE_DIR / "tests" / "e2e" / "dds"
BUILT_DIR = os.environ.get("RTF_DDS_WORLD_DIR") or str(BUILD_DIR / "tests/e2e/dds/world")
COPIES = ["a.xml", "b.xml", "c.xml"]
LOOPBACK_ONLY = ('<CycloneDDS><Domain><General><Interfaces><NetworkInterface name="lo" '
                 'multicast="true"/></Interfaces></General></Domain></CycloneDDS>')
TOKEN = re.compile(r"this world's token: (net:\[\d+\])")


def write_suites(folder):
    """The suite (three copies, identical but for their file names), its world file, the
    publisher and the test plug-in, side by side as a user keeps them."""
    for name in ("world.xml", "dds_world_publisher", "dds_world_test.so"):
        source = SUITE_DIR / name if name.endswith(".xml") else os.path.join(BUILT_DIR, name)
        assert os.path.exists(source), \
            f"{source} is missing: the tests' build makes it (tests/e2e/dds/CMakeLists.txt)"
        shutil.copy(source, folder / name)
    suite = (SUITE_DIR / "dds.xml").read_text()
    args = []
    for copy in COPIES:
        (folder / copy).write_text(suite)
        args += ["-s", copy]
    return args


class Intruder:
    """A publisher of the same topic on the same DDS domain in this machine's network, its
    token "intruder": what a world that shares its network with others sees."""

    def __init__(self, folder, marker):
        env = {**os.environ, **marked(marker), "CYCLONEDDS_URI": LOOPBACK_ONLY}
        self.process = subprocess.Popen([str(folder / "dds_world_publisher"), "intruder"],
                                        cwd=folder, env=env, stdin=subprocess.DEVNULL,
                                        stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                        text=True)
        line = self.process.stdout.readline()
        assert line.startswith("publishing intruder"), line

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.process.send_signal(2)
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        self.process.stdout.close()


def own_token():
    return os.readlink("/proc/self/ns/net")


def check_isolated_run(result, folder, copies=3):
    assert result.returncode == 0, result.output
    assert f"{copies} passed, 0 failed" in result.stdout, result.stdout
    tokens = TOKEN.findall(result.stdout)
    # Each world its own network: as many tokens as copies, none the machine's network.
    assert len(tokens) == copies and len(set(tokens)) == copies, result.stdout
    assert own_token() not in tokens
    assert "intruder" not in result.output
    for test in validate_ctrf(folder / "r.json")["results"]["tests"]:
        measured = {m["name"]: m for m in test["extra"]["robotology.rtf"]["measurements"]}
        assert measured["rate"]["passed"] and measured["rate"]["unit"] == "Hz", measured
        assert (measured["rate"]["low"], measured["rate"]["high"]) == (50, 200), measured
        assert measured["latency"]["passed"] and measured["latency"]["unit"] == "ms", measured
        assert measured["latency"]["high"] == 50, measured
        assert measured["samples"]["value"] > 0, measured
        # For the record (never asserted beyond the limits).
        print(test["name"], {name: round(m["value"], 3) for name, m in measured.items()})


def test_three_copies_on_one_domain_each_see_only_their_own_world(tmp_path, marker):
    suites = write_suites(tmp_path)
    with Intruder(tmp_path, marker):
        result = run_runner(*suites, "-j", "3", "--network", "private", "-v",
                            "-o", "json:r.json", cwd=tmp_path, env=marked(marker))
    check_isolated_run(result, tmp_path)
    # The publishers stopped cleanly on SIGINT, each after its own suite.
    assert result.stdout.count("it exited with status 0") == 3, result.stdout
    assert not leftover_processes(marker)


def test_in_the_machines_network_the_check_sees_the_other_world_and_fails(tmp_path, marker):
    suites = write_suites(tmp_path)
    with Intruder(tmp_path, marker) as intruder:
        result = run_runner(*suites[:2], "-v", "--no-output", cwd=tmp_path,
                            env=marked(marker))
    assert result.returncode == 1, result.output
    assert "0 passed, 1 failed" in result.stdout, result.stdout
    # (Another run's intruder on this machine at the same time would be named too.)
    assert re.search(rf"\d+ of \d+ samples come from another world: .*intruder "
                     rf"\(pid {intruder.process.pid}\).*; this world's token is "
                     rf"{re.escape(own_token())}", result.stdout), result.stdout
    assert "writers; this world has one" in result.stdout
    assert not leftover_processes(marker)


def test_in_private_networks_cyclone_dds_needs_no_configuration(tmp_path, marker):
    # The suite and its world without any Cyclone DDS configuration (no CYCLONEDDS_URI, no
    # --config): a private network's loopback has multicast on, Cyclone DDS finds its peer there.
    suites = write_suites(tmp_path)
    world = (tmp_path / "world.xml").read_text()
    (tmp_path / "world.xml").write_text(world.replace(
        "<env name=\"CYCLONEDDS_URI\">${cyclonedds}</env>", ""))
    for copy in COPIES:
        suite = (tmp_path / copy).read_text()
        (tmp_path / copy).write_text(suite.replace(" --config ${cyclonedds}", ""))
    assert "CYCLONEDDS_URI" not in (tmp_path / "world.xml").read_text()
    assert "--config" not in (tmp_path / COPIES[0]).read_text()
    env = {key: value for key, value in os.environ.items() if key != "CYCLONEDDS_URI"}
    result = run_runner(*suites, "-j", "3", "--network", "private", "-v", "-o", "json:r.json",
                        cwd=tmp_path, env={**env, **marked(marker)}, inherit=False)
    check_isolated_run(result, tmp_path)
    assert not leftover_processes(marker)


def as_nobody(folder):
    """The test's folder, and the folders above it up to pytest's base folder, open to the
    user nobody (uid 65534); its files nobody's."""
    walked = folder
    while walked != walked.parent:
        mode = walked.stat().st_mode
        if walked.stat().st_uid == os.getuid() and not mode & 0o001:
            walked.chmod(mode | 0o011)
        if walked.name.startswith("test_dds_world"):
            break
        walked = walked.parent
    for entry in [folder, *folder.iterdir()]:
        os.chown(entry, 65534, 65534)


@pytest.mark.skipif(os.getuid() != 0 or shutil.which("setpriv") is None,
                    reason="becoming another user needs root (as another user, the tests "
                           "above already run through user namespaces)")
def test_another_user_runs_the_copies_through_user_namespaces(tmp_path, marker):
    suites = write_suites(tmp_path)
    as_nobody(tmp_path)
    args = [*suites, "-j", "3", "--network", "private", "-v", "-o", "json:r.json"]
    with Intruder(tmp_path, marker):
        result = subprocess.run(
            ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", RUNNER, *args],
            cwd=tmp_path, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=120,
            env=runner_environment(args, marked(marker, HOME=str(tmp_path)), cwd=tmp_path))
    result.output = result.stdout + result.stderr
    assert "a user and a network namespace" in result.stdout, result.output
    check_isolated_run(result, tmp_path)
    assert not leftover_processes(marker)
