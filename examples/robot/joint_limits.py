"""Reads the simulated robot's joint states for half a second and checks every joint stays
within its limits; measures how closely the joints track their reference trajectory and how
fast the states arrive (with limits), and attaches a plot of the elbow's tracking.
Param: --port N (the robot's port on 127.0.0.1)."""
import json
import math
import os
import socket
import tempfile
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

        # The simulated robot follows middle + 0.8 * half * sin(t + i): the tracking error is
        # how far a reported position is from that reference at its reported time.
        errors = []
        for i, (name, (low, high)) in enumerate(LIMITS.items()):
            middle, half = (low + high) / 2, (high - low) / 2
            for s in samples:
                reference = middle + 0.8 * half * math.sin(s["time"] + i)
                errors.append(abs(s["joints"][name]["position"] - reference))
        robottestingframework.testMeasure("joint tracking error", max(errors), "rad", 0, 0.01)
        span = samples[-1]["time"] - samples[0]["time"]
        rate = (len(samples) - 1) / span if span > 0 else 0.0
        robottestingframework.testMeasure("joint state rate", rate, "Hz", 20, 500)
        self.attach_plot(samples)

    def attach_plot(self, samples):
        """An SVG of the elbow's reported position against its reference, attached."""
        low, high = LIMITS["elbow"]
        middle, half = (low + high) / 2, (high - low) / 2
        t0, t1 = samples[0]["time"], max(samples[-1]["time"], samples[0]["time"] + 1e-3)

        def point(t, position):
            return f"{400 * (t - t0) / (t1 - t0):.1f},{200 - 200 * (position - low) / (high - low):.1f}"

        seen = " ".join(point(s["time"], s["joints"]["elbow"]["position"]) for s in samples)
        reference = " ".join(point(s["time"], middle + 0.8 * half * math.sin(s["time"] + 3))
                             for s in samples)
        svg = ('<svg xmlns="http://www.w3.org/2000/svg" width="400" height="200">'
               '<rect width="400" height="200" fill="white"/>'
               f'<polyline points="{reference}" fill="none" stroke="#999" stroke-width="4"/>'
               f'<polyline points="{seen}" fill="none" stroke="#c00" stroke-width="1.5"/>'
               '<text x="5" y="15" font-size="12">elbow: reported (red), reference (grey)</text>'
               "</svg>\n")
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "elbow-tracking.svg")
            with open(path, "w") as f:
                f.write(svg)
            robottestingframework.testAttach(path, "elbow position against its reference")
