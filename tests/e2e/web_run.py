"""Helpers for the live web page tests: a run whose tests wait for a file, and HTTP calls."""
import http.client
import queue
import re
import signal
import socket
import threading
import time

import pytest

from conftest import start_runner

URL_LINE = re.compile(r"live web page at (http://[^\s]+/)")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def waiting_test(folder, name, signal_file, body=""):
    """An executable test that waits (at most 60 s) for `signal_file` to appear."""
    path = folder / name
    path.write_text("#!/bin/sh\n"
                    f"i=0; while [ ! -e '{signal_file}' ] && [ $i -lt 1200 ]; do "
                    "sleep 0.05; i=$((i+1)); done\n" + body)
    path.chmod(0o755)
    return path


def quick_test(folder, name, body="exit 0\n"):
    path = folder / name
    path.write_text("#!/bin/sh\n" + body)
    path.chmod(0o755)
    return path


class WebRun:
    """The runner started with the web page on a free port; its output read by a thread."""

    def __init__(self, *args, cwd, env=None):
        self.proc = start_runner("-w", "--web-port", "0", "--no-output", *args, cwd=cwd, env=env)
        self.lines = queue.Queue()
        self.stdout = []
        self.stderr = []
        self._readers = [threading.Thread(target=self._read, args=(s, out), daemon=True)
                         for s, out in ((self.proc.stdout, self.stdout),
                                        (self.proc.stderr, self.stderr))]
        for reader in self._readers:
            reader.start()
        self.url = self._wait_for_url()
        self.port = int(self.url.rsplit(":", 1)[1].strip("/"))

    def _read(self, stream, into):
        for line in stream:
            into.append(line)
            self.lines.put(line)

    def _wait_for_url(self, timeout=30):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            try:
                line = self.lines.get(timeout=0.2)
            except queue.Empty:
                if self.proc.poll() is not None:
                    break
                continue
            found = URL_LINE.search(line)
            if found:
                return found.group(1)
        self.kill()
        pytest.fail(f"no URL printed\n{''.join(self.stdout)}{''.join(self.stderr)}")

    def wait_for_line(self, text, timeout=30):
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if any(text in line for line in self.stdout + self.stderr):
                return
            time.sleep(0.05)
        pytest.fail(f"no line with {text!r}\n{self.output()}")

    def wait(self, timeout=30):
        """The exit status; fails the test if the runner is still running after `timeout`."""
        try:
            status = self.proc.wait(timeout=timeout)
        except Exception:
            self.kill()
            pytest.fail(f"the runner did not exit within {timeout} s\n{self.output()}")
        for reader in self._readers:
            reader.join(timeout=5)
        return status

    def output(self):
        return "".join(self.stdout) + "".join(self.stderr)

    def kill(self):
        if self.proc.poll() is None:
            import os
            os.killpg(self.proc.pid, signal.SIGKILL)
            self.proc.wait()


def request(port, path, method="GET", headers=None, timeout=10):
    """(status, headers, body) of one request to 127.0.0.1:port."""
    connection = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    try:
        connection.request(method, path, headers=headers or {})
        response = connection.getresponse()
        return response.status, dict(response.getheaders()), response.read().decode()
    finally:
        connection.close()


def poll(condition, timeout=30, what="condition"):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        value = condition()
        if value:
            return value
        time.sleep(0.05)
    pytest.fail(f"timed out waiting for {what}")
