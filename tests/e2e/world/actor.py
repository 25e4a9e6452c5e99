"""A small server for the process fixture's end-to-end tests. Does, in this order, what its
options ask, then serves until it is stopped:
  --require FILE   exit 9 at once unless FILE exists (proves a dependency was ready first)
  --sleep S        wait S seconds first (a slow start)
  --listen PORT    listen on 127.0.0.1:PORT (accepts and closes connections)
  --touch FILE     create FILE
  --say TEXT       print TEXT on a line of its own (repeatable; flushed)
  --print TEXT     then print TEXT with no newline after it (flushed)
  --spew MB        before that, print a line of MB megabytes of "x" (no newline until its end)
  --orphan         leave a grandchild behind in a new session (a daemon that double-forks)
  --die-after S    exit after S more seconds with --status N (default 3), saying why first
"""
import argparse
import os
import socket
import sys
import threading
import time


def serve(server):
    while True:
        try:
            connection, _ = server.accept()
            connection.close()
        except OSError:
            return


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--require")
    parser.add_argument("--sleep", type=float, default=0)
    parser.add_argument("--listen", type=int)
    parser.add_argument("--touch")
    parser.add_argument("--say", action="append", default=[])
    parser.add_argument("--print")
    parser.add_argument("--spew", type=int, default=0)
    parser.add_argument("--orphan", action="store_true")
    parser.add_argument("--die-after", type=float)
    parser.add_argument("--status", type=int, default=3)
    args = parser.parse_args()

    if args.require and not os.path.exists(args.require):
        print(f"{args.require} is missing: what I depend on is not ready", flush=True)
        sys.exit(9)
    time.sleep(args.sleep)
    if args.listen:
        server = socket.socket()
        server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        server.bind(("127.0.0.1", args.listen))
        server.listen(16)
        threading.Thread(target=serve, args=(server,), daemon=True).start()
    if args.touch:
        open(args.touch, "w").close()
    if args.spew:
        for _ in range(args.spew * 16):
            sys.stdout.write("x" * 65536)
        sys.stdout.write("\n")
    for text in args.say:
        print(text, flush=True)
    if args.print is not None:
        print(args.print, end="", flush=True)
    if args.orphan and os.fork() == 0:
        os.setsid()
        if os.fork() == 0:
            time.sleep(600)
        os._exit(0)
    if args.die_after is not None:
        time.sleep(args.die_after)
        print(f"fatal: lost contact with the motors, exiting with {args.status}", flush=True)
        sys.exit(args.status)
    while True:
        time.sleep(60)


if __name__ == "__main__":
    main()
