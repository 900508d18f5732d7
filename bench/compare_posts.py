#!/usr/bin/env python3
"""How far apart two `wcmps post` outputs of the same case are (docs/performance.md, "Case I's
whole run"): for each time both have, the surface eta(x) as the rms difference over the
largest |eta - eta_far| of the first (eta_far: its mean beyond x = 1.5 m, the still level),
and each section's velocity as the rms of |u_a - u_b| over the largest |u_a|.

    /usr/bin/python3 bench/compare_posts.py POST_A POST_B [--sections A,B]

Exit codes: 0 done, 2 usage, 3 a missing or unreadable file.
"""

import argparse
import csv
import math
import sys
from pathlib import Path

import numpy as np


def read_csv(path):
    try:
        with open(path, newline="") as f:
            return list(csv.DictReader(f))
    except OSError as e:
        print(f"compare_posts.py: {path}: {e.strerror}", file=sys.stderr)
        sys.exit(3)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("a", type=Path)
    ap.add_argument("b", type=Path)
    ap.add_argument("--sections", default="A,B")
    args = ap.parse_args()
    surf = [read_csv(p / "free_surface.csv") for p in (args.a, args.b)]
    secs = [read_csv(p / "sections.csv") for p in (args.a, args.b)]
    times = sorted({r["time [s]"] for r in surf[0]} & {r["time [s]"] for r in surf[1]})
    if not times:
        print("compare_posts.py: the two outputs have no time in common", file=sys.stderr)
        sys.exit(3)
    for t in times:
        xa, ea = (np.array([float(r[k]) for r in surf[0] if r["time [s]"] == t])
                  for k in ("x [m]", "eta [m]"))
        xb, eb = (np.array([float(r[k]) for r in surf[1] if r["time [s]"] == t])
                  for k in ("x [m]", "eta [m]"))
        # The surfaces are sampled at each run's own x: compare on a common fine grid.
        x = np.linspace(max(xa.min(), xb.min()), min(xa.max(), xb.max()), 2000)
        d = np.interp(x, xa, ea) - np.interp(x, xb, eb)
        wave = np.max(np.abs(ea - np.mean(ea[xa > 1.5])))
        out = [f"t = {t} s: surface {math.sqrt(np.mean(d * d)) / wave:.4f}"]
        for name in args.sections.split(","):
            ua, ub = ([(float(r["u [m/s]"]), float(r["v [m/s]"])) for r in rows
                       if r["time [s]"] == t and r["section"] == name] for rows in secs)
            if not ua or len(ua) != len(ub):
                out.append(f"{name} -")
                continue
            ua, ub = np.array(ua), np.array(ub)
            rms = math.sqrt(np.mean(np.sum((ua - ub) ** 2, axis=1)))
            out.append(f"{name} {rms / np.max(np.hypot(ua[:, 0], ua[:, 1])):.4f}")
        print(" ".join(out))


if __name__ == "__main__":
    main()
