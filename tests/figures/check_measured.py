"""Checks that the measured surface points of a case's [figures] are drawn: for each point of
the measured CSV at the figure's time, a black marker (the measured points' colour; nothing
else in the surface figure is black but the bed, far from these points) within 4 pixels of
where x and eta fall in the panel (figures.json gives the panel's plot area and ranges).

usage: check_measured.py FIG_DIR MEASURED_SURFACE_CSV
"""
import csv
import json
import sys
from pathlib import Path

import numpy as np
from matplotlib import image

fig_dir, measured = Path(sys.argv[1]), sys.argv[2]
index = json.loads((fig_dir / "figures.json").read_text())
entry = next(e for e in index["files"] if e["figure"] == "surface")
img = image.imread(str(fig_dir / entry["file"]))[:, :, :3]
panel = entry["panels"][0]
t = entry["times"][0]
x0, y0, w, h = panel["plot_area_px"]
(xa, xb), (ya, yb) = panel["x_range"], panel["y_range"]
found, problems = 0, []
with open(measured, newline="") as f:
    for row in csv.DictReader(f):
        if abs(float(row["time [s]"]) - t) > 1e-4:
            continue
        px = x0 + (float(row["x [m]"]) - xa) / (xb - xa) * w
        py = y0 + (float(row["eta [m]"]) - ya) / (yb - ya) * h
        r, c = img.shape[0] - 1 - int(round(py)), int(round(px))
        patch = img[r - 4:r + 5, c - 4:c + 5]
        if (patch.max(axis=2) < 0.25).any():
            found += 1
        else:
            problems.append(f"no marker near ({px:.0f}, {py:.0f}) for x = {row['x [m]']}")
if problems:
    print("\n".join(problems))
    sys.exit(1)
print(f"ok: {found} measured points drawn")
