"""Two runs on one directory (io/RunLock.h; tests/cli/CMakeLists.txt): while a run has it, a
second run, with or without --overwrite, is refused with exit code 4 and a message naming the
first process, and touches nothing there; once the first is killed (kill -9), its lock is gone
and a new run takes the directory over.

usage: check_lock.py WCMPS CASE DIR
Prints "ok ..." or the problem and exits 1.
"""
import os
import shutil
import signal
import subprocess
import sys
import time


def main():
    wcmps, case, d = sys.argv[1:4]
    shutil.rmtree(d, ignore_errors=True)
    first = subprocess.Popen([wcmps, "run", case, "-o", d, "--threads", "1"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    lock = os.path.join(d, ".wcmps.lock")
    try:
        # The first run holds the lock once its note names it (it builds the scene first).
        deadline = time.time() + 60
        while time.time() < deadline:
            if os.path.exists(lock) and f"process {first.pid} " in open(lock).read():
                break
            if first.poll() is not None:
                print(f"the first run ended (exit {first.returncode}) before the test")
                return 1
            time.sleep(0.05)
        else:
            print("the first run did not take the lock within 60 s")
            return 1
        series = os.path.join(d, "series.pvd")
        before = open(series).read() if os.path.exists(series) else None
        for extra in ([], ["--overwrite"]):
            r = subprocess.run([wcmps, "run", case, "-o", d, "--end-time", "0.01"] + extra,
                               capture_output=True, text=True)
            if r.returncode != 4 or f"is in use by process {first.pid} " not in r.stderr:
                print(f"second run {extra}: exit {r.returncode}, stderr {r.stderr.strip()!r}")
                return 1
        if first.poll() is not None:
            print("the first run ended while the second was refused: the test proves nothing")
            return 1
        now = open(series).read() if os.path.exists(series) else None
        if before is not None and now is not None and len(now) < len(before):
            print("the refused runs changed the first run's series")
            return 1
    finally:
        if first.poll() is None:
            first.send_signal(signal.SIGKILL)
        first.wait()
    r = subprocess.run([wcmps, "run", case, "-o", d, "--end-time", "0.01", "--overwrite"],
                       capture_output=True, text=True)
    if r.returncode != 0:
        print(f"after kill -9 of the first run: exit {r.returncode}, {r.stderr.strip()!r}")
        return 1
    print("ok: refused twice (exit 4, naming the running process), taken over after kill -9")
    return 0


if __name__ == "__main__":
    sys.exit(main())
