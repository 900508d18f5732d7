#!/usr/bin/python3
"""The motion of water that should be at rest: per frame of a run, the fluid particles' rms and
largest speed in bands of x, and the rms speed split into the means of square cells (a flow)
and what is left about them (particle noise). docs/validation.md, "The water at t = 0: what
settling leaves", reads still tanks and case I with its block held with it.

usage: tools/water_motion.py RUN_DIR [--bands 0,0.4,1.2,2.2] [--cell 0.05] [--every 1]
                             [--map T --map-cell 0.1]

--map T prints instead the mean velocity (mm/s, u,v) of the cells of --map-cell m in the frame
nearest to time T, top row first: where the water moves.
"""
import argparse
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader


def frames(run):
    """The series' frames in time order, from series.pvd."""
    pvd = Path(run) / "series.pvd"
    if not pvd.is_file():
        sys.exit(f"{pvd}: no series (is {run} a run directory?)")
    items = [(float(d.get("timestep")), Path(run) / d.get("file"))
             for d in ET.parse(pvd).getroot().iter("DataSet")]
    return sorted(items)


def read_fluid(path):
    """Positions and velocities of the frame's fluid particles."""
    r = vtkXMLPolyDataReader()
    r.SetFileName(str(path))
    r.Update()
    pd = r.GetOutput()
    kind = pd.GetPointData().GetArray("kind")
    vel = pd.GetPointData().GetArray("velocity")
    if kind is None or vel is None:
        sys.exit(f"{path}: the frame has no kind or velocity field")
    fluid = vtk_to_numpy(kind) == 0
    return vtk_to_numpy(pd.GetPoints().GetData())[fluid][:, :2], vtk_to_numpy(vel)[fluid][:, :2]


def print_map(args):
    t, path = min(frames(args.run), key=lambda f: abs(f[0] - args.map))
    xy, u = read_fluid(path)
    c = args.map_cell
    print(f"t = {t:g} s: mean u,v (mm/s) of {c:g} m cells; columns from x = "
          f"{np.floor(xy[:, 0].min() / c) * c:g} m, rows from the top")
    for y0 in np.arange(np.floor(xy[:, 1].max() / c) * c, xy[:, 1].min() - c, -c):
        row = f"y {y0:+.2f} "
        for x0 in np.arange(np.floor(xy[:, 0].min() / c) * c, xy[:, 0].max(), c):
            m = (xy[:, 0] >= x0) & (xy[:, 0] < x0 + c) & (xy[:, 1] >= y0) & (xy[:, 1] < y0 + c)
            row += (f" {u[m, 0].mean() * 1e3:+5.1f},{u[m, 1].mean() * 1e3:+5.1f}" if m.sum() >= 5
                    else "       .     ")
        print(row)
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("run")
    ap.add_argument("--bands", default="", help="x edges of the bands (m), e.g. 0,0.4,1.2,2.2; "
                    "default: the whole water")
    ap.add_argument("--cell", type=float, default=0.05, help="cell size of the flow's means (m)")
    ap.add_argument("--every", type=int, default=1, help="read every k-th frame")
    ap.add_argument("--map", type=float, help="print the cells' mean velocity at this time (s)")
    ap.add_argument("--map-cell", type=float, default=0.1, help="the map's cell size (m)")
    args = ap.parse_args()
    if args.map is not None:
        return print_map(args)
    edges = [float(v) for v in args.bands.split(",")] if args.bands else []
    series = frames(args.run)
    print("| t (s) | rms speed (m/s) | of the cells' means | about them |"
          + "".join(f" x {a:g}-{b:g} m: rms (max) |" for a, b in zip(edges, edges[1:])))
    print("|---|---|---|---|" + "---|" * max(0, len(edges) - 1))
    for t, path in series[::args.every]:
        xy, u = read_fluid(path)
        cells = np.floor(xy / args.cell).astype(np.int64)
        _, inv, count = np.unique(cells[:, 0] * 1_000_003 + cells[:, 1], return_inverse=True,
                                  return_counts=True)
        mean = np.zeros((len(count), 2))
        np.add.at(mean, inv, u)
        mean = (mean / count[:, None])[inv]
        rms = lambda v: float(np.sqrt((v ** 2).sum(axis=1).mean())) if len(v) else float("nan")
        row = f"| {t:.2f} | {rms(u):.4f} | {rms(mean):.4f} | {rms(u - mean):.4f} |"
        speed = np.hypot(u[:, 0], u[:, 1])
        for a, b in zip(edges, edges[1:]):
            m = (xy[:, 0] >= a) & (xy[:, 0] < b)
            row += (f" {rms(u[m]):.4f} ({speed[m].max():.4f}) |" if m.any() else " – |")
        print(row)
    return 0


if __name__ == "__main__":
    sys.exit(main())
