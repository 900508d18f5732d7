#!/usr/bin/python3
"""The standing wave of cases/standing-wave against linear theory: period and amplitude lost
per period, for schemes side by side.

usage: bench/standing_wave.py [--wcmps build/bin/wcmps] [--out DIR] [--dl 0.01] [--end 6]
                              [--threads 1] [--schemes 0,1,2,3] [--reuse]

Runs the case with each scheme of SCHEMES below (rows 0-3: the new default, the scheme of commit
3a85288, each with and without artificial viscosity; rows 4 on: the default with one change each,
for where the loss comes from), reads gauges.csv, and prints one row per scheme:
the period (mean time between the up-crossings of the two antinode gauges, the still level
taken as the mean of the record) against T = 2 pi / sqrt(g k tanh(k h)), and the amplitude lost
per period: 1 - exp(b T), b the slope of a least-squares line through log |eta - mean| at the
record's extrema (crests and troughs of both antinodes). The artificial viscosity's share of
the loss is the difference between a scheme with and without it.
"""
import argparse
import csv
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
CASE = ROOT / "cases" / "standing-wave" / "case.toml"
OLD = {"negative_pressure": '"zero"', "number_density": '"summation"',
       "free_surface": '"koshizuka1996"', "shifting": '"none"'}
# Rows 0-3 are the table of docs/validation.md; the rest take the default scheme apart, one
# change each ("time.KEY" goes to [time]).
SCHEMES = [
    ("new default", {}),
    ("new, artificial viscosity 0", {"artificial_viscosity": "0.0"}),
    ("3a85288 scheme", OLD),
    ("3a85288 scheme, artificial viscosity 0", dict(OLD, artificial_viscosity="0.0")),
    ("new, shifting none", {"shifting": '"none"'}),
    ("new, density_diffusion 0", {"density_diffusion": "0.0"}),
    ("new, wall_collision none", {"wall_collision": '"none"'}),
    ("new, kinematic_viscosity 0", {"kinematic_viscosity": "0.0"}),
    ("new, free_surface koshizuka1996", {"free_surface": '"koshizuka1996"'}),
    ("new, courant 0.2", {"time.courant": "0.2"}),
    ("new, courant 0.2, shifting none", {"time.courant": "0.2", "shifting": '"none"'}),
    ("new, artificial viscosity 0, shifting none",
     {"artificial_viscosity": "0.0", "shifting": '"none"'}),
    ("new, sound speed x 2", {"sound_speed_factor": "20.0"}),
]
L, H = 1.0, 0.5
G = 9.81


def case_text(physics, dl):
    text = CASE.read_text()
    text = re.sub(r"(?m)^spacing = [0-9.e-]+", f"spacing = {dl}", text)
    for k, v in physics.items():  # keys the case sets already are replaced
        if re.search(rf"(?m)^{k} = ", text):
            text = re.sub(rf"(?m)^{k} = .*$", f"{k} = {v}", text)
    lines = "".join(f"{k} = {v}\n" for k, v in physics.items()
                    if not k.startswith("time.") and not re.search(rf"(?m)^{k} = ", text))
    times = "".join(f"{k[5:]} = {v}\n" for k, v in physics.items() if k.startswith("time."))
    text = text.replace("[time]\n", "[time]\n" + times, 1)
    return text.replace("[physics]\n", "[physics]\n" + lines, 1)


def analyse(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    head = rows[0]
    data = np.array([[float(v) for v in r] for r in rows[1:]])
    t = data[:, 0]
    xs = [float(re.search(r"x = ([-0-9.e]+) m", h).group(1)) for h in head[1:]]
    cols = [k + 1 for k, x in enumerate(xs) if abs(x - L / 2) > 0.1]  # the antinodes
    periods, ext_t, ext_a = [], [], []
    for c in cols:
        eta = data[:, c] - np.nanmean(data[:, c])
        up = [t[k] - eta[k] * (t[k + 1] - t[k]) / (eta[k + 1] - eta[k])
              for k in range(len(t) - 1) if eta[k] < 0 <= eta[k + 1]]
        periods += list(np.diff(up))
        # extrema between successive zero crossings
        zc = [k for k in range(len(t) - 1) if (eta[k] < 0) != (eta[k + 1] < 0)]
        for a, b in zip(zc[:-1], zc[1:]):
            seg = np.abs(eta[a + 1:b + 1])
            if len(seg) == 0:
                continue
            k = a + 1 + int(np.argmax(seg))
            ext_t.append(t[k])
            ext_a.append(abs(eta[k]))
    period = float(np.mean(periods)) if periods else float("nan")
    b = np.polyfit(ext_t, np.log(ext_a), 1)[0] if len(ext_t) > 2 else float("nan")
    return period, b, len(periods)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--wcmps", default=str(ROOT / "build" / "bin" / "wcmps"))
    ap.add_argument("--out", default="runs/standing-wave-schemes")
    ap.add_argument("--dl", type=float, default=0.01)
    ap.add_argument("--end", type=float, default=6.0)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--reuse", action="store_true", help="analyse earlier runs in --out")
    ap.add_argument("--schemes", default="0,1,2,3",
                    help="which rows of SCHEMES to run (indices), e.g. 0,2 for the two defaults")
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    k = math.pi / L
    period_linear = 2 * math.pi / math.sqrt(G * k * math.tanh(k * H))
    print(f"linear theory: T = {period_linear:.4f} s, no loss (molecular viscosity: 2e-5 per period)")
    print("| scheme | DL (m) | period (s) | period / linear | amplitude lost per period |")
    print("|---|---|---|---|---|")
    wanted = [int(k) for k in args.schemes.split(",")]
    for k_s, (name, physics) in enumerate(SCHEMES):
        if k_s not in wanted:
            continue
        run = out / f"scheme{k_s}"
        if not args.reuse:
            case = out / f"scheme{k_s}.toml"
            case.write_text(case_text(physics, args.dl))
            r = subprocess.run([args.wcmps, "run", str(case), "-o", str(run), "--overwrite",
                                "--end-time", str(args.end), "--threads", str(args.threads)],
                               capture_output=True, text=True)
            if r.returncode != 0:
                print(f"| {name} | {args.dl} | run failed: {r.stderr.strip()[-200:]} | | |")
                continue
        period, b, n = analyse(run / "gauges.csv")
        loss = 1.0 - math.exp(b * period_linear)
        print(f"| {name} | {args.dl} | {period:.4f} | {period / period_linear:.4f} | {100 * loss:.2f} % |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
