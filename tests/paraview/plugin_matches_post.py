"""Runs every filter of the WCMPSFilters plugin through pvpython on one frame of a run and
compares its numbers with what `wcmps post` wrote for the same frame (one source of truth:
the plugin wraps the library `wcmps post` links, so they must agree).

usage: pvpython plugin_matches_post.py PLUGIN RUN_DIR POST_DIR TIME

Tolerance: 1e-7 of each quantity's scale (its largest magnitude over the frame). `wcmps post`
prints CSV numbers with 9 significant digits (relative rounding 5e-9), and the section
averages' bed normal comes from the case in `wcmps post` and from the block's face on the bed
in the plugin, equal to about 1e-15 but able to move a section's water edge by a rounding's
worth; anything of the order of a kernel or gradient difference would be 1e-3 or more.
Prints "ok" and the largest differences, or the mismatches and exits 1.
"""
import csv
import math
import sys
import xml.etree.ElementTree as ET

import numpy as np
from paraview import servermanager
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLImageDataReader

TOL = 1e-7

plugin, run, post, t = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
ns = dict(vars(simple))  # (an empty dict would be taken as "none given")
simple.LoadPlugin(plugin, remote=False, ns=ns)
reader = simple.PVDReader(FileName=f"{run}/series.pvd")
reader.UpdatePipelineInformation()
errors, report = [], []


def csv_rows(name, **match):
    with open(f"{post}/{name}", newline="") as f:
        rows = [r for r in csv.DictReader(f) if math.isclose(float(r["time [s]"]), t, abs_tol=1e-9)]
    return [r for r in rows if all(r[k] == v for k, v in match.items())]


def compare(what, ours, theirs):
    """Two equal-length float sequences, NaN where either has none."""
    a, b = np.asarray(ours, dtype=float), np.asarray(theirs, dtype=float)
    if a.shape != b.shape:
        errors.append(f"{what}: {a.shape[0]} values in the plugin, {b.shape[0]} in post")
        return
    if not np.array_equal(np.isnan(a), np.isnan(b)):
        errors.append(f"{what}: NaN at different places")
        return
    ok = ~np.isnan(a)
    if not ok.any():
        return
    scale = max(np.abs(b[ok]).max(), 1e-30)
    diff = np.abs(a[ok] - b[ok]).max() / scale
    report.append(f"{what} {diff:.1e}")
    if diff > TOL:
        errors.append(f"{what}: relative difference {diff:.2e} > {TOL:g}")


def point_array(data, name, comp=0):
    arr = vtk_to_numpy(data.GetPointData().GetArray(name))
    return arr if arr.ndim == 1 else arr[:, comp]


# Speed and vorticity on the grid: the .vti of post against the plugin's grid on the same box.
pvd = ET.parse(f"{post}/grid.pvd").getroot()
files = [d.get("file") for d in pvd.iter("DataSet") if math.isclose(float(d.get("timestep")), t, abs_tol=1e-9)]
vti = vtkXMLImageDataReader()
vti.SetFileName(f"{post}/{files[0]}")
vti.Update()
theirs = vti.GetOutput()
bounds, spacing = theirs.GetBounds(), theirs.GetSpacing()
sv = ns["MPSSpeedVorticity"](Input=reader)
grid = ns["MPSParticlesToGrid"](Input=sv, Spacing=spacing[0], SamplingBounds=list(bounds),
                                ArrayNames=["velocity", "pressure", "speed", "vorticity"])
grid.UpdatePipeline(t)
ours = servermanager.Fetch(grid)
if ours.GetDimensions() != theirs.GetDimensions():
    errors.append(f"grid: dimensions {ours.GetDimensions()} against {theirs.GetDimensions()}")
else:
    for name in ("speed", "vorticity", "pressure", "coverage"):
        compare(f"grid {name}", point_array(ours, name), point_array(theirs, name))

# Sections: profiles (the frame's own sections, as the case lists them) and the summary.
sections = ns["MPSSections"](Input=reader, NumberOfSamples=51)
sections.UpdatePipeline(t)
profiles = servermanager.Fetch(sections, idx=0)
summary = servermanager.Fetch(sections, idx=1)
names = [summary.GetValueByName(r, "section").ToString() for r in range(summary.GetNumberOfRows())]
section_index = point_array(profiles, "section")
for k, name in enumerate(names):
    rows = csv_rows("sections.csv", section=name)
    pick = section_index == k
    for col, arr in (("u_along [m/s]", "u_along"), ("u_normal [m/s]", "u_normal"),
                     ("pressure [Pa]", "pressure"), ("Y [-]", "Y")):
        compare(f"section {name} {arr}", point_array(profiles, arr)[pick],
                [float(r[col]) for r in rows])
summ = csv_rows("section_summary.csv")
if [r["section"] for r in summ] != names:
    errors.append(f"sections {names} in the plugin, {[r['section'] for r in summ]} in post")
for col in ("H", "mean_u_along", "mean_u_normal", "mean_pressure"):
    compare(f"summary {col}", [summary.GetValueByName(r, col).ToDouble() for r in range(len(names))],
            [float(r[next(c for c in r if c.startswith(col + " "))]) for r in summ])

# Section averages over the block, X/L = 0 ... 3.5.
averages = ns["MPSSectionAverages"](Input=reader, MaximumXOverL=3.5, NumberOfStations=36)
averages.UpdatePipeline(t)
table = servermanager.Fetch(averages)
rows = csv_rows("section_averages.csv")
for col, key in (("X_over_L", "X/L [-]"), ("H", "H [m]"), ("mean_u_along", "mean_u_along [m/s]"),
                 ("mean_u_normal", "mean_u_normal [m/s]")):
    compare(f"averages {col}", [table.GetValueByName(r, col).ToDouble() for r in range(table.GetNumberOfRows())],
            [float(r[key]) for r in rows])

# Free surface across the water, stations every DL.
surface = ns["MPSFreeSurface"](Input=reader)
surface.UpdatePipeline(t)
s = servermanager.Fetch(surface)
rows = csv_rows("free_surface.csv")
compare("free surface x", point_array(s, "x"), [float(r["x [m]"]) for r in rows])
compare("free surface eta", point_array(s, "eta"), [float(r["eta [m]"]) for r in rows])

# The block's top, C to A.
line = ns["MPSPolylineProbe"](Input=reader)
line.UpdatePipeline(t)
p = servermanager.Fetch(line)
rows = csv_rows("lines.csv", line="C-A")
compare("line C-A pressure", point_array(p, "pressure"), [float(r["pressure [Pa]"]) for r in rows])
compare("line C-A u", point_array(p, "velocity", 0), [float(r["u [m/s]"]) for r in rows])

if errors:
    print("\n".join(errors))
    sys.exit(1)
print("ok: " + ", ".join(report))
