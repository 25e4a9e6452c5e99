"""A world process for the checked-shutdown tests (test_checked_shutdown.py): prints "ready",
then serves until it is stopped. What it does on SIGINT or SIGTERM is its argument:
  exit N    says so, then exits with status N
  abort     says so, then aborts (dies by SIGABRT; no core file)
  ignore    ignores both (it outlives any grace and is killed with SIGKILL)
  default   nothing of its own: the signal's default action (Python dies by SIGINT on SIGINT)
  die S N   (before any stop) exits with status N after S seconds, saying so first
"""
import os
import resource
import signal
import sys
import time


def main():
    mode = sys.argv[1]
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))

    def on_stop(number, _frame):
        print(f"got {signal.Signals(number).name}: saving the map", flush=True)
        if mode == "exit":
            print(f"cannot save the map: exiting with status {sys.argv[2]}", flush=True)
            os._exit(int(sys.argv[2]))
        print("aborting", flush=True)
        os.abort()

    for number in (signal.SIGINT, signal.SIGTERM):
        if mode in ("exit", "abort"):
            signal.signal(number, on_stop)
        elif mode == "ignore":
            signal.signal(number, signal.SIG_IGN)
    print("ready", flush=True)
    if mode == "die":
        time.sleep(float(sys.argv[2]))
        print(f"giving up: exiting with status {sys.argv[3]}", flush=True)
        sys.exit(int(sys.argv[3]))
    while True:
        time.sleep(1)


if __name__ == "__main__":
    main()
