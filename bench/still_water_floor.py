#!/usr/bin/python3
"""The still water's late motion (cases/hydrostatic, DL 10 mm) for variants of the scheme, each
run at several Courant numbers: builds and schemes that differ only in rounding take different
paths after a second or so (the test Hydrostatic.FlatTankDl10mm follows one of them), so a
variant is judged by the spread of a few paths, not by one.

usage: bench/still_water_floor.py [--wcmps build/bin/wcmps] [--out DIR] [--end 7]
                                  [--variants 0,1] [--courants 0.38,0.39,0.41,0.42] [--jobs 2]
                                  [--reuse]

Frames every 0.05 s. Per run: the largest rms particle speed over the last 0.5 s and its share
of the run's largest (the start-up transient's peak), the measures of the test; the rms of
p - rho g (H - y) over the last 0.5 s below the top 3.5 DL, in per cent of rho g H; at the end,
the rms speed by region: within 3.5 cm of a wall, within 3.5 cm of the surface (and not of a
wall), and the rest; and over the last 4 s, the part of the motion that stands still in time
(the velocity averaged over the frames in cells of 5 cm, its rms weighted by the particles in
each cell) and the rms speed of the surface row (the top DL, 3.5 cm or more from the side
walls), where the motion is largest. Prints a Markdown table, then the median of each variant.
"""
import argparse
import concurrent.futures
import glob
import re
import statistics
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from physics_options import FREE_SLIP, NO_COLLISION, PLAIN, STRAIN, WALL_FRICTION  # bench/, beside the script

ROOT = Path(__file__).resolve().parent.parent
CASE = ROOT / "cases" / "hydrostatic" / "case.toml"
H, WIDTH, RHO, G, STRIP, DL = 0.7, 0.5, 1000.0, 9.81, 0.035, 0.01
CELL, WINDOW = 0.05, 4.0  # m, s: the steady part's cells and the window of the last two measures
VARIANTS = [
    ("defaults", {}),
    ("gradient_renormalisation khayyer2011-deviatoric",
     {"gradient_renormalisation": '"khayyer2011-deviatoric"'}),
    ("gradient_renormalisation khayyer2011-hydrostatic",
     {"gradient_renormalisation": '"khayyer2011-hydrostatic"'}),
    ("gradient_renormalisation khayyer2011-strain",
     STRAIN),
    ("artificial_viscosity_walls free-slip", FREE_SLIP),
    ("khayyer2011-strain, artificial_viscosity_walls free-slip",
     {**STRAIN, **FREE_SLIP}),
    ("artificial_viscosity_walls free-slip, wall_friction spalding1961",
     {**FREE_SLIP, **WALL_FRICTION}),
    ("khayyer2011-strain, artificial_viscosity_walls free-slip, wall_friction spalding1961",
     {**STRAIN, **FREE_SLIP, **WALL_FRICTION}),
    ("defaults before session 13 (gradient_renormalisation none)", PLAIN),
    ("defaults before session 15 (particle_collision none)", NO_COLLISION),
]


def case_text(physics, courant, end):
    text = CASE.read_text()
    keys = "".join(f"{k} = {v}\n" for k, v in physics.items())
    text = text.replace("[physics]\n", "[physics]\n" + keys, 1)
    text = re.sub(r"(?m)^end = .*$", f"end = {end}\ncourant = {courant}", text)
    return re.sub(r"(?m)^interval = .*$", "interval = 0.05", text)


def frame(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    out = reader.GetOutput()
    pd = out.GetPointData()
    fields = {pd.GetArrayName(k): vtk_to_numpy(pd.GetArray(k))
              for k in range(pd.GetNumberOfArrays())}
    return vtk_to_numpy(out.GetPoints().GetData()), fields


def measure(run, end):
    pvd = ET.parse(next(Path(run).glob("*.pvd"))).getroot()
    frames = sorted((float(d.get("timestep")), d.get("file")) for d in pvd.iter("DataSet"))
    peak = late = 0.0
    err2, count = 0.0, 0
    regions = None
    cells = np.zeros((int(WIDTH / CELL) + 1, int(1.5 * H / CELL) + 1, 2))
    in_cell = np.zeros(cells.shape[:2])
    top2, top_count = 0.0, 0
    for t, name in frames:
        if t < 0.04:
            continue
        pts, f = frame(Path(run) / name)
        fluid = f["kind"] == 0
        x, y = pts[fluid, 0], pts[fluid, 1]
        vel = f["velocity"][fluid]
        speed2 = vel[:, 0] ** 2 + vel[:, 1] ** 2
        rms = float(np.sqrt(speed2.mean()))
        peak = max(peak, rms)
        if t >= end - 0.5 - 1e-9:
            late = max(late, rms)
            deep = y < H - STRIP
            e = f["pressure"][fluid][deep] - RHO * G * (H - y[deep])
            err2 += float(np.sum(e ** 2))
            count += int(deep.sum())
        if t >= end - WINDOW - 1e-9:
            ix = np.clip((x / CELL).astype(int), 0, cells.shape[0] - 1)
            iy = np.clip((y / CELL).astype(int), 0, cells.shape[1] - 1)
            np.add.at(cells, (ix, iy), vel[:, :2])
            np.add.at(in_cell, (ix, iy), 1)
            top = (H - y < DL) & (np.minimum(x, WIDTH - x) >= STRIP)
            top2 += float(speed2[top].sum())
            top_count += int(top.sum())
        if t >= end - 1e-9:
            wall = np.minimum(np.minimum(x, WIDTH - x), y) < STRIP
            surface = (H - y < STRIP) & ~wall
            rest = ~wall & ~surface
            regions = [float(np.sqrt(speed2[m].mean())) for m in (wall, surface, rest)]
    held = in_cell > 0
    mean = cells[held] / in_cell[held][:, None]
    steady = float(np.sqrt(((mean ** 2).sum(axis=1) * in_cell[held]).sum() / in_cell[held].sum()))
    surface_row = float(np.sqrt(top2 / max(top_count, 1)))
    return (late, late / peak, 100.0 * np.sqrt(err2 / count) / (RHO * G * H), regions, steady,
            surface_row)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--wcmps", default=str(ROOT / "build" / "bin" / "wcmps"))
    ap.add_argument("--out", default="/tmp/wcmps-still-water-floor")
    ap.add_argument("--end", type=float, default=7.0)
    ap.add_argument("--variants", default="0,1")
    ap.add_argument("--courants", default="0.38,0.39,0.41,0.42")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--reuse", action="store_true", help="measure the runs already in --out")
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    runs = [(v, c) for v in (int(k) for k in args.variants.split(","))
            for c in args.courants.split(",")]

    def run(vc):
        v, c = vc
        d = out / f"v{v}_c{c}"
        if not args.reuse:
            case = out / f"v{v}_c{c}.toml"
            case.write_text(case_text(VARIANTS[v][1], c, args.end))
            subprocess.run([args.wcmps, "run", str(case), "-o", str(d), "--overwrite",
                            "--threads", "1"], check=True, stdout=subprocess.DEVNULL)
        return vc, measure(d, args.end)

    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = dict(pool.map(run, runs))
    print("| variant | Courant | rms speed, last 0.5 s (m/s) | of the peak | p error rms (% rho g H) "
          "| at the end: wall strip / under the surface / rest (m/s) "
          "| last 4 s: steady part; surface row (m/s) |")
    print("|---|---|---|---|---|---|---|")
    for (v, c), (late, share, perr, reg, steady, row) in results.items():
        print(f"| {VARIANTS[v][0]} | {c} | {late:.4f} | {share:.2f} | {perr:.2f} | "
              f"{reg[0]:.4f} / {reg[1]:.4f} / {reg[2]:.4f} | {steady:.5f}; {row:.4f} |")
    for v in sorted({v for v, _ in runs}):
        mine = [r for (w, _), r in results.items() if w == v]
        print(f"median, {VARIANTS[v][0]}: rms {statistics.median(r[0] for r in mine):.4f} m/s, "
              f"of the peak {statistics.median(r[1] for r in mine):.2f}, "
              f"p error {statistics.median(r[2] for r in mine):.2f} %, "
              f"steady part {statistics.median(r[4] for r in mine):.5f} m/s, "
              f"surface row {statistics.median(r[5] for r in mine):.4f} m/s")


if __name__ == "__main__":
    main()
