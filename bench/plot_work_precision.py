#!/usr/bin/env python3
"""Work-precision plot of bench_work_precision's CSV: error against wall time, log-log, a line
per (time-step rule, pressure gradient, stabilisation) through its particle sizes, a panel per error measure;
and the settings on the best front of each (no other run both faster and more accurate).

usage: plot_work_precision.py RESULTS.csv OUT.png [TITLE]
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    if len(sys.argv) < 3:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["error"] not in ("nan", "")]
    if not rows:
        print(f"plot_work_precision: {sys.argv[1]} has no finished run", file=sys.stderr)
        return 1
    for r in rows:
        r["t"] = float(r["wall_seconds_median"])
        r["e"] = float(r["error"])
        r["dl"] = float(r["dl_m"])
        r["grad"] = r["gradient"] + ("" if r.get("stabilisation", "default") == "default"
                                     else f" ({r['stabilisation']})")
    # A panel per error measure (case I has two: the surface and a section's velocity).
    measures = list(dict.fromkeys(r["error_measure"] for r in rows))
    fig, axes = plt.subplots(1, len(measures), figsize=(7 * len(measures), 5), dpi=110,
                             squeeze=False)
    front = []
    for ax, measure in zip(axes[0], measures):
        mine = [r for r in rows if r["error_measure"] == measure]
        series = sorted({(r["step_rule"], r["grad"]) for r in mine})
        for rule, grad in series:
            pts = sorted((r for r in mine if (r["step_rule"], r["grad"]) == (rule, grad)),
                         key=lambda r: r["t"])
            ax.loglog([p["t"] for p in pts], [p["e"] for p in pts],
                      "o-" if rule == "courant" else "s--", label=f"{grad}, {rule} step")
            for p in pts:
                ax.annotate(f"{p['dl'] * 1000:g}", (p["t"], p["e"]), fontsize=7,
                            textcoords="offset points", xytext=(3, 3))
        ax.set_xlabel("wall time of the run (s, median; labels: DL in mm)")
        ax.set_ylabel(measure)
        ax.set_title(sys.argv[3] if len(sys.argv) > 3 else mine[0]["study"])
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
        front += [r for r in mine
                  if not any(o["t"] <= r["t"] and o["e"] < r["e"]
                             or o["t"] < r["t"] and o["e"] <= r["e"] for o in mine)]
    fig.tight_layout()
    fig.savefig(sys.argv[2])
    print("best front (no run both faster and more accurate):")
    for r in sorted(front, key=lambda r: (r["error_measure"], r["t"])):
        print(f"  {r['error_measure']}: DL {r['dl'] * 1000:g} mm, {r['step_rule']} step, "
              f"{r['grad']}: {r['t']:.3g} s, error {r['e']:.3g}")
    return 0 if all(math.isfinite(r["e"]) for r in front) else 1


if __name__ == "__main__":
    sys.exit(main())
