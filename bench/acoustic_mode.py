#!/usr/bin/python3
"""The breathing mode of still water: whether the slowest acoustic mode of the tank of
cases/hydrostatic (DL 10 mm, 0.7 m deep) dies out or grows, for variants of the scheme.

usage: bench/acoustic_mode.py [--wcmps build/bin/wcmps] [--out DIR] [--end 4]
                              [--variants 0,1,...] [--jobs 2] [--reuse]

Each variant runs with one thread and writes the fluid's pressure every 0.01 s. The measure is
the mean, over the water deeper than 0.1 m, of p - rho g (H - y): zero in the discrete still
state, and the quarter-wave mode of the column (closed bottom, free top: f = c0 / (4 H), 13 Hz
at the default c0 = 37 m/s, 26 Hz at twice it; both under the 50 Hz that samples every 0.01 s
resolve) where the water breathes. The table gives the largest |mean| in each 0.5 s of the run,
its frequency (the peak of the spectrum after 1 s) and the ratio of the last window to the one
at 0.5-1.0 s: above 1 the mode grows. Its last column is how far the fluid's centre of mass
rose over the run: the particles carry fixed masses, so a rise is the water's volume growing
(its mean density falling), which still water should not do.
"""
import argparse
import concurrent.futures
import glob
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from physics_options import FREE_SLIP, NO_COLLISION, OLD, PLAIN, STRAIN, WALL_FRICTION  # bench/

ROOT = Path(__file__).resolve().parent.parent
CASE = ROOT / "cases" / "hydrostatic" / "case.toml"
H, RHO, G = 0.7, 1000.0, 9.81
# (label, sound_speed_factor, extra [physics] keys)
VARIANTS = [
    ("defaults", 10, {}),
    ("defaults, c0 x 2", 20, {}),
    ("3a85288 scheme", 10, OLD),
    ("3a85288 scheme, c0 x 2", 20, OLD),
    ("density_diffusion 0", 10, {"density_diffusion": "0.0"}),
    ("density_diffusion 0, c0 x 2", 20, {"density_diffusion": "0.0"}),
    ("density_diffusion 0.05", 10, {"density_diffusion": "0.05"}),
    ("density_diffusion_scheme molteni2009, c0 x 2", 20,
     {"density_diffusion_scheme": '"molteni2009"'}),
    ("shifting none", 10, {"shifting": '"none"'}),
    ("shifting none, c0 x 2", 20, {"shifting": '"none"'}),
    ("artificial_viscosity 0", 10, {"artificial_viscosity": "0.0"}),
    ("wall_pressure eos", 10, {"wall_pressure": '"eos"'}),
    ("eos_exponent 1 (linear), c0 x 2", 20, {"eos_exponent": "1.0"}),
    ("shifting_in_continuity true", 10, {"shifting_in_continuity": "true"}),
    ("shifting_in_continuity true, c0 x 2", 20, {"shifting_in_continuity": "true"}),
    ("shifting_in_continuity true, artificial_viscosity 0", 10,
     {"shifting_in_continuity": "true", "artificial_viscosity": "0.0"}),
    ("surface_pressure_cap false", 10, {"surface_pressure_cap": "false"}),
    ("gradient_renormalisation khayyer2011", 10, {"gradient_renormalisation": '"khayyer2011"'}),
    ("gradient_renormalisation khayyer2011, c0 x 2", 20,
     {"gradient_renormalisation": '"khayyer2011"'}),
    ("gradient_renormalisation khayyer2011-hydrostatic", 10,
     {"gradient_renormalisation": '"khayyer2011-hydrostatic"'}),
    ("gradient_renormalisation khayyer2011-hydrostatic, c0 x 2", 20,
     {"gradient_renormalisation": '"khayyer2011-hydrostatic"'}),
    ("density_rate randles1996", 10, {"density_rate": '"randles1996"'}),
    ("density_rate randles1996, c0 x 2", 20, {"density_rate": '"randles1996"'}),
    ("wall_density adami2012", 10, {"wall_density": '"adami2012"'}),
    ("wall_density adami2012, c0 x 2", 20, {"wall_density": '"adami2012"'}),
    ("wall_density adami2012, artificial_viscosity 0", 10,
     {"wall_density": '"adami2012"', "artificial_viscosity": "0.0"}),
    ("wall_density adami2012, artificial_viscosity 0, c0 x 2", 20,
     {"wall_density": '"adami2012"', "artificial_viscosity": "0.0"}),
    ("wall_density n0 (the default until 2026-12-04)", 10, {"wall_density": '"n0"'}),
    ("wall_density n0, c0 x 2", 20, {"wall_density": '"n0"'}),
    ("density_rate summed (the default until 2026-12-04, later)", 10,
     {"density_rate": '"summed"'}),
    ("gradient_renormalisation khayyer2011-deviatoric", 10,
     {"gradient_renormalisation": '"khayyer2011-deviatoric"'}),
    ("gradient_renormalisation khayyer2011-deviatoric, c0 x 2", 20,
     {"gradient_renormalisation": '"khayyer2011-deviatoric"'}),
    ("gradient_renormalisation khayyer2011-strain", 10,
     STRAIN),
    ("artificial_viscosity_walls free-slip", 10, FREE_SLIP),
    ("khayyer2011-strain, artificial_viscosity_walls free-slip", 10,
     {**STRAIN, **FREE_SLIP}),
    ("artificial_viscosity_walls free-slip, wall_friction spalding1961", 10,
     {**FREE_SLIP, **WALL_FRICTION}),
    ("defaults before session 13 (gradient_renormalisation none)", 10, PLAIN),
    ("defaults before session 15 (particle_collision none)", 10, NO_COLLISION),
]


def case_text(factor, physics, end):
    text = CASE.read_text()
    keys = "".join(f"{k} = {v}\n" for k, v in physics.items())
    text = re.sub(r"(?m)^sound_speed_factor = .*$", f"sound_speed_factor = {factor:.1f}\n" + keys,
                  text)
    text = re.sub(r"(?m)^end = .*$", f"end = {end}", text)
    return re.sub(r"(?m)^interval = .*$",
                  'interval = 0.01\nfields = ["pressure"]\nparticles = ["fluid"]', text)


def breathing(run):
    """The time, the mean of p - rho g (H - y) over the deep water, and the mean y of all the
    fluid particles (their centre of mass) of each frame."""
    ts, ms, cs = [], [], []
    for f in sorted(glob.glob(str(run / "frame_*.vtp"))):
        r = vtkXMLPolyDataReader()
        r.SetFileName(f)
        r.Update()
        pd = r.GetOutput()
        y = vtk_to_numpy(pd.GetPoints().GetData())[:, 1]
        p = vtk_to_numpy(pd.GetPointData().GetArray("pressure"))
        deep = y < H - 0.1
        ts.append(pd.GetFieldData().GetArray("TimeValue").GetValue(0))
        ms.append(float(np.mean(p[deep] - RHO * G * (H - y[deep]))))
        cs.append(float(np.mean(y)))
    return np.array(ts), np.array(ms), np.array(cs)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--wcmps", default=str(ROOT / "build" / "bin" / "wcmps"))
    ap.add_argument("--out", default="runs/acoustic-mode")
    ap.add_argument("--end", type=float, default=4.0)
    ap.add_argument("--variants", default=",".join(str(k) for k in range(len(VARIANTS))))
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--reuse", action="store_true", help="analyse earlier runs in --out")
    args = ap.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    wanted = [int(k) for k in args.variants.split(",")]

    def run(k):
        label, factor, physics = VARIANTS[k]
        d = out / f"variant{k}"
        if not args.reuse:
            case = out / f"variant{k}.toml"
            case.write_text(case_text(factor, physics, args.end))
            r = subprocess.run([args.wcmps, "run", str(case), "-o", str(d), "--overwrite",
                                "--threads", "1"], capture_output=True, text=True)
            if r.returncode != 0:
                return f"| {label} | run failed: {r.stderr.strip()[-200:]} | | | |"
        ts, ms, cs = breathing(d)
        windows = np.arange(0.0, ts.max() - 1e-9, 0.5)
        amp = [np.max(np.abs(ms[(ts >= a) & (ts < a + 0.5)])) for a in windows]
        late = ts >= 1.0
        x = ms[late] - ms[late].mean()
        freq = np.fft.rfftfreq(len(x), np.median(np.diff(ts)))
        f_peak = freq[1 + np.argmax(np.abs(np.fft.rfft(x))[1:])]
        return (f"| {label} | " + " ".join(f"{a:.0f}" for a in amp) +
                f" | {f_peak:.1f} | {amp[-1] / amp[1]:.2f} | {1000 * (cs[-1] - cs[0]):+.2f} |")

    print("| variant | largest abs. mean of p - rho g (H - y), Pa, per 0.5 s from 0 to "
          f"{args.end:g} s | frequency (Hz) | last / 0.5-1 s | centre of mass, last - first (mm) |")
    print("|---|---|---|---|---|")
    failed = 0
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as ex:
        for line in ex.map(run, wanted):
            print(line, flush=True)
            failed += "run failed" in line
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
