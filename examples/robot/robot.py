"""A simulated robot (standard library only). It announces itself to the MQTT broker, takes a
while to "calibrate", then serves its joint states as JSON lines on 127.0.0.1:PORT, one line
every 10 ms to every client, until it gets SIGINT or SIGTERM.

    python3 robot.py --broker-port 18830 --port 18831 [--calibration 1.0]
"""
import argparse
import json
import math
import signal
import socket
import struct
import sys
import threading
import time

JOINTS = {  # name: (lower limit, upper limit) in radians
    "shoulder_pitch": (-1.6, 1.6), "shoulder_roll": (-0.5, 2.8), "shoulder_yaw": (-0.8, 1.4),
    "elbow": (0.0, 1.9), "wrist_pitch": (-1.1, 1.1), "wrist_yaw": (-0.4, 0.4),
}


def mqtt_string(text):
    data = text.encode()
    return struct.pack("!H", len(data)) + data


def mqtt_packet(kind, body):
    length, encoded = len(body), b""
    while True:  # MQTT's variable-length "remaining length"
        byte, length = length % 128, length // 128
        encoded += bytes([byte | (0x80 if length else 0)])
        if not length:
            return bytes([kind]) + encoded + body


def announce(broker_port):
    """MQTT 3.1.1: CONNECT, wait for CONNACK, PUBLISH robot/status (QoS 0), DISCONNECT."""
    with socket.create_connection(("127.0.0.1", broker_port), timeout=5) as broker:
        broker.sendall(mqtt_packet(0x10, mqtt_string("MQTT") + bytes([4, 0x02]) +
                                   struct.pack("!H", 30) + mqtt_string("rtf-example-robot")))
        ack = broker.recv(4)
        if len(ack) < 4 or ack[0] != 0x20 or ack[3] != 0:
            raise RuntimeError(f"the broker refused the connection: {ack!r}")
        broker.sendall(mqtt_packet(0x30, mqtt_string("robot/status") + b"calibrating"))
        broker.sendall(bytes([0xE0, 0]))


def joint_states(started):
    t = time.monotonic() - started
    states = {}
    for i, (name, (low, high)) in enumerate(JOINTS.items()):
        middle, half = (low + high) / 2, (high - low) / 2
        states[name] = {"position": round(middle + 0.8 * half * math.sin(t + i), 4),
                        "velocity": round(0.8 * half * math.cos(t + i), 4)}
    return {"time": round(t, 3), "joints": states}


def serve_client(client, started, stop):
    with client:
        try:
            while not stop.is_set():
                client.sendall((json.dumps(joint_states(started)) + "\n").encode())
                time.sleep(0.01)
        except OSError:
            pass  # the client left


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--broker-port", type=int, required=True)
    parser.add_argument("--port", type=int, required=True)
    parser.add_argument("--calibration", type=float, default=1.0)
    args = parser.parse_args()

    stop = threading.Event()
    signal.signal(signal.SIGINT, lambda *_: stop.set())
    signal.signal(signal.SIGTERM, lambda *_: stop.set())

    announce(args.broker_port)
    print(f"connected to the MQTT broker on 127.0.0.1:{args.broker_port}", flush=True)
    print(f"calibrating for {args.calibration} s", flush=True)
    time.sleep(args.calibration)

    server = socket.socket()
    server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    server.bind(("127.0.0.1", args.port))
    server.listen(8)
    server.settimeout(0.1)
    started = time.monotonic()
    print(f"calibrated: serving joint states on 127.0.0.1:{args.port}", flush=True)
    while not stop.is_set():
        try:
            client, _ = server.accept()
        except socket.timeout:
            continue
        threading.Thread(target=serve_client, args=(client, started, stop), daemon=True).start()
    print("stopping", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
