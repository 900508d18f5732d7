#!/usr/bin/env python3
"""Figures and tables of the sliding-block cases for docs/validation.md.

    /usr/bin/python3 tools/plot_block_cases.py --case I RUN_I_PRESCRIBED RUN_I_FREE \
        --case II RUN_II_PRESCRIBED RUN_II_FREE -o docs/figures

Reads each run directory's block.csv and frames (series.pvd) and writes
  block_motion.png          S(t) and U(t) of every run against the study's measured table
  block_surface_case<N>.png water surface at 0.1, 0.2, 0.3, 0.4 s with the block's outline
and prints the error table (markdown) of S and U at the table's times.

The study's U column is the mean speed over the preceding 0.1 s (U_k = (S_k - S_k-1) / 0.1
to its three digits), so U is compared as that mean; the instantaneous U(t) is plotted too.
"""
import argparse
import os
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader  # noqa: E402

# The study's measured motion (../shared/spec/cases.md; thesis Table 3-1).
TABLE = {
    "I": {"t": [0.0, 0.1, 0.2, 0.3, 0.4], "S": [0.0, 0.018, 0.058, 0.121, 0.190],
          "U": [0.0, 0.181, 0.399, 0.630, 0.693]},
    "II": {"t": [0.0, 0.1, 0.2, 0.3, 0.4], "S": [0.0, 0.024, 0.073, 0.140, 0.216],
           "U": [0.0, 0.236, 0.499, 0.663, 0.763]},
}


def read_block(run):
    d = np.genfromtxt(os.path.join(run, "block.csv"), delimiter=",", names=True)
    return d


def motion_label(run):
    with open(os.path.join(run, "case.toml")) as f:
        text = f.read()
    section = text[text.find("[block.motion]"):]
    for line in section.splitlines():
        if line.strip().startswith("type"):
            kind = line.split("=")[1].split("#")[0].strip().strip('"')
            if kind == "free":
                for l2 in section.splitlines():
                    if l2.strip().startswith("friction"):
                        return "free, mu = " + l2.split("=")[1].split("#")[0].strip()
            return kind
    return "?"


def frames(run):
    root = ET.parse(os.path.join(run, "series.pvd")).getroot()
    return [(float(e.get("timestep")), os.path.join(run, e.get("file")))
            for e in root.iter("DataSet")]


def read_frame(path):
    r = vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    d = r.GetOutput()
    x = vtk_to_numpy(d.GetPoints().GetData())[:, :2]
    kind = vtk_to_numpy(d.GetPointData().GetArray("kind"))
    outline = vtk_to_numpy(d.GetFieldData().GetArray("BlockOutline"))[:, :2]
    return x[kind == 0], outline


def surface_line(fluid, dl, x0, x1):
    """Highest fluid particle per DL-wide column, ignoring splash: a column's top counts only if
    it has another fluid particle within 1.5 DL below it."""
    xs, ys = [], []
    for c in np.arange(x0, x1, dl):
        m = (fluid[:, 0] >= c) & (fluid[:, 0] < c + dl)
        if not m.any():
            continue
        y = np.sort(fluid[m, 1])[::-1]
        top = y[0]
        for k in range(len(y) - 1):
            if y[k] - y[k + 1] < 1.5 * dl:
                top = y[k]
                break
        xs.append(c + 0.5 * dl)
        ys.append(top + 0.5 * dl)
    return np.array(xs), np.array(ys)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--case", nargs="+", action="append", required=True,
                    metavar=("NAME", "RUN"), help="I or II, then its run directories")
    ap.add_argument("-o", "--output", default="docs/figures")
    a = ap.parse_args()
    os.makedirs(a.output, exist_ok=True)

    fig, ax = plt.subplots(2, len(a.case), figsize=(5.5 * len(a.case), 7), squeeze=False)
    print("| case | run | t (s) | S measured (m) | S (m) | error (mm) | mean U measured (m/s) "
          "| mean U (m/s) | error (m/s) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for col, (name, *runs) in enumerate(a.case):
        tab = TABLE[name]
        ax[0, col].plot(tab["t"], tab["S"], "ko", label="measured (study)")
        ax[1, col].plot(tab["t"][1:], tab["U"][1:], "ks",
                        label="measured: mean over the preceding 0.1 s")
        for run in runs:
            d = read_block(run)
            label = motion_label(run)
            line, = ax[0, col].plot(d["time_s"], d["S_m"], label=label)
            ax[1, col].plot(d["time_s"], d["U_m_s"], color=line.get_color(), label=label)
            s_at = np.interp(tab["t"], d["time_s"], d["S_m"])
            u_mean = np.diff(s_at) / np.diff(tab["t"])
            ax[1, col].plot(tab["t"][1:], u_mean, "s", mfc="none", color=line.get_color())
            for k in range(1, len(tab["t"])):
                print(f"| {name} | {label} | {tab['t'][k]:.1f} | {tab['S'][k]:.3f} | "
                      f"{s_at[k]:.4f} | {1000 * (s_at[k] - tab['S'][k]):+.1f} | "
                      f"{tab['U'][k]:.3f} | {u_mean[k - 1]:.3f} | "
                      f"{u_mean[k - 1] - tab['U'][k]:+.3f} |")
        ax[0, col].set_title(f"case {name}")
        ax[0, col].set_ylabel("S (m)")
        ax[1, col].set_ylabel("U (m/s)")
        ax[1, col].set_xlabel("t (s)")
        for r in (0, 1):
            ax[r, col].grid(alpha=0.3)
            ax[r, col].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(a.output, "block_motion.png"), dpi=90)

    # Water surface of each case's first run at the study's times.
    for name, *runs in a.case:
        run = runs[0]
        fr = [(t, f) for t, f in frames(run) if any(abs(t - s) < 1e-6 for s in (0.1, 0.2, 0.3, 0.4))]
        dl = float(open(os.path.join(run, "case.toml")).read().split("spacing =")[1].split()[0])
        fig, axs = plt.subplots(len(fr), 1, figsize=(8, 2.0 * len(fr)), sharex=True)
        for axi, (t, f) in zip(np.atleast_1d(axs), fr):
            fluid, outline = read_frame(f)
            xs, ys = surface_line(fluid, dl, -0.1, 0.8)
            axi.plot(xs, ys * 100, "b-", lw=1)
            poly = np.vstack([outline, outline[:1]])
            axi.fill(poly[:, 0], poly[:, 1] * 100, color="0.5")
            axi.set_ylim(-10, 3)
            axi.set_ylabel("y (cm)")
            axi.text(0.01, 0.85, f"t = {t:.1f} s", transform=axi.transAxes)
            axi.grid(alpha=0.3)
        np.atleast_1d(axs)[-1].set_xlabel("x (m) from the shoreline")
        np.atleast_1d(axs)[0].set_title(f"case {name}: water surface ({motion_label(run)})")
        fig.tight_layout()
        fig.savefig(os.path.join(a.output, f"block_surface_case{name}.png"), dpi=90)


if __name__ == "__main__":
    main()
