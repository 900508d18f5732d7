"""Checks a profile plot of section_plots.py by its pixels: the requested size, a white
chart with both velocity curves drawn in the plot area (the blue of u_along and the orange of
u_normal, the colours section_plots.py gives them), not a blank or single-curve image.

usage: pvpython check_profile_plot.py PNG WIDTH HEIGHT
"""
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

png, width, height = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
reader = vtkPNGReader()
reader.SetFileName(png)
reader.Update()
image = reader.GetOutput()
w, h, _ = image.GetDimensions()
rgb = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)
problems = []
if (w, h) != (width, height):
    problems.append(f"size {w}x{h}, expected {width}x{height}")


def near(colour, tol=40):
    """Pixels within tol (of 255, per channel: antialiasing blends the lines) of colour."""
    return int((np.abs(rgb - np.array(colour)).max(axis=1) <= tol).sum())


white = near([255, 255, 255], 5)
blue = near([31, 89, 191])      # 0.12 0.35 0.75
orange = near([217, 84, 26])    # 0.85 0.33 0.10
if white < 0.5 * w * h:
    problems.append(f"only {white} white pixels: not a chart on white")
for name, n in (("u_along (blue)", blue), ("u_normal (orange)", orange)):
    # A curve across the plot is at least a few hundred pixels (one per row it spans).
    if n < 200:
        problems.append(f"{name}: {n} pixels, no curve")
if problems:
    print("\n".join(problems))
    sys.exit(1)
print(f"ok: {w}x{h}, {blue} blue and {orange} orange pixels")
