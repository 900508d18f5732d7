#!/usr/bin/env python3
"""How fast the free-surface particles' number density rises, frame to frame.

    /usr/bin/python3 tools/surface_rise.py RUN [--frames 5-11]

For each frame k of the range and the next one, every fluid particle flagged free surface in
frame k gets the rate (n_{k+1} - n_k) / (n0 (t_{k+1} - t_k)), matched by id. Prints the median,
the 99th percentile and the largest, against sqrt(g / DL), the rate above which the surface
pressure cap counts a particle as struck (solver/physics/SurfacePressureCap.h; g = 9.81). The frames
must hold number_density, free_surface, kind and id (the default frame fields). A frame-to-frame
rate is a mean over the output interval: it shows a slow, steady rise (a draining surface), not
the step-long rise of an impact.
"""
import argparse
import json
import math
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def load(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(str(path))
    reader.Update()
    data = reader.GetOutput().GetPointData()
    fields = {}
    for name in ("number_density", "free_surface", "kind", "id"):
        array = data.GetArray(name)
        if array is None:
            sys.exit(f"{path}: the frame has no '{name}' field")
        fields[name] = vtk_to_numpy(array)
    return fields


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("run", type=Path)
    parser.add_argument("--frames", default=None,
                        help="first-last frame index (default: all but the last)")
    args = parser.parse_args()
    try:
        summary = json.loads((args.run / "run.json").read_text())
        series = ET.parse(args.run / "series.pvd").getroot()
    except (OSError, ValueError, ET.ParseError) as e:
        sys.exit(f"{args.run}: not a finished run directory ({e})")
    n0, dl = summary["method"]["n0"], summary["method"]["DL"]
    frames = [(float(d.get("timestep")), args.run / d.get("file"))
              for d in series.iter("DataSet")]
    first, last = 0, len(frames) - 2
    if args.frames:
        try:
            first, last = (int(v) for v in args.frames.split("-"))
        except ValueError:
            sys.exit(f"--frames {args.frames}: expected FIRST-LAST, e.g. 5-11")
    if not 0 <= first <= last <= len(frames) - 2:
        sys.exit(f"--frames {args.frames}: the run has frames 0 to {len(frames) - 1}")
    threshold = math.sqrt(9.81 / dl)
    print(f"sqrt(g/DL) = {threshold:.1f} per second (n0 = {n0:.6f}, DL = {dl} m)")
    for k in range(first, last + 1):
        (t_a, path_a), (t_b, path_b) = frames[k], frames[k + 1]
        a, b = load(path_a), load(path_b)
        order_a, order_b = np.argsort(a["id"]), np.argsort(b["id"])
        if not np.array_equal(a["id"][order_a], b["id"][order_b]):
            sys.exit(f"frames {k} and {k + 1} do not hold the same particles")
        rate = (b["number_density"][order_b] - a["number_density"][order_a]) / (n0 * (t_b - t_a))
        surface = (a["free_surface"][order_a] == 1) & (a["kind"][order_a] == 0)
        r = rate[surface]
        if r.size == 0:
            print(f"t = {t_a:.3f} s: no surface particles")
            continue
        print(f"t = {t_a:.3f}-{t_b:.3f} s: {r.size} surface particles, rise per second in n0: "
              f"median {np.median(r):+.3f}, 99th percentile {np.percentile(r, 99):+.3f}, "
              f"largest {r.max():+.3f}; above sqrt(g/DL): {(r > threshold).sum()}")


if __name__ == "__main__":
    main()
