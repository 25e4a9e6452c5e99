"""Reads the simulated robot's joint states for half a second and checks every joint stays
within its limits. Param: --port N (the robot's port on 127.0.0.1)."""
import json
import socket
import time

import robottestingframework

LIMITS = {
    "shoulder_pitch": (-1.6, 1.6), "shoulder_roll": (-0.5, 2.8), "shoulder_yaw": (-0.8, 1.4),
    "elbow": (0.0, 1.9), "wrist_pitch": (-1.1, 1.1), "wrist_yaw": (-0.4, 0.4),
}


class TestCase:
    def setup(self, param):
        robottestingframework.setName("JointLimits")
        words = param.split()
        self.port = int(words[words.index("--port") + 1]) if "--port" in words else 18831
        return True

    def run(self):
        samples = []
        with socket.create_connection(("127.0.0.1", self.port), timeout=5) as robot:
            stream = robot.makefile("r")
            end = time.monotonic() + 0.5
            while time.monotonic() < end:
                samples.append(json.loads(stream.readline()))
        robottestingframework.testReport(f"read {len(samples)} joint states")
        robottestingframework.testCheck(len(samples) >= 10, "the robot streams its joints")
        for name, (low, high) in LIMITS.items():
            positions = [s["joints"][name]["position"] for s in samples]
            robottestingframework.testCheck(
                all(low <= p <= high for p in positions),
                f"{name} within [{low}, {high}] (seen {min(positions)} .. {max(positions)})")
