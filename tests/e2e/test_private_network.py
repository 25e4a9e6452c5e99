"""A private network per suite (<suite network="private">, --network private) through the
installed runner, from the suites' own folder: four copies of a suite whose world serves one
fixed port on 127.0.0.1 run side by side green in private networks, in both isolation modes,
while this machine's loopback holds that very port; without private networks they clash. Bad
values stop the run before it starts (exit 2). Loopback only; nothing is left behind."""
import os
import shutil
import socket
import subprocess
import sys

import pytest

from conftest import RUNNER, leftover_processes, marked, run_runner, runner_environment

COPIES = ["arm", "base", "head", "legs"]


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def write_suites(folder, port, network=""):
    """The world (an HTTP server on 127.0.0.1:port, ready once the port accepts), the test
    that fetches from it, and four copies of the suite, identical but for their file names."""
    (folder / "world.xml").write_text(f"""<world name="web" logdir="logs">
  <process name="web" command="{sys.executable} -m http.server {port} --bind 127.0.0.1">
    <ready timeout="20s"><port>{port}</port></ready>
  </process>
</world>
""")
    fetch = folder / "fetch.py"
    fetch.write_text(f"""#!{sys.executable}
import socket
with socket.create_connection(("127.0.0.1", {port}), timeout=10) as s:
    s.sendall(b"GET / HTTP/1.0\\r\\n\\r\\n")
    answer = s.recv(100).decode(errors="replace")
print(answer.splitlines()[0] if answer else "(no answer)")
raise SystemExit(0 if answer.startswith("HTTP/1.0 200") else 1)
""")
    fetch.chmod(0o755)
    attribute = f' network="{network}"' if network else ""
    names = []
    for copy in COPIES:
        (folder / f"{copy}.xml").write_text(f"""<suite{attribute}>
  <fixture type="process">world.xml</fixture>
  <test type="exec">fetch.py</test>
</suite>
""")
        names += ["-s", f"{copy}.xml"]
    return names


def holding(port):
    """A socket listening on this machine's 127.0.0.1:port: a world in this machine's network
    cannot have it, and a test connecting here gets no HTTP answer."""
    s = socket.socket()
    s.bind(("127.0.0.1", port))
    s.listen(8)
    return s


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_four_copies_of_a_fixed_port_world_run_side_by_side(tmp_path, marker, isolation):
    port = free_port()
    suites = write_suites(tmp_path, port)
    with holding(port):
        result = run_runner(*suites, "-j", "4", "--network", "private", "--isolation", isolation,
                            "-v", "--no-output", cwd=tmp_path, env=marked(marker))
    # The cost of a private network, for the record (never asserted).
    print([line for line in result.stdout.splitlines() if "private network is made" in line])
    assert result.returncode == 0, result.output
    assert "4 passed, 0 failed" in result.stdout
    assert result.stdout.count("HTTP/1.0 200 OK") == 4, result.stdout
    assert not leftover_processes(marker)


def test_without_private_networks_the_copies_clash(tmp_path, marker):
    port = free_port()
    suites = write_suites(tmp_path, port)
    result = run_runner(*suites, "-j", "4", "--no-output", cwd=tmp_path, env=marked(marker))
    assert result.returncode != 0, result.stdout
    assert "0 failed" not in result.stdout.splitlines()[-1], result.stdout
    assert not leftover_processes(marker)


def test_a_suite_file_asks_for_its_own_network(tmp_path, marker):
    port = free_port()
    suites = write_suites(tmp_path, port, network="private")
    with holding(port):
        result = run_runner(*suites, "-j", "4", "--no-output", cwd=tmp_path, env=marked(marker))
        # "host" is the default: as without the attribute, the held port stops the worlds.
        write_suites(tmp_path, port, network="host")
        clashing = run_runner(*suites, "-j", "4", "--no-output", cwd=tmp_path,
                              env=marked(marker))
    assert result.returncode == 0, result.output
    assert "4 passed, 0 failed" in result.stdout
    assert clashing.returncode != 0, clashing.stdout
    assert "already accepts connections" in clashing.output
    assert not leftover_processes(marker)


def test_an_unknown_network_value_stops_the_run_naming_file_and_line(tmp_path):
    (tmp_path / "suite.xml").write_text(
        '<?xml version="1.0"?>\n<suite name="s"\n  network="bridge">\n'
        '<test type="exec">/bin/true</test>\n</suite>\n')
    result = run_runner("-s", "suite.xml", "--no-output", cwd=tmp_path)
    assert result.returncode == 2, result.output
    assert ('suite.xml:2: network="bridge": expected private (a network of its own) or host '
            "(the machine's)") in result.stderr
    assert "passed" not in result.stdout

    option = run_runner("-s", "suite.xml", "--network", "Private", "--no-output", cwd=tmp_path)
    assert option.returncode == 2
    assert "--network: Private not in {private,host}" in option.stderr


def test_where_no_private_network_can_be_had_the_run_stops_before_it_starts(tmp_path, marker):
    # A user namespace of this test's own whose limit of network namespaces is 0: the kernel
    # refuses every new one there, as on a machine whose setting forbids them.
    port = free_port()
    suites = write_suites(tmp_path, port)
    args = [*suites, "--network", "private", "--no-output"]
    proc = subprocess.run(
        ["unshare", "--user", "--map-root-user", "sh", "-c",
         'echo 0 > /proc/sys/user/max_net_namespaces && exec "$0" "$@"', RUNNER, *args],
        cwd=tmp_path, env=runner_environment(args, marked(marker), cwd=tmp_path),
        stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=60)
    assert proc.returncode == 2, proc.stdout + proc.stderr
    assert ("--network private: a private network cannot be made: unshare(CLONE_NEWNET): "
            "No space left on device") in proc.stderr
    assert "user.max_net_namespaces = 0" in proc.stderr
    assert "passed" not in proc.stdout and "web" not in proc.stdout
    assert not leftover_processes(marker)


def as_nobody(tmp_path):
    """For a run as the user "nobody" (uid 65534), as a CI job that is not root runs: the test's
    folder, and the folders above it up to pytest's base folder, open to it; its files its."""
    folder = tmp_path
    while folder != folder.parent:
        mode = folder.stat().st_mode
        if folder.stat().st_uid == os.getuid() and not mode & 0o001:
            folder.chmod(mode | 0o011)
        if folder.name.startswith("test_private_network"):
            break
        folder = folder.parent
    for entry in tmp_path.iterdir():
        os.chown(entry, 65534, 65534)
    os.chown(tmp_path, 65534, 65534)


def run_as_nobody(tmp_path, marker, *args):
    command = ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", RUNNER, *args]
    return subprocess.run(command, cwd=tmp_path,
                          env=runner_environment(list(args), marked(marker, HOME=str(tmp_path)),
                                                 cwd=tmp_path),
                          stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=120)


@pytest.mark.skipif(os.getuid() != 0 or shutil.which("setpriv") is None,
                    reason="becoming another user needs root (as another user, every test "
                           "above already runs through a user namespace)")
def test_another_user_has_private_networks_through_user_namespaces(tmp_path, marker):
    port = free_port()
    suites = write_suites(tmp_path, port)
    as_nobody(tmp_path)
    with holding(port):
        result = run_as_nobody(tmp_path, marker, *suites, "-j", "4", "--network", "private",
                               "-v", "--no-output")
        # A thread of the runner cannot join a user namespace: --isolation none is refused.
        refused = run_as_nobody(tmp_path, marker, *suites, "--network", "private",
                                "--isolation", "none", "--no-output")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "a user and a network namespace" in result.stdout
    assert "4 passed, 0 failed" in result.stdout
    assert result.stdout.count("HTTP/1.0 200 OK") == 4, result.stdout
    assert refused.returncode == 2, refused.stdout + refused.stderr
    assert ("--network private with --isolation none: the runner's thread must join each "
            "suite's network, which only root can") in refused.stderr
    assert "passed" not in refused.stdout
    assert not leftover_processes(marker)
