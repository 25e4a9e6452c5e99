"""The live web page on Windows (-w/--web-port: cpp-httplib over Winsock, in
libRobotTestingFrameworkWeb.dll, which the runner loads): served on 127.0.0.1 under Wine and
fetched from Linux with urllib, its event stream delivering the run's results as they happen.
The run is a Lua suite from its own folder (--isolation none); its first test waits for a file
the test writes once the page has shown it running."""
import json
import re
import socket
import threading
import time
import urllib.request

import pytest

from conftest import run_runner, start_runner, stop_runner

URL_LINE = re.compile(r"live web page at (http://[^\s]+/)")

# Busy-waits (Lua has no sleep) for the file `go` in the runner's folder, at most 60 s.
WAITING = """TestCase.run = function()
    local deadline = os.clock() + 60
    while os.clock() < deadline do
        local go = io.open("go")
        if go then
            go:close()
            robottestingframework.testReport("go found")
            return
        end
        local next = os.clock() + 0.05
        while os.clock() < next do end
    end
    robottestingframework.assertFail("go never appeared")
end
"""
PASSING = """TestCase.run = function()
    robottestingframework.testCheck(true, "holds")
end
"""
FAILING = """TestCase.run = function()
    robottestingframework.testCheck(false, "the gripper slipped")
end
"""
SUITE = """<suite name="web on windows">
    <test name="waiting">../tests/waiting.lua</test>
    <test name="passing">../tests/passing.lua</test>
    <test name="failing">../tests/failing.lua</test>
</suite>
"""


class Output:
    """The lines a started runner prints, read by threads as they come."""

    def __init__(self, proc):
        self.lines = []
        self._threads = [threading.Thread(target=self._read, args=(stream,), daemon=True)
                         for stream in (proc.stdout, proc.stderr)]
        for thread in self._threads:
            thread.start()

    def _read(self, stream):
        for line in stream:
            self.lines.append(line)

    def find(self, pattern, proc, timeout=60):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            for line in list(self.lines):
                found = pattern.search(line)
                if found:
                    return found
            if proc.poll() is not None:
                break
            time.sleep(0.05)
        pytest.fail(f"no line matching {pattern.pattern!r}\n{self.text()}")

    def text(self):
        """What was read so far (all of it once the runner has ended: see finished)."""
        return "".join(self.lines)

    def finished(self):
        """Everything the runner printed, once it has ended and its pipes are read out."""
        for thread in self._threads:
            thread.join(timeout=10)
        return self.text()


def get(url, timeout=20):
    with urllib.request.urlopen(url, timeout=timeout) as response:
        return response.status, dict(response.getheaders()), response.read().decode()


def poll(condition, what, timeout=60):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if condition():
            return
        time.sleep(0.1)
    pytest.fail(f"timed out waiting for {what}")


def write_project(tmp_path):
    tests = tmp_path / "tests"
    tests.mkdir()
    for name, text in (("waiting.lua", WAITING), ("passing.lua", PASSING),
                       ("failing.lua", FAILING)):
        (tests / name).write_text(text)
    suites = tmp_path / "suites"
    suites.mkdir()
    (suites / "suite.xml").write_text(SUITE)
    return suites


def test_the_page_is_served_and_its_event_stream_delivers_the_run(tmp_path):
    suites = write_project(tmp_path)
    go = suites / "go"
    proc = start_runner("-s", "suite.xml", "--isolation", "none", "-w", "--web-port", "0",
                        "--no-output", cwd=suites)
    try:
        output = Output(proc)
        url = output.find(URL_LINE, proc).group(1)
        assert re.fullmatch(r"http://127\.0\.0\.1:\d+/", url), url

        status, headers, body = get(url)
        assert status == 200 and '<main id="suites">' in body, body[:500]
        assert "script-src 'self'" in headers["Content-Security-Policy"], headers
        status, _, script = get(url + "page.js")
        assert status == 200 and "EventSource" in script

        def first_running():
            tests = json.loads(get(url + "snapshot")[2])["suites"][0]["tests"]
            return [test["state"] for test in tests] == ["running", "not run", "not run"]
        poll(first_running, "the first test running on the page")
        snapshot = json.loads(get(url + "snapshot")[2])
        assert snapshot["run"]["state"] == "running", snapshot
        seq = snapshot["seq"]

        # The event stream from there on, read line by line as a browser's EventSource does.
        with urllib.request.urlopen(f"{url}events?since={seq}", timeout=20) as events:
            assert events.headers["Content-Type"].startswith("text/event-stream")
            go.touch()
            lines = []
            deadline = time.monotonic() + 60
            while time.monotonic() < deadline:
                line = events.readline().decode()
                if not line:
                    break
                lines.append(line)
                if '"state":"finished"' in line:
                    break
        text = "".join(lines)
        ids = [int(line[4:]) for line in lines if line.startswith("id: ")]
        assert ids and ids[0] > seq and ids == sorted(ids), text
        data = [json.loads(line[6:]) for line in lines if line.startswith("data: ")]
        states = {}
        for event in data:
            if event.get("type") == "test":
                states[event["test"]["name"]] = event["test"]["state"]
        assert states == {"waiting": "passed", "passing": "passed", "failing": "failed"}, text
        assert '"state":"finished"' in text and "the gripper slipped" in text, text

        assert proc.wait(timeout=60) == 1, output.finished()  # a test failed
        assert "2 passed, 1 failed" in output.finished(), output.finished()
    finally:
        go.touch()
        stop_runner(proc)


def test_a_port_in_use_exits_2_naming_it(tmp_path):
    (tmp_path / "t.lua").write_text(PASSING)
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        run = run_runner("-w", "--web-port", port, "--no-output", "--isolation", "none",
                         "-t", "t.lua", cwd=tmp_path)
    assert run.returncode == 2, run
    assert f"--web-port {port}: cannot listen on 127.0.0.1:{port}" in run.stderr, run
    # Winsock's error (WSAGetLastError), not errno, which Winsock never sets.
    assert f"127.0.0.1:{port}: the port is in use by another program (Winsock error 10048)" in (
        run.stderr), run
    assert "1 passed" not in run.stdout, run
