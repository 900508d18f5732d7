#!/usr/bin/python3
"""The impact pressure of the Lobovsky et al. (2014) dam break (cases/lobovsky) against their
records of sensors 1 and 3, and the water's level against their gauges H3 and H4, for the
default scheme and the others listed below.

usage: bench/lobovsky_pressure.py [--wcmps build/bin/wcmps] [--out DIR] [--dl 0.005]
                                  [--threads 2] [--reuse] [--plot FILE.png] [--schemes 0,1,2]
                                  [--reading wetted|shepard] [--wall-height 0.6]
                                  [--plot-levels FILE.png]

Each scheme's run writes frames every 1 ms (pressure and kind only). A sensor reads the
pressure the way the experiment's does: averaged over its face, a disc of 4.2 mm on the wall,
here the segment of the wall's surface x = 1.61 m over the sensor's height, sampled at 9 points;
each point takes the kernel average of the fluid particles within re of it, carried to the point
by the hydrostatic term (p_f + rho g (y_f - y), the reading Adami et al. 2012 give a wall).
The average divides by the weights present, but never by less than half of what the point
would weigh under still water (--reading wetted, the default): a point that water covers only in
small part reads that part, as a sensor's face that is partly dry carries the pressure over its
wet part only. (Half, not the whole: the water beside a wall after the impact sits a little
farther from it than the lattice does, and a fully wet point would read low.) --reading shepard
divides by the weights present alone (the Shepard average, as before 2026-12-02): a point then
reads the full pressure of a single particle up to re away, and the first particles to strike
the wall (the most compressed) set the reading of every point within re of them, dry or not.
Times are t (g/H)^1/2 and pressures p / (rho g H), H = 0.3 m, as the paper plots them.

Metrics for each sensor: the impact time (first sample at or above 0.1 rho g H), the peak (the
largest sample within 0.3 of the impact), the level after (the mean over t* = 3.5 ... 3.8),
and the noise (rms of the signal about its running mean over 0.1 in t*, from impact + 0.3 to
t* = 4.5).

The experiment's record: Lobovsky et al.'s data for H = 300 mm, sensor 1, peak event 5, as held
by TNL-Project/TNL-SPH (examples/resources/damBreak2D/damBreak2D_experimentalDataLobovsky2014/
pressure/Fig18_peak_event_5_sensors_5.dat: t*, p/(rho g H) at 20 kHz, 24,000 samples). Its
numbers below were read from that file: the samples rise from 0.01 at t* = 2.4423 through 0.099
(2.44347) and 0.164 (2.44375) to the peak 3.044 at t* = 2.45462, fall to 2.0 by t* = 2.57 and
1.5 by 2.71; from t* = 3.548 to 3.820 every sample lies between 0.736 and 0.786 (mean 0.765 to
the precision of reading). The record's sample-to-sample noise on that plateau is about 0.002
(its quantisation is 0.00036). One event: Lobovsky et al. repeated the impact about 100 times
and show the peak varying widely from event to event, so the peak is compared as an order of
magnitude, the impact time and the level after closely.

The same event's sensor 3 (P3, 30 mm up), held beside it (..._sensors_2.dat, whose header reads
"# sensor 3"), read the same way: it stays under 0.1 until t* = 2.50923 (0.102), then rises
without a spike, through 0.42 (2.528), 1.0 (2.578) and 1.5 (2.64), to its peak 1.544 at
t* = 2.671, and falls slowly (1.23 at 2.98); from t* = 3.500 to 3.800 every sample lies between
0.537 and 0.629 (mean 0.58 to the precision of reading), with sample-to-sample noise of about
0.002. The public record holds no P2 or P4 of this event.

**The water's levels** (added 2026-12-07). Lobovsky et al. also recorded the water's height at
four places along the tank, H1 to H4 at x = 300, 865, 1114 and 1362.5 mm from the upstream wall
(the positions TNL-SPH's measuring tool gives them). The records of H3 and H4 for H = 300 mm
are held beside the pressures (.../waterLevel/Fig16_WaterLevels_H3_4.dat, header "ETSIN 01",
and ..._H4_4.dat, "ETSIN 02": t*, h/H every 0.019 in t*, to t* = 11.2). Their numbers below were
read from those files. H3: the first water at t* = 1.639 (0.004), 0.05 H crossed at 1.709; the
surge's level 0.159 to 0.165 over t* 2.2-2.6 (mean 0.163), rising to a mean of 0.206 over
3.5-3.8; the bore reflected from the far wall crosses 0.4 H at t* 6.792 (0.374 at 6.786, 0.458 at
6.805); the largest level to t* 7.4 is 0.582 (6.976). H4: the first water at 2.154 (0.016), 0.05 H
crossed at 2.231; the surge's level 0.130 to 0.132 over 2.8-3.4 (mean 0.131), 0.137 over
3.5-3.8; the reflected bore crosses 0.5 H at t* 6.116 (0.407 at 6.100, 0.513 at 6.119); the
largest level to t* 7.4 is 0.811 (7.167). The level records come from other runs of the
experiment than the pressure record, and their clock need not start where the pressures' does:
the surge's passage from H3 to H4 (0.522 in t* at 0.05 H) is free of that, its arrival at each is not.
A level is read from a frame as the highest point of the gauge's vertical line at which the fluid
particles within re weigh at least half of what a point inside still water weighs (the kernel
of the pressure's points, the same half): a point on a still surface weighs about half, so the
reading is the surface, and a lone drop of spray weighs less than half and is not read (the
column's initial height reads 0.996 H at H1).
"""
import argparse
import functools
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

# bench/, beside the script
from physics_options import (FREE_SLIP, NO_COLLISION, OLD, PARTICLE_COLLISION, PLAIN,
                             SIDE_WALLS_LOBOVSKY, STRAIN, WALL_FRICTION)

ROOT = Path(__file__).resolve().parent.parent
CASE = ROOT / "cases" / "lobovsky" / "case.toml"
H, RHO, G, WALL_X = 0.3, 1000.0, 9.81, 1.61
SENSORS = {"P1": 0.003, "P2": 0.015, "P3": 0.030, "P4": 0.080}
GAUGES = {"H1": 0.300, "H2": 0.865, "H3": 1.114, "H4": 1.3625}  # x of the level gauges (m)
SENSOR_SIZE = 0.0042
# A point of a sensor is wet when the fluid near it weighs at least this share of what still
# water would put there; below it, it reads its wet part only (see the module's text).
WET_SHARE = 0.5
EXPERIMENT = {
    "P1": {"impact": 2.4438, "peak": 3.044, "peak_t": 2.455, "after": 0.765, "noise": 0.002,
           "points": ([2.4438, 2.4438, 2.455, 2.57, 2.71, 3.55, 3.82],
                      [0.0, 0.16, 3.044, 2.0, 1.5, 0.765, 0.765])},
    "P3": {"impact": 2.509, "peak": 1.544, "peak_t": 2.671, "after": 0.58, "noise": 0.002,
           "points": ([2.509, 2.528, 2.578, 2.64, 2.671, 2.98, 3.5, 3.8],
                      [0.10, 0.42, 1.0, 1.5, 1.544, 1.23, 0.58, 0.58])},
}
# The level records' numbers (see the module's text): the surge's arrival (0.05 H crossed), its
# level over a window where the record is flat, the level over t* 3.5-3.8 (the pressure's "after"
# window), the reflected bore (the level crossing bore_level after t* 4.5) and the largest level
# from t* 4.5 to the runs' end, t* 7.4.
LEVEL_ARRIVAL = 0.05
EXPERIMENT_LEVELS = {
    "H3": {"arrival": 1.709, "surge_window": (2.2, 2.6), "surge": 0.163, "after": 0.206,
           "bore_level": 0.4, "bore": 6.792, "largest": 0.582,
           "points": ([1.639, 1.709, 2.0, 2.4, 3.0, 3.65, 4.5, 5.5, 6.6, 6.792, 6.976, 7.3],
                      [0.004, 0.05, 0.147, 0.164, 0.173, 0.205, 0.230, 0.238, 0.242, 0.4, 0.582,
                       0.499])},
    "H4": {"arrival": 2.231, "surge_window": (2.8, 3.4), "surge": 0.131, "after": 0.137,
           "bore_level": 0.5, "bore": 6.116, "largest": 0.811,
           "points": ([2.154, 2.231, 2.5, 3.0, 3.65, 4.5, 5.5, 6.0, 6.116, 6.4, 7.167],
                      [0.016, 0.05, 0.113, 0.131, 0.136, 0.181, 0.237, 0.359, 0.5, 0.741, 0.811])},
}
SCHEMES = [("new default", {}), ("3a85288 scheme", OLD),
           ("surface_pressure_cap false", {"surface_pressure_cap": "false"}),
           ("gradient_renormalisation khayyer2011",
            {"gradient_renormalisation": '"khayyer2011"'}),
           ("gradient_renormalisation khayyer2011-hydrostatic",
            {"gradient_renormalisation": '"khayyer2011-hydrostatic"'}),
           ("density_rate randles1996", {"density_rate": '"randles1996"'}),
           ("wall_density adami2012", {"wall_density": '"adami2012"'}),
           ("wall_density adami2012, artificial_viscosity 0",
            {"wall_density": '"adami2012"', "artificial_viscosity": "0.0"}),
           ("wall_density n0 (the default until 2026-12-04)", {"wall_density": '"n0"'}),
           ("density_rate summed (the default until 2026-12-04, later)",
            {"density_rate": '"summed"'}),
           ("gradient_renormalisation khayyer2011-deviatoric",
            {"gradient_renormalisation": '"khayyer2011-deviatoric"'}),
           ("gradient_renormalisation khayyer2011-strain",
            STRAIN),
           ("artificial_viscosity_walls free-slip", FREE_SLIP),
           ("gradient_renormalisation khayyer2011-strain, artificial_viscosity_walls free-slip",
            {**STRAIN, **FREE_SLIP}),
           ("artificial_viscosity_walls free-slip, wall_friction spalding1961",
            {**FREE_SLIP, **WALL_FRICTION}),
           ("khayyer2011-strain, artificial_viscosity_walls free-slip, wall_friction spalding1961",
            {**STRAIN, **FREE_SLIP, **WALL_FRICTION}),
           ("artificial_viscosity_walls free-slip, wall_friction and side_wall_friction "
            "spalding1961 (flume_width 0.15)",
            {**FREE_SLIP, **WALL_FRICTION, **SIDE_WALLS_LOBOVSKY}),
           ("side_wall_friction spalding1961 (flume_width 0.15)", SIDE_WALLS_LOBOVSKY),
           ("khayyer2011-strain, artificial_viscosity_walls free-slip, wall_friction and "
            "side_wall_friction spalding1961 (flume_width 0.15)",
            {**STRAIN, **FREE_SLIP, **WALL_FRICTION, **SIDE_WALLS_LOBOVSKY}),
           ("defaults before session 13 (gradient_renormalisation none)", PLAIN),
           # 20 (session 14): the particle collision between fluid particles, l0 = DL (as
           # measured then; the option's default became 0.8 DL after it)
           ("particle_collision jandaghian2021, l0 DL",
            {**PARTICLE_COLLISION, "particle_collision_distance": "1.0"}),
           ("particle_collision jandaghian2021, l0 0.8 DL",
            {**PARTICLE_COLLISION, "particle_collision_distance": "0.8"}),
           ("particle_collision jandaghian2021, l0 DL, no repulsion",
            {**PARTICLE_COLLISION, "particle_collision_distance": "1.0",
             "particle_collision_lambda": "0.0",
             "particle_collision_min_pressure": "0.0"}),
           ("particle_collision jandaghian2021, l0 0.8 DL, elastic",
            {**PARTICLE_COLLISION, "particle_collision_distance": "0.8",
             "particle_collision_restitution": "1.0"}),
           ("particle_collision jandaghian2021, p_min 0",
            {**PARTICLE_COLLISION, "particle_collision_min_pressure": "0.0"}),
           # 25: the defaults before 2026-12-08, session 15 (row 24 is the default since)
           ("defaults before session 15 (particle_collision none)", NO_COLLISION)]


def case_text(physics, dl, wall_height=0.6):
    text = CASE.read_text()
    text = re.sub(r"(?m)^spacing = [0-9.e-]+", f"spacing = {dl}", text)
    if wall_height != 0.6:
        old = "polyline = [[0.0, 0.6], [0.0, 0.0], [1.61, 0.0], [1.61, 0.6]]"
        assert old in text, "cases/lobovsky's walls are not the ones --wall-height rewrites"
        text = text.replace(old, old.replace("0.6]", f"{wall_height}]"))
    text = re.sub(r"(?m)^interval = [0-9.e-]+.*$", 'interval = 0.001\nfields = ["pressure", "kind"]',
                  text)
    keys = "".join(f"{k} = {v}\n" for k, v in physics.items())
    return text.replace("[physics]\n", "[physics]\n" + keys, 1)


@functools.lru_cache(maxsize=None)
def wet_weight(y, re_radius, dl):
    """The weight sum of the point (WALL_X, y) on the wall under still water: the fluid lattice
    of the scene (its first column and row DL/2 off the wall's and the floor's surfaces), which
    fills the quarter of the kernel between wall and floor near the corner (P1, P2) and the half
    beside the wall above it."""
    i, j = np.meshgrid(np.arange(int(re_radius / dl) + 2), np.arange(int((y + re_radius) / dl) + 2))
    d = np.hypot((i + 0.5) * dl, (j + 0.5) * dl - y)
    return float((np.clip(1.0 - d / re_radius, 0.0, None) ** 3).sum())


def read_frame(frame):
    """The frame's time and its fluid particles' positions and pressures."""
    r = vtkXMLPolyDataReader()
    r.SetFileName(str(frame))
    r.Update()
    pd = r.GetOutput()
    t = pd.GetFieldData().GetArray("TimeValue").GetValue(0)
    kind = vtk_to_numpy(pd.GetPointData().GetArray("kind"))
    xy = vtk_to_numpy(pd.GetPoints().GetData())[kind == 0][:, :2]
    p = vtk_to_numpy(pd.GetPointData().GetArray("pressure"))[kind == 0]
    return t, xy, p


@functools.lru_cache(maxsize=None)
def interior_weight(re_radius, dl):
    """The weight sum of a point of the fluid lattice far from walls and surface."""
    n = int(re_radius / dl) + 1
    i, j = np.meshgrid(np.arange(-n, n + 1), np.arange(-n, n + 1))
    return float((np.clip(1.0 - np.hypot(i * dl, j * dl) / re_radius, 0.0, None) ** 3).sum())


def read_levels(xy, re_radius, dl):
    """The water's level at each gauge (m): the highest point of its vertical line whose fluid
    weighs at least half of an interior point's (see the module's text)."""
    ys = np.arange(0.0, xy[:, 1].max() + re_radius, dl / 4) if len(xy) else np.zeros(0)
    out = {}
    for name, xg in GAUGES.items():
        q = xy[np.abs(xy[:, 0] - xg) < re_radius]
        if len(q) == 0 or len(ys) == 0:
            out[name] = 0.0
            continue
        d = np.hypot(q[None, :, 0] - xg, q[None, :, 1] - ys[:, None])
        w = (np.clip(1.0 - d / re_radius, 0.0, None) ** 3).sum(axis=1)
        wet = np.nonzero(w >= WET_SHARE * interior_weight(re_radius, dl))[0]
        out[name] = float(ys[wet[-1]]) if len(wet) else 0.0
    return out


def read_sensors(xy, p, re_radius, dl, shepard=False):
    near = xy[:, 0] > WALL_X - re_radius
    xy, p = xy[near], p[near]
    out = {}
    for name, yc in SENSORS.items():
        readings = []
        for y in yc + np.linspace(-0.5, 0.5, 9) * SENSOR_SIZE:
            d = np.hypot(xy[:, 0] - WALL_X, xy[:, 1] - y)
            w = np.clip(1.0 - d / re_radius, 0.0, None) ** 3
            s = w.sum()
            wet = 0.0 if shepard else WET_SHARE * wet_weight(y, re_radius, dl)
            if s > 0:
                readings.append(((p + RHO * G * (xy[:, 1] - y)) * w).sum() / max(s, wet))
            else:
                readings.append(0.0)
        out[name] = float(np.mean(readings))
    return out


def metrics(ts, ps):
    ts, ps = np.asarray(ts), np.asarray(ps)
    hit = np.nonzero(ps >= 0.1)[0]
    if len(hit) == 0:
        return None
    ti = ts[hit[0]]
    win = (ts >= ti) & (ts <= ti + 0.3)
    k = np.argmax(np.where(win, ps, -np.inf))
    after = ps[(ts >= 3.5) & (ts <= 3.8)].mean()
    span = (ts >= ti + 0.3) & (ts <= 4.5)
    dt = np.median(np.diff(ts))
    half = max(1, int(round(0.05 / dt)))
    kernel = np.ones(2 * half + 1) / (2 * half + 1)
    mean = np.convolve(ps, kernel, mode="same")
    noise = math.sqrt(np.mean((ps[span] - mean[span]) ** 2))
    return {"impact": ti, "peak": ps[k], "peak_t": ts[k], "after": after, "noise": noise}


def crossing(ts, hs, level, after=0.0):
    """The first t* >= after at which hs reaches level, interpolated; nan if it never does."""
    k = np.nonzero((hs >= level) & (ts >= after))[0]
    if len(k) == 0:
        return math.nan
    k = k[0]
    if k == 0 or ts[k - 1] < after:
        return float(ts[k])
    return float(ts[k - 1] + (ts[k] - ts[k - 1]) * (level - hs[k - 1]) / (hs[k] - hs[k - 1]))


def level_metrics(ts, hs, gauge):
    """The level record's numbers as EXPERIMENT_LEVELS gives them for the gauge."""
    ts, hs = np.asarray(ts), np.asarray(hs)
    e = EXPERIMENT_LEVELS[gauge]
    lo, hi = e["surge_window"]
    late = ts >= 4.5
    return {"arrival": crossing(ts, hs, LEVEL_ARRIVAL),
            "surge": float(hs[(ts >= lo) & (ts <= hi)].mean()),
            "after": float(hs[(ts >= 3.5) & (ts <= 3.8)].mean()),
            "bore": crossing(ts, hs, e["bore_level"], 4.5),
            "largest": float(hs[late].max()) if late.any() else math.nan}


def two_panels():
    """A figure of two panels, one over the other, sharing t* (matplotlib off-screen)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt.subplots(2, 1, figsize=(8, 6), sharex=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--wcmps", default=str(ROOT / "build" / "bin" / "wcmps"))
    ap.add_argument("--out", default="runs/lobovsky-schemes")
    ap.add_argument("--dl", type=float, default=0.005)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--reuse", action="store_true", help="analyse earlier runs in --out")
    ap.add_argument("--wall-height", type=float, default=0.6,
                    help="the tank's walls (m; the experiment's tank: 0.6). A jet that runs up the "
                    "far wall without drag can go over it and leave the domain, which stops the "
                    "run; a taller wall keeps it in without changing the sensors' record before")
    ap.add_argument("--plot", help="write the sensors' signals to this PNG")
    ap.add_argument("--plot-levels", help="write the levels at H3 and H4 to this PNG")
    ap.add_argument("--reading", choices=("wetted", "shepard"), default="wetted",
                    help="how a point of a sensor averages the fluid near it (see above)")
    ap.add_argument("--schemes", default=",".join(str(k) for k in range(len(SCHEMES))),
                    help="which of the schemes to run or read, by index (default: all): " +
                    "; ".join(f"{k} {name}" for k, (name, _) in enumerate(SCHEMES)))
    args = ap.parse_args()
    chosen = {int(k) for k in args.schemes.split(",")}
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    scale = math.sqrt(G / H)
    series = {}
    for k_s, (name, physics) in enumerate(SCHEMES):
        if k_s not in chosen:
            continue
        run = out / f"scheme{k_s}"
        if not args.reuse:
            case = out / f"scheme{k_s}.toml"
            case.write_text(case_text(physics, args.dl, args.wall_height))
            r = subprocess.run([args.wcmps, "run", str(case), "-o", str(run), "--overwrite",
                                "--threads", str(args.threads)], capture_output=True, text=True)
            if r.returncode != 0:
                print(f"{name}: run failed: {r.stderr.strip()[-300:]}")
                continue
        frames = sorted(run.glob("frame_*.vtp"))
        ts, ps, hs = [], {s: [] for s in SENSORS}, {g: [] for g in GAUGES}
        for f in frames:
            t, xy, p = read_frame(f)
            reading = read_sensors(xy, p, 3.5 * args.dl, args.dl, args.reading == "shepard")
            level = read_levels(xy, 3.5 * args.dl, args.dl)
            ts.append(t * scale)
            for s in SENSORS:
                ps[s].append(reading[s] / (RHO * G * H))
            for g in GAUGES:
                hs[g].append(level[g] / H)
        series[name] = (ts, ps, hs)
    print(f"DL = {args.dl} m; t* = t (g/H)^1/2, p* = p / (rho g H) = p / {RHO * G * H:.0f} Pa")
    print("| sensor | run | impact t* | peak p* (at t*) | level after, t* 3.5-3.8 | noise (rms about the running mean) |")
    print("|---|---|---|---|---|---|")
    for s in SENSORS:
        if s in EXPERIMENT:
            e = EXPERIMENT[s]
            print(f"| {s} | experiment (event 5) | {e['impact']:.3f} | {e['peak']:.2f} "
                  f"({e['peak_t']:.3f}) | {e['after']:.2f} | {e['noise']:.3f} |")
        for name, (ts, ps, _) in series.items():
            m = metrics(ts, ps[s])
            if m is None:
                print(f"| {s} | {name} | no impact | | | |")
                continue
            print(f"| {s} | {name} | {m['impact']:.3f} | {m['peak']:.2f} ({m['peak_t']:.3f}) | "
                  f"{m['after']:.2f} | {m['noise']:.3f} |")
    print()
    print(f"The water's level h / H at the gauges H3 (x = {GAUGES['H3']} m) and H4 "
          f"(x = {GAUGES['H4']} m): the surge's arrival ({LEVEL_ARRIVAL} H crossed), its level "
          "(H3: mean over t* 2.2-2.6, H4: 2.8-3.4), the mean over t* 3.5-3.8, the bore reflected "
          "from the far wall (H3: 0.4 H, H4: 0.5 H crossed after t* 4.5), the largest level after "
          "t* 4.5; and the surge's passage from H3 to H4")
    print("| run | H3 arrival | H3 surge | H3 3.5-3.8 | H3 bore | H3 largest | H4 arrival | "
          "H4 surge | H4 3.5-3.8 | H4 bore | H4 largest | H3 to H4 |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    rows = [("experiment", EXPERIMENT_LEVELS["H3"], EXPERIMENT_LEVELS["H4"])]
    for name, (ts, _, hs) in series.items():
        rows.append((name, level_metrics(ts, hs["H3"], "H3"), level_metrics(ts, hs["H4"], "H4")))
    for name, m3, m4 in rows:
        cells = [f"{m[k]:.3f}" for m in (m3, m4)
                 for k in ("arrival", "surge", "after", "bore", "largest")]
        print(f"| {name} | " + " | ".join(cells) + f" | {m4['arrival'] - m3['arrival']:.3f} |")
    if args.plot:
        fig, axes = two_panels()
        for ax, s in zip(axes, ("P1", "P3")):
            for name, (ts, ps, _) in series.items():
                ax.plot(ts, ps[s], lw=0.8, label=f"wcmps, {name}")
            ax.set_ylabel(f"{s}: p / (rho g H)")
            ax.set_xlim(2.0, 7.0)
            ax.grid(alpha=0.3)
        for ax, s in zip(axes, ("P1", "P3")):
            e = EXPERIMENT[s]
            ax.axhline(e["after"], color="k", ls=":", lw=0.8)
            ax.plot(*e["points"], "k.", label="experiment, event 5 (points read from the record)")
            ax.legend(fontsize=8)
        axes[1].set_xlabel("t (g/H)^1/2")
        fig.suptitle(f"Lobovsky et al. (2014) dam break, H = 300 mm, DL = {args.dl * 1000:g} mm")
        fig.tight_layout()
        fig.savefig(args.plot, dpi=100)
        print(f"wrote {args.plot}")
    if args.plot_levels:
        fig, axes = two_panels()
        for ax, g in zip(axes, ("H3", "H4")):
            for name, (ts, _, hs) in series.items():
                ax.plot(ts, hs[g], lw=0.8, label=f"wcmps, {name}")
            ax.plot(*EXPERIMENT_LEVELS[g]["points"], "k.",
                    label="experiment (points read from the record)")
            ax.set_ylabel(f"{g} (x = {GAUGES[g]} m): h / H")
            ax.set_xlim(1.0, 7.5)
            ax.grid(alpha=0.3)
        axes[0].legend(fontsize=7, loc="upper left")  # over the dry gauge, before the surge
        axes[1].set_xlabel("t (g/H)^1/2")
        fig.suptitle(f"Lobovsky et al. (2014) dam break, water levels, DL = {args.dl * 1000:g} mm")
        fig.tight_layout()
        fig.savefig(args.plot_levels, dpi=100)
        print(f"wrote {args.plot_levels}")


if __name__ == "__main__":
    sys.exit(main())
