#!/usr/bin/python3
"""The standing wave of cases/standing-wave against linear theory: period and amplitude lost
per period, for schemes side by side.

usage: bench/standing_wave.py [--wcmps build/bin/wcmps] [--out DIR] [--dl 0.01] [--end 6]
                              [--threads 1] [--schemes 0,1,2,3] [--reuse] [--amplitude A]

Runs the case with each scheme of SCHEMES below (rows 0-3: the new default, the scheme of commit
3a85288, each with and without artificial viscosity; rows 4 on: the default with one change each,
for where the loss comes from; rows 13-16 the artificial viscosity's alpha; rows 20-23 the
renormalised gradient, whole and hydrostatic; rows 24-30 the sound speed, the kernel radius and
the time step, for what the loss does not depend on; rows 31-32 the band's rate renormalised;
rows 41-42 the hydrostatic gradient read through M's deviatoric part, rows 43-44 through the
change of it from each particle's rest shape, rows 45-46 with that shape's memory shorter and
longer, rows 47-49 with its artificial viscosity's alpha 0.005, 0.01, 0.04; rows 50-51 the
defaults and the shape's change with the artificial viscosity's walls free-slip, rows 52-53 the
same with the wall friction of the law of the wall), reads gauges.csv,
and prints one row per scheme, by two measures (the gauges: GAUGES below).

The mode (the first measure of docs/validation.md): a1(t), the least-squares amplitude of
cos(pi x / L) in the surface the 19 gauges from 0.05 to 0.95 m see; the period from its
up-crossings against T = 2 pi / sqrt(g k tanh(k h)); the amplitude lost per period,
1 - exp(b T), b the slope of a line fitted to log of a1's envelope (its analytic signal's
modulus), over the whole record and from the third period on (the first two lose more).

The antinodes (the measure of earlier tables): the two gauges a DL off the walls, their
up-crossings for the period, and a line through log |eta - mean| at their extrema between zero
crossings. It reads the loss high: near the zero crossings the acoustic ripple adds crossings,
and small extrema between them, to the fit (15.5 % where the mode gives 12.2 %).

The artificial viscosity's share of the loss is the difference between a scheme with and
without it.
"""
import argparse
import csv
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np

from physics_options import (FREE_SLIP, NO_COLLISION, OLD, PARTICLE_COLLISION, PLAIN,  # bench/
                             STRAIN, WALL_FRICTION)

ROOT = Path(__file__).resolve().parent.parent
CASE = ROOT / "cases" / "standing-wave" / "case.toml"
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
    ("new, artificial viscosity 1e-6", {"artificial_viscosity": "0.000001"}),
    ("new, artificial viscosity 0.001", {"artificial_viscosity": "0.001"}),
    ("new, artificial viscosity 0.005", {"artificial_viscosity": "0.005"}),
    ("new, artificial viscosity 0.01", {"artificial_viscosity": "0.01"}),
    ("new, shifting in continuity", {"shifting_in_continuity": "true"}),
    ("new, shifting in continuity, artificial viscosity 0",
     {"shifting_in_continuity": "true", "artificial_viscosity": "0.0"}),
    ("new, surface pressure cap off", {"surface_pressure_cap": "false"}),
    ("new, gradient renormalised", {"gradient_renormalisation": '"khayyer2011"'}),
    ("new, gradient renormalised, artificial viscosity 0",
     {"gradient_renormalisation": '"khayyer2011"', "artificial_viscosity": "0.0"}),
    ("new, hydrostatic gradient renormalised",
     {"gradient_renormalisation": '"khayyer2011-hydrostatic"'}),
    ("new, hydrostatic gradient renormalised, artificial viscosity 0",
     {"gradient_renormalisation": '"khayyer2011-hydrostatic"', "artificial_viscosity": "0.0"}),
    # 24-30: what the loss does not depend on (docs/validation.md, run with --amplitude 0.02)
    ("new, sound speed factor 7", {"sound_speed_factor": "7.0"}),
    ("new, sound speed factor 14", {"sound_speed_factor": "14.0"}),
    ("new, artificial viscosity 0, sound speed factor 7",
     {"artificial_viscosity": "0.0", "sound_speed_factor": "7.0"}),
    ("new, artificial viscosity 0, sound speed factor 14",
     {"artificial_viscosity": "0.0", "sound_speed_factor": "14.0"}),
    ("new, kernel radius 3.1 DL", {"particles.kernel_radius": "3.1"}),
    ("new, kernel radius 4.0 DL", {"particles.kernel_radius": "4.0"}),
    ("new, artificial viscosity 0, courant 0.1",
     {"artificial_viscosity": "0.0", "time.courant": "0.1"}),
    # 31-32: the band's rate renormalised (physics/DensityRate_Randles1996.h)
    ("new, density rate randles1996", {"density_rate": '"randles1996"'}),
    ("new, density rate randles1996, artificial viscosity 0",
     {"density_rate": '"randles1996"', "artificial_viscosity": "0.0"}),
    # 33-36: the boundary particles at the density of their pressure
    # (physics/WallDensity_Adami2012.h)
    ("new, wall density adami2012", {"wall_density": '"adami2012"'}),
    ("new, wall density adami2012, artificial viscosity 0",
     {"wall_density": '"adami2012"', "artificial_viscosity": "0.0"}),
    ("new, wall density adami2012, hydrostatic gradient renormalised",
     {"wall_density": '"adami2012"', "gradient_renormalisation": '"khayyer2011-hydrostatic"'}),
    ("new, wall density adami2012, hydrostatic gradient renormalised, artificial viscosity 0",
     {"wall_density": '"adami2012"', "gradient_renormalisation": '"khayyer2011-hydrostatic"',
      "artificial_viscosity": "0.0"}),
    # 37-38: the boundary particles at n0 (the default until 2026-12-04; rows 33-34 are the
    # defaults since then)
    ("new, wall density n0", {"wall_density": '"n0"'}),
    ("new, wall density n0, artificial viscosity 0",
     {"wall_density": '"n0"', "artificial_viscosity": "0.0"}),
    # 39-40: the band's rate summed (the default until later on 2026-12-04; rows 31-32 are the
    # defaults since then)
    ("new, density rate summed", {"density_rate": '"summed"'}),
    ("new, density rate summed, artificial viscosity 0",
     {"density_rate": '"summed"', "artificial_viscosity": "0.0"}),
    # 41-42: the hydrostatic gradient read through M's deviatoric part (2026-12-07)
    ("new, deviatoric hydrostatic gradient",
     {"gradient_renormalisation": '"khayyer2011-deviatoric"'}),
    ("new, deviatoric hydrostatic gradient, artificial viscosity 0",
     {"gradient_renormalisation": '"khayyer2011-deviatoric"', "artificial_viscosity": "0.0"}),
    # 43-44: the same read against each particle's rest shape (2026-12-07)
    ("new, deviatoric hydrostatic gradient of the shape's change",
     STRAIN),
    ("new, deviatoric hydrostatic gradient of the shape's change, artificial viscosity 0",
     {**STRAIN, "artificial_viscosity": "0.0"}),
    # 45-46: its memory a fifth and four times as long (the filter's phase lead 1 / (omega tau)
    # five times and a quarter of the default's): what of the loss the filter's phase makes
    ("new, the shape's change, strain_memory 1 s",
     {**STRAIN, "strain_memory": "1.0"}),
    ("new, the shape's change, strain_memory 20 s",
     {**STRAIN, "strain_memory": "20.0"}),
    # 47-49: its artificial viscosity's alpha a quarter, half and twice the default's: whether
    # the loss follows alpha as the walls' drag would (tools/wall_drag_estimate.py)
    ("new, the shape's change, artificial viscosity 0.005",
     {**STRAIN, "artificial_viscosity": "0.005"}),
    ("new, the shape's change, artificial viscosity 0.01",
     {**STRAIN, "artificial_viscosity": "0.01"}),
    ("new, the shape's change, artificial viscosity 0.04",
     {**STRAIN, "artificial_viscosity": "0.04"}),
    # 50-51: the artificial viscosity's walls free-slip (2026-12-07, session 10): the defaults
    # and the shape's change without the walls' drag of rows 47-49
    ("new, artificial viscosity's walls free-slip", FREE_SLIP),
    ("new, the shape's change, artificial viscosity's walls free-slip",
     {**STRAIN, **FREE_SLIP}),
    # 52-53: the same with the walls' friction of the law of the wall (water's own drag)
    ("new, artificial viscosity's walls free-slip, wall friction",
     {**FREE_SLIP, **WALL_FRICTION}),
    ("new, the shape's change, artificial viscosity's walls free-slip, wall friction",
     {**STRAIN, **FREE_SLIP, **WALL_FRICTION}),
    # 54: the defaults before 2026-12-07, session 13 (the gradient not renormalised)
    ("defaults before session 13 (gradient_renormalisation none)", PLAIN),
    # 55: the particle collision between fluid particles (session 14), l0 = DL (as measured
    # then; the option's default became 0.8 DL after it)
    ("new, particle collision jandaghian2021, l0 DL",
     {**PARTICLE_COLLISION, "particle_collision_distance": "1.0"}),
    # 56-57: its collision distance 0.8 DL (pairs of a wave's strain left alone); its collision
    # part alone (lambda 0, p_min 0, l0 DL)
    ("new, particle collision jandaghian2021, l0 0.8 DL",
     {**PARTICLE_COLLISION, "particle_collision_distance": "0.8"}),
    ("new, particle collision jandaghian2021, l0 DL, no repulsion",
     {**PARTICLE_COLLISION, "particle_collision_distance": "1.0",
      "particle_collision_lambda": "0.0",
      "particle_collision_min_pressure": "0.0"}),
    # 58: l0 0.8 DL with no least repulsion (p_min 0: surface pairs, at p = 0, only collide)
    ("new, particle collision jandaghian2021, p_min 0",
     {**PARTICLE_COLLISION, "particle_collision_min_pressure": "0.0"}),
    # 59: the defaults before 2026-12-08, session 15 (row 58 is the default since)
    ("defaults before session 15 (particle_collision none)", NO_COLLISION),
]
L, H = 1.0, 0.5
G = 9.81


def surface_polygon(amplitude):
    """The fluid polygon of the case with the surface h + a cos(pi x / L) through 51 points."""
    pts = [(0.0, 0.0), (L, 0.0)] + [(round(L - 0.02 * i, 2),
                                      H + amplitude * math.cos(math.pi * (L - 0.02 * i) / L))
                                     for i in range(51)]
    return "polygon = [" + ", ".join(f"[{x:g}, {y:.6f}]" for x, y in pts) + "]"


def case_text(physics, dl, amplitude=None):
    text = CASE.read_text()
    text = re.sub(r"(?m)^spacing = [0-9.e-]+", f"spacing = {dl}", text)
    if amplitude is not None:
        text = re.sub(r"(?m)^polygon = .*$", surface_polygon(amplitude), text)
    # "particles.KEY" goes to [particles], after the spacing
    for k, v in physics.items():
        if k.startswith("particles."):
            text = re.sub(r"(?m)^(spacing = .*)$", rf"\1\n{k[10:]} = {v}", text, count=1)
    physics = {k: v for k, v in physics.items() if not k.startswith("particles.")}
    for k, v in physics.items():  # keys the case sets already are replaced
        if re.search(rf"(?m)^{k} = ", text):
            text = re.sub(rf"(?m)^{k} = .*$", f"{k} = {v}", text)
    lines = "".join(f"{k} = {v}\n" for k, v in physics.items()
                    if not k.startswith("time.") and not re.search(rf"(?m)^{k} = ", text))
    times = "".join(f"{k[5:]} = {v}\n" for k, v in physics.items() if k.startswith("time."))
    text = text.replace("[time]\n", "[time]\n" + times, 1)
    text = re.sub(r"(?m)^x = \[.*$", "x = [" + ", ".join(f"{x:g}" for x in GAUGES) + "]", text)
    return text.replace("[physics]\n", "[physics]\n" + lines, 1)


# The gauges the runs record: a DL off each wall (the antinodes, the first measure) and every
# 0.05 m between (the mode's shape, the second).
GAUGES = [0.02] + [round(0.05 * k, 2) for k in range(1, 20)] + [0.98]


def read_gauges(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    xs = np.array([float(re.search(r"x = ([-0-9.e]+) m", h).group(1)) for h in rows[0][1:]])
    data = np.array([[float(v) for v in r] for r in rows[1:]])
    return data[:, 0], xs, data[:, 1:]


def up_crossings(t, eta):
    return [t[k] - eta[k] * (t[k + 1] - t[k]) / (eta[k + 1] - eta[k])
            for k in range(len(t) - 1) if eta[k] < 0 <= eta[k + 1]]


def analyse_antinodes(t, xs, eta):
    """The first measure: the two antinode gauges' up-crossings and extrema. An extremum is the
    largest |eta - mean| between two zero crossings, so the acoustic ripple of a gauge near its
    zero adds small extrema of its own to the fit: it reads the loss high where the record is
    noisy."""
    periods, ext_t, ext_a = [], [], []
    for c in [k for k, x in enumerate(xs) if abs(x - L / 2) > 0.47]:  # x = 0.02, 0.98 m
        e = eta[:, c] - np.nanmean(eta[:, c])
        periods += list(np.diff(up_crossings(t, e)))
        zc = [k for k in range(len(t) - 1) if (e[k] < 0) != (e[k + 1] < 0)]
        for a, b in zip(zc[:-1], zc[1:]):
            seg = np.abs(e[a + 1:b + 1])
            if len(seg) == 0:
                continue
            k = a + 1 + int(np.argmax(seg))
            ext_t.append(t[k])
            ext_a.append(abs(e[k]))
    period = float(np.mean(periods)) if periods else float("nan")
    b = np.polyfit(ext_t, np.log(ext_a), 1)[0] if len(ext_t) > 2 else float("nan")
    return period, b


def mode_amplitude(t, xs, eta):
    """a1(t): the surface's first sloshing mode, the least-squares fit of
    eta(x) - <eta(x)> = a0 + a1 cos(pi x / L) + a2 cos(2 pi x / L) over the gauges 0.05 to
    0.95 m (19 of them): the gauges' own offsets, the acoustic ripple of one gauge and the second
    harmonic do not enter a1."""
    inner = (xs > 0.04) & (xs < 0.96)
    x = xs[inner]
    e = eta[:, inner] - np.nanmean(eta[:, inner], axis=0)
    basis = np.stack([np.ones_like(x), np.cos(np.pi * x / L), np.cos(2 * np.pi * x / L)], axis=1)
    coef, *_ = np.linalg.lstsq(basis, e.T, rcond=None)
    return coef[1]


def analyse_mode(t, a1, period_linear):
    """The second measure, from a1(t): the period from its up-crossings, and the loss from the
    slope of a least-squares line through log of its envelope (the modulus of the analytic
    signal, by FFT), leaving out the first and last half period, where the transform's ends
    distort it: b over the whole record, and b_late from the third period on (the first two
    periods lose more: the start's transient)."""
    a = a1 - np.mean(a1)
    up = up_crossings(t, a)
    period = float(np.mean(np.diff(up))) if len(up) > 1 else float("nan")
    n = len(a)
    spectrum = np.fft.fft(a)
    h = np.zeros(n)
    h[0] = 1.0
    h[1:(n + 1) // 2] = 2.0
    if n % 2 == 0:
        h[n // 2] = 1.0
    envelope = np.abs(np.fft.ifft(spectrum * h))
    end = t[-1] - 0.5 * period_linear
    keep = (t > 0.5 * period_linear) & (t < end)
    late = (t > 2.0 * period_linear) & (t < end)
    b = np.polyfit(t[keep], np.log(envelope[keep]), 1)[0] if keep.sum() > 10 else float("nan")
    b_late = np.polyfit(t[late], np.log(envelope[late]), 1)[0] if late.sum() > 10 else float("nan")
    return period, b, b_late


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--wcmps", default=str(ROOT / "build" / "bin" / "wcmps"))
    ap.add_argument("--out", default="runs/standing-wave-schemes")
    ap.add_argument("--dl", type=float, default=0.01)
    ap.add_argument("--end", type=float, default=6.0)
    ap.add_argument("--amplitude", type=float,
                    help="the wave's amplitude a (m) instead of the case's 10 mm")
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
    print("| scheme | DL (m) | period / linear (mode) | amplitude lost per period (mode) "
          "| the same from the third period | period / linear (antinodes) "
          "| lost per period (antinodes) |")
    print("|---|---|---|---|---|---|---|")
    wanted = [int(k) for k in args.schemes.split(",")]
    for k_s, (name, physics) in enumerate(SCHEMES):
        if k_s not in wanted:
            continue
        run = out / f"scheme{k_s}"
        if not args.reuse:
            case = out / f"scheme{k_s}.toml"
            case.write_text(case_text(physics, args.dl, args.amplitude))
            r = subprocess.run([args.wcmps, "run", str(case), "-o", str(run), "--overwrite",
                                "--end-time", str(args.end), "--threads", str(args.threads)],
                               capture_output=True, text=True)
            if r.returncode != 0:
                print(f"| {name} | {args.dl} | run failed: {r.stderr.strip()[-200:]} | | | | |")
                continue
        t, xs, eta = read_gauges(run / "gauges.csv")
        period_mode, b_mode, b_late = analyse_mode(t, mode_amplitude(t, xs, eta), period_linear)
        period_anti, b_anti = analyse_antinodes(t, xs, eta)
        cols = [f"{100 * (1.0 - math.exp(b * period_linear)):.2f} %"
                for b in (b_mode, b_late, b_anti)]
        print(f"| {name} | {args.dl} | {period_mode / period_linear:.4f} | {cols[0]} | {cols[1]} "
              f"| {period_anti / period_linear:.4f} | {cols[2]} |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
