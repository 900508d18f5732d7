#!/usr/bin/env python3
"""Checkpoints, restart, clean stops and kill -9 (docs/checkpoints.md).

usage: check_restart.py WCMPS CASE OUT_DIR MODE [TRIALS]

MODE "stops": a reference run; then runs stopped by SIGTERM (after t = 0; a stale temporary
file is left for the restart to remove) and by SIGINT
(during settling) and continued with `--restart` (with 1 thread where the reference had 2),
which must end with the same files as the reference, byte for byte; a corrupted newest checkpoint (the older one is used); an edited case.toml, a run
without checkpoints and a directory without a run (exit 7); a finished run continued to a later
end time, which must equal a run made to that time at once; a run killed between its final
checkpoint and its run.json, which the restart finishes.

MODE "diskfull": runs on a disk that fills up (LD_PRELOAD of tests/support/full_disk.c, given as
TRIALS' place: the library's path) after 0.3 to 3 MB: each must exit 4 with one line saying
so, leave a valid series and no temporary file, and once there is room `--restart` must finish
the run with the reference's files.

MODE "kill9": TRIALS runs killed with SIGKILL at random moments (the seed is printed): each time
the series on disk must be valid (every frame it lists complete), and `--restart` must finish
the run with the reference's files (or, killed before the first checkpoint, exit 7 saying so).

Identical, not close: the continued run reloads every particle's state and rebuilds the
neighbour lists from the positions they were built from, so it adds in the same order.
"""
import json
import os
import random
import shutil
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

WCMPS, CASE, OUT, MODE = sys.argv[1:5]
EXTRA = sys.argv[5] if len(sys.argv) > 5 else ""


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def fresh(name):
    d = os.path.join(OUT, name)
    shutil.rmtree(d, ignore_errors=True)
    return d


def run(*args):
    return subprocess.run([WCMPS, *args], capture_output=True, text=True)


def start(*args):
    return subprocess.Popen([WCMPS, *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                            text=True)


def expect(p, code, stderr_pattern=None):
    err = p.stderr if isinstance(p, subprocess.CompletedProcess) else p.stderr.read()
    rc = p.returncode
    if rc != code:
        fail(f"exit code {rc}, expected {code}; stderr:\n{err}")
    if stderr_pattern and stderr_pattern not in err:
        fail(f"stderr lacks '{stderr_pattern}':\n{err}")
    return err


def handlers_installed(pid):
    """True once the process catches SIGINT and SIGTERM (/proc/PID/status, SigCgt)."""
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("SigCgt:"):
                    mask = int(line.split()[1], 16)
                    return bool(mask & (1 << (signal.SIGINT - 1))) and bool(
                        mask & (1 << (signal.SIGTERM - 1)))
    except FileNotFoundError:
        pass
    return False


def wait_for(predicate, what, timeout=60.0):
    t0 = time.time()
    while not predicate():
        if time.time() - t0 > timeout:
            fail("timed out waiting for " + what)
        time.sleep(0.001)


def log_checkpoints(d):
    try:
        with open(os.path.join(d, "run.log")) as f:
            return [line for line in f if line.startswith("checkpoint t = ")]
    except FileNotFoundError:
        return []


def series(d):
    """The (time, file) list of series.pvd; every frame it lists must be complete."""
    root = ET.parse(os.path.join(d, "series.pvd")).getroot()
    out = []
    for ds in root.iter("DataSet"):
        f = os.path.join(d, ds.get("file"))
        if not os.path.exists(f):
            fail(f"{d}/series.pvd lists {ds.get('file')}, which is missing")
        frame = ET.parse(f).getroot()  # a cut file does not parse
        piece = frame.find("PolyData/Piece")
        if frame.tag != "VTKFile" or piece is None or int(piece.get("NumberOfPoints")) <= 0:
            fail(f"{f} is not a complete frame")
        out.append((float(ds.get("timestep")), ds.get("file")))
    return out


def same_files(ref, d, what):
    a, b = series(ref), series(d)
    if a != b:
        fail(f"{what}: series differ:\n{a}\n{b}")
    names = [f for _, f in a] + ["block.csv", "gauges.csv", "series.pvd"]
    for n in names:
        with open(os.path.join(ref, n), "rb") as x, open(os.path.join(d, n), "rb") as y:
            if x.read() != y.read():
                fail(f"{what}: {n} differs from the uninterrupted run's")
    leftovers = [n for n in os.listdir(d) if ".tmp-" in n]
    if leftovers:
        fail(f"{what}: temporary files left: {leftovers}")


def status(d):
    with open(os.path.join(d, "run.json")) as f:
        return json.load(f)


def reference(name="reference", *extra):
    d = fresh(name)
    expect(run("run", CASE, "-o", d, "--threads", "2", *extra), 0)
    return d


def stops():
    ref = reference()

    # SIGTERM after t = 0: exit 143, a checkpoint, status "stopped"; the restart finishes it.
    d = fresh("sigterm")
    p = start("run", CASE, "-o", d, "--threads", "2")
    wait_for(lambda: any("settling" not in c and not c.startswith("checkpoint t = 0 ")
                         for c in log_checkpoints(d)), "a checkpoint after t = 0")
    p.send_signal(signal.SIGTERM)
    p.wait()
    expect(p, 143, "stopped by SIGTERM")
    j = status(d)
    if j["status"] != "stopped" or j["stop_signal"] != 15:
        fail(f"run.json after SIGTERM: status {j['status']}, stop_signal {j.get('stop_signal')}")
    series(d)
    # What a killed run leaves while writing: a temporary name, which the restart removes.
    with open(os.path.join(d, "frame_000099.vtp.tmp-12345"), "w") as f:
        f.write("<VTKFile")
    err = expect(run("run", "--restart", d, "--threads", "1"), 0)
    if "continuing from checkpoint_" not in err:
        fail("the restart does not say where it continues from:\n" + err)
    if status(d)["restart"]["time"] <= 0.0:
        fail("SIGTERM: the restart did not continue from after t = 0")
    same_files(ref, d, "SIGTERM + restart")
    print("SIGTERM at t > 0: exit 143, restart with 1 thread gives the same files")

    # SIGINT while settling: a checkpoint of the settling state; the restart finishes it.
    d = fresh("sigint_settling")
    p = start("run", CASE, "-o", d, "--threads", "2")
    wait_for(lambda: handlers_installed(p.pid) or p.poll() is not None, "the signal handlers")
    p.send_signal(signal.SIGINT)
    p.wait()
    expect(p, 130, "of settling")
    if not any("(settling)" in c for c in log_checkpoints(d)):
        fail("SIGINT during settling wrote no settling checkpoint")
    if series(d) != []:
        fail("a run stopped while settling has frames")  # but an (empty) series.pvd: series()
    expect(run("run", "--restart", d, "--threads", "2"), 0)
    same_files(ref, d, "SIGINT while settling + restart")
    print("SIGINT while settling: exit 130, restart gives the same files")

    # A corrupted newest checkpoint: skipped (and said so), the older one is used.
    d = fresh("corrupted")
    p = start("run", CASE, "-o", d, "--threads", "2")
    wait_for(lambda: len(log_checkpoints(d)) >= 3, "three checkpoints")
    p.send_signal(signal.SIGTERM)
    p.wait()
    expect(p, 143)
    newest = sorted(n for n in os.listdir(d) if n.startswith("checkpoint_"))[-1]
    with open(os.path.join(d, newest), "r+b") as f:
        f.truncate(os.path.getsize(os.path.join(d, newest)) // 2)
    expect(run("run", "--restart", d), 0, "checkpoint skipped and removed: " + os.path.join(d, newest))
    same_files(ref, d, "corrupted newest checkpoint + restart")
    print("corrupted newest checkpoint: skipped, the older one gives the same files")

    # Errors: exit 7 and one line.
    with open(os.path.join(d, "case.toml"), "a") as f:
        f.write("\n# edited\n")
    expect(run("run", "--restart", d), 7, "written for another case file")
    for n in os.listdir(d):
        if n.startswith("checkpoint_"):
            os.remove(os.path.join(d, n))
    expect(run("run", "--restart", d), 7, "holds no checkpoint")
    expect(run("run", "--restart", os.path.join(OUT, "no_such_run")), 7, "no such run directory")
    expect(run("run", "--restart", ref, "--settle-time", "0"), 2, "excludes")
    print("restart errors: edited case, no checkpoint, no run (exit 7), --settle-time (exit 2)")

    # A finished run: not again to the same end; continued to a later one, it equals a run made
    # to that end at once (0.3 s is an output time, so both land on it).
    expect(run("run", "--restart", ref), 2, "give a later --end-time")
    # Killed after its final checkpoint but before its summary (run.json, written last): absent,
    # or left by an earlier stop. The restart finishes the run: the summary, nothing else to do.
    for left in ("absent", "stopped"):
        d = fresh(f"killed_at_end_{left}")
        shutil.copytree(ref, d)
        summary = status(d)
        os.remove(os.path.join(d, "run.json"))
        if left == "stopped":
            summary["status"] = "stopped"
            with open(os.path.join(d, "run.json"), "w") as f:
                json.dump(summary, f)
        expect(run("run", "--restart", d), 0)
        same_files(ref, d, f"killed before the summary ({left}) + restart")
        if status(d)["status"] != "completed":
            fail(f"killed before the summary ({left}): the restart's run.json is not 'completed'")
    print("killed between the final checkpoint and run.json: the restart finishes the run")
    longer = reference("reference_longer", "--end-time", "0.34")
    expect(run("run", "--restart", ref, "--end-time", "0.34"), 0)
    same_files(longer, ref, "a finished run continued to a later end")
    print("a finished run continued to 0.34 s equals a run to 0.34 s")


def kill9():
    ref = reference()
    seed = int(time.time())
    rng = random.Random(seed)
    wall = status(ref)["performance"]["wall_seconds"]
    print(f"seed {seed}; the uninterrupted run takes {wall:.2f} s")
    outcomes = []
    for k in range(int(EXTRA or 6)):
        d = fresh(f"kill9_{k}")
        p = start("run", CASE, "-o", d, "--threads", "2")
        delay = rng.uniform(0.0, 1.1 * wall)
        time.sleep(delay)
        p.kill()
        p.wait()
        if os.path.exists(os.path.join(d, "series.pvd")):
            n = len(series(d))
        else:
            n = 0
        r = run("run", "--restart", d, "--threads", "2")
        early = ("holds no checkpoint", "holds no run", "no such run directory")
        if r.returncode == 7 and any(e in r.stderr for e in early):
            outcomes.append(f"{delay:.2f} s: {n} frames, killed before the first checkpoint "
                            f"(exit 7: {r.stderr.strip().split(': ')[-1]})")
            continue
        # Finished (run.json written last, saying so) before the kill, or before exiting.
        if r.returncode == 2 and status(d)["status"] == "completed":
            same_files(ref, d, f"kill -9 after {delay:.2f} s, finished")
            outcomes.append(f"{delay:.2f} s: finished before the kill (exit {p.returncode})")
            continue
        expect(r, 0)
        same_files(ref, d, f"kill -9 after {delay:.2f} s + restart")
        outcomes.append(f"{delay:.2f} s: {n} frames valid; restart gives the same files")
    print("\n".join(outcomes))


def diskfull():
    ref = reference()
    for budget in (300_000, 1_000_000, 2_000_000, 3_000_000):
        d = fresh(f"diskfull_{budget}")
        os.makedirs(d)
        # (An AddressSanitizer build wants its runtime first among the preloaded libraries;
        # the full disk's wrappers do not touch memory, so the check can be off.)
        asan = ":".join(filter(None, [os.environ.get("ASAN_OPTIONS"), "verify_asan_link_order=0"]))
        env = dict(os.environ, LD_PRELOAD=EXTRA, WCMPS_FULL_DISK_DIR=os.path.abspath(d),
                   WCMPS_FULL_DISK_BYTES=str(budget), ASAN_OPTIONS=asan)
        p = subprocess.run([WCMPS, "run", CASE, "-o", d, "--threads", "2"], env=env,
                           capture_output=True, text=True)
        err = expect(p, 4, "No space left on device")
        if err.count("\n") != 1:
            fail("the disk-full message is not one line:\n" + err)
        n = len(series(d))
        if any(".tmp-" in f for f in os.listdir(d)):
            fail(f"{budget} B: temporary files left after the disk filled up")
        r = run("run", "--restart", d, "--threads", "2")
        if r.returncode == 7 and "holds no checkpoint" in r.stderr:
            print(f"{budget} B: {err.strip()}; {n} frames valid, no checkpoint yet (exit 7)")
            continue
        expect(r, 0)
        same_files(ref, d, f"disk full after {budget} B + restart")
        print(f"{budget} B: {err.strip()}; {n} frames valid; restart gives the same files")


{"stops": stops, "kill9": kill9, "diskfull": diskfull}[MODE]()
print("ok")
