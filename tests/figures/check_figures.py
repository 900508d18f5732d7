"""Checks what `wcmps figures` rendered, by its pixels (tests/figures/CMakeLists.txt).

usage: check_figures.py FIG_DIR WIDTH HEIGHT BASELINE_DIR [FILE ...]

- figures.json lists every file; each is a PNG of WIDTH x HEIGHT that is not blank;
- in every panel of the speed and vorticity maps, the pixel at the block's centroid (from
  the panel's plot area and ranges in figures.json) has the block's colour, and the colour
  bar runs from the colour map's low end at its bottom to its high end at its top;
- each FILE equals tests/figures/baseline/FILE within the tolerance below.

Image tolerance: at most 0.5 % of the pixels may differ by more than 0.2 (of 1) in a
channel. Two runs and renders here give identical images (0 pixels differ); the margin is for
text and line edges, which Mesa's software rasteriser antialiases and another Mesa build may
round differently. A real change is larger: the speed map of the same run at DL 7 mm instead
of 5 mm differs in 1.7 % of the pixels, a shifted panel or colour range in far more.
Prints "ok ..." or the problems and exits 1.
"""
import json
import sys
from pathlib import Path

import numpy as np
from matplotlib import image

BLOCK = np.array([110, 72, 40]) / 255.0
VIRIDIS_LOW, VIRIDIS_HIGH = np.array([0.267, 0.005, 0.329]), np.array([0.993, 0.906, 0.144])
COOLWARM_LOW, COOLWARM_HIGH = np.array([0.230, 0.299, 0.754]), np.array([0.706, 0.016, 0.150])
COLOUR_TOL = 0.12  # colours are drawn exactly but blended at the edges of a region
PIXEL_DIFF, PIXEL_FRACTION = 0.2, 0.005


def rgb(path):
    img = image.imread(str(path))
    return img[:, :, :3] if img.ndim == 3 else np.dstack([img] * 3)


def at(img, x, y):
    """The colour at pixel (x, y) counted from the bottom left, as figures.json counts."""
    return img[img.shape[0] - 1 - int(round(y)), int(round(x))]


def main():
    fig_dir, width, height, baseline = Path(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), Path(sys.argv[4])
    compare = sys.argv[5:]
    index = json.loads((fig_dir / "figures.json").read_text())
    problems, checked = [], 0
    for entry in index["files"]:
        path = fig_dir / entry["file"]
        if not path.is_file():
            problems.append(f"{entry['file']}: listed but missing")
            continue
        img = rgb(path)
        if img.shape[:2] != (height, width):
            problems.append(f"{entry['file']}: {img.shape[1]}x{img.shape[0]}, expected {width}x{height}")
        ink = float((img.min(axis=2) < 0.9).mean())
        if ink < 0.02:
            problems.append(f"{entry['file']}: blank ({ink:.1%} of pixels not white)")
        if entry["figure"] in ("speed", "vorticity"):
            for p in entry["panels"]:
                x0, y0, w, h = p["plot_area_px"]
                (xa, xb), (ya, yb) = p["x_range"], p["y_range"]
                cx, cy = np.mean(p["block"]["x"]), np.mean(p["block"]["y"])
                px, py = x0 + (cx - xa) / (xb - xa) * w, y0 + (cy - ya) / (yb - ya) * h
                c = at(img, px, py)
                if np.abs(c - BLOCK).max() > COLOUR_TOL:
                    problems.append(f"{entry['file']}, {p['title']}: {np.round(c, 2)} at the block's "
                                    f"centroid ({px:.0f}, {py:.0f}), not the block's colour")
            bx, by, bw, bh = entry["colour_bar"]["area_px"]
            low, high = (VIRIDIS_LOW, VIRIDIS_HIGH) if entry["figure"] == "speed" else (COOLWARM_LOW, COOLWARM_HIGH)
            for name, y, want in (("bottom", by + 3, low), ("top", by + bh - 3, high)):
                c = at(img, bx + bw / 2, y)
                if np.abs(c - want).max() > COLOUR_TOL:
                    problems.append(f"{entry['file']}: colour bar {name} is {np.round(c, 2)}, expected {want}")
        checked += 1
    for name in compare:
        ours, ref = rgb(fig_dir / name), rgb(baseline / name)
        if ours.shape != ref.shape:
            problems.append(f"{name}: {ours.shape} against the baseline's {ref.shape}")
            continue
        differ = float((np.abs(ours - ref).max(axis=2) > PIXEL_DIFF).mean())
        print(f"{name}: {differ:.3%} of pixels differ from the baseline")
        if differ > PIXEL_FRACTION:
            problems.append(f"{name}: {differ:.2%} of pixels differ by more than {PIXEL_DIFF} "
                            f"from {baseline / name} (tolerance {PIXEL_FRACTION:.1%})")
    if problems:
        print("\n".join(problems))
        sys.exit(1)
    print(f"ok: {checked} figures, rendering through {index['rendering']}")


main()
