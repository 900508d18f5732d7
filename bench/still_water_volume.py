#!/usr/bin/python3
"""Does still water keep its volume? (docs/validation.md, "The still water swells".)

Still water (cases/hydrostatic, DL = 10 mm) for 4 s, a frame every 0.1 s, with variants of the
defaults. The particles carry fixed masses, so the fluid's centre of mass rises only if the
water's volume grows. For the deep water (deeper than 0.1 m, 0.05 m or more from the walls and
the bottom) the table compares the number density the particles carry (the evolved n of the
equation of state) with the number density of their arrangement, summed anew from the frame's
positions with the solver's kernel (1 - r/re)^3 over every particle, walls and ghosts included.
The two start equal (the difference is measured from t = 0); a growing gap means the particles
spread while their n, and with it their pressure, does not see it.

    bench/still_water_volume.py [--wcmps build/bin/wcmps] [--out runs/still-water-volume]
                                [--variants 0,1,2,3,4] [--reuse]

Runs the variants two at a time, one thread each.
"""
import argparse
import concurrent.futures
import glob
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

ROOT = Path(__file__).resolve().parent.parent
CASE = ROOT / "cases" / "hydrostatic" / "case.toml"
DL = 0.01
RE = 3.5 * DL  # the case's re / DL (the default)
H, WIDTH = 0.7, 0.5
# (label, extra [physics] keys)
VARIANTS = [
    ("defaults", {}),
    ("density_diffusion 0", {"density_diffusion": "0.0"}),
    ("shifting none", {"shifting": '"none"'}),
    ("shifting_in_continuity true", {"shifting_in_continuity": "true"}),
    ("shifting_in_continuity true, density_diffusion 0",
     {"shifting_in_continuity": "true", "density_diffusion": "0.0"}),
    ("surface_pressure_cap false", {"surface_pressure_cap": "false"}),
]


def case_text(physics, end):
    text = CASE.read_text()
    keys = "".join(f"{k} = {v}\n" for k, v in physics.items())
    text = text.replace("[physics]\n", "[physics]\n" + keys, 1)
    text = re.sub(r"(?m)^end = .*$", f"end = {end}", text)
    return re.sub(r"(?m)^interval = .*$", "interval = 0.1", text)


def frame_measures(path):
    """Time, mean y of the fluid, and the deep water's mean carried and summed n."""
    r = vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    pd = r.GetOutput()
    xy = vtk_to_numpy(pd.GetPoints().GetData())[:, :2]
    data = pd.GetPointData()
    kind = vtk_to_numpy(data.GetArray("kind"))
    carried = vtk_to_numpy(data.GetArray("number_density"))
    pairs = cKDTree(xy).query_pairs(RE, output_type="ndarray")
    w = (1.0 - np.linalg.norm(xy[pairs[:, 0]] - xy[pairs[:, 1]], axis=1) / RE) ** 3
    summed = np.bincount(pairs[:, 0], w, len(xy)) + np.bincount(pairs[:, 1], w, len(xy))
    x, y = xy[:, 0], xy[:, 1]
    fluid = kind == 0  # particles/ParticleKind.h: Fluid
    deep = fluid & (y < H - 0.1) & (y > 0.05) & (x > 0.05) & (x < WIDTH - 0.05)
    t = pd.GetFieldData().GetArray("TimeValue").GetValue(0)
    return t, y[fluid].mean(), carried[deep].mean(), summed[deep].mean()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--wcmps", default=str(ROOT / "build" / "bin" / "wcmps"))
    ap.add_argument("--out", default="runs/still-water-volume")
    ap.add_argument("--end", type=float, default=4.0)
    ap.add_argument("--variants", default=",".join(str(k) for k in range(len(VARIANTS))))
    ap.add_argument("--reuse", action="store_true", help="analyse earlier runs in --out")
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    wanted = [int(k) for k in args.variants.split(",")]

    def run(k):
        label, physics = VARIANTS[k]
        d = out / f"variant{k}"
        if not args.reuse:
            case = out / f"variant{k}.toml"
            case.write_text(case_text(physics, args.end))
            r = subprocess.run([args.wcmps, "run", str(case), "-o", str(d), "--overwrite",
                                "--threads", "1"], capture_output=True, text=True)
            if r.returncode != 0:
                return f"| {label} | run failed: {r.stderr.strip()[-200:]} | | |", False
        rows = np.array([frame_measures(f) for f in sorted(glob.glob(str(d / "frame_*.vtp")))])
        t, ycm, carried, summed = rows.T
        n0 = summed[0]  # the deep water's summed n at the start, in the solver's n0 units
        gap = (summed - carried) - (summed[0] - carried[0])
        at = [np.argmin(np.abs(t - s)) for s in (1.0, 2.0, 3.0, t[-1])]
        return (f"| {label} | {1000 * (ycm[-1] - ycm[0]):+.2f} | "
                + " ".join(f"{100 * gap[i] / n0:+.3f}" for i in at) + " |"), True

    print(f"| variant | centre of mass, {args.end:g} s - 0 (mm) | deep water: summed n - carried n, "
          "change since t = 0 (% of n), at 1, 2, 3 and "
          f"{args.end:g} s |")
    print("|---|---|---|")
    failed = 0
    with concurrent.futures.ThreadPoolExecutor(2) as ex:
        for line, ok in ex.map(run, wanted):
            print(line, flush=True)
            failed += 0 if ok else 1
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
