"""Checks the CSV products of `wcmps post` on the short case I run (tests/cli/CMakeLists.txt):
every requested time has every section with its samples from the bed (Y = 0) to the surface
(Y = 1), the section averages over X/L = 0 ... 3.5, the free surface across the tank near the
still-water line, the line C-A, and the cavity at every frame of the series (none: the water
is whole at these early times).

usage: check_post.py POST_DIR TIME [TIME ...]
"""
import csv
import math
import statistics
import sys


def rows(post, name):
    with open(f"{post}/{name}", newline="") as f:
        return list(csv.DictReader(f))


def by_time(table, t):
    return [r for r in table if math.isclose(float(r["time [s]"]), t, abs_tol=1e-9)]


def main():
    post, times = sys.argv[1], [float(t) for t in sys.argv[2:]]
    sections = rows(post, "sections.csv")
    summary = rows(post, "section_summary.csv")
    averages = rows(post, "section_averages.csv")
    surface = rows(post, "free_surface.csv")
    lines = rows(post, "lines.csv")
    cavity = rows(post, "cavity.csv")
    errors = []
    # Every frame of the run (0, 0.02, 0.04, 0.05 s), whatever --times asks for, and no cavity:
    # at t <= 0.05 s the water has not begun to leave the block (measured 0 at every frame).
    frames = [float(r["time [s]"]) for r in cavity]
    if frames != [0.0, 0.02, 0.04, 0.05]:
        errors.append(f"cavity at times {frames}, expected every frame 0 ... 0.05 s")
    if any(float(r["area [m^2]"]) != 0.0 for r in cavity):
        errors.append("cavity: " + ", ".join(f"{r['area [m^2]']} m^2 at {r['time [s]']} s" for r in cavity))
    for t in times:
        names = [r["section"] for r in by_time(summary, t)]
        if names != list("ABCDEFG"):
            errors.append(f"t = {t}: sections {names}, expected A ... G")
        for row in by_time(summary, t):
            s = row["section"]
            prof = [r for r in by_time(sections, t) if r["section"] == s]
            if float(row["H [m]"]) == 0.0:
                # E sits 0.02 m upslope of C, under a film thinner than DL: it may be dry.
                if s != "E" or prof:
                    errors.append(f"t = {t}, section {s}: dry")
                continue
            y = [float(r["Y [-]"]) for r in prof]
            h = [float(r["h [m]"]) for r in prof]
            if len(prof) != 51 or y[0] != 0.0 or y[-1] != 1.0 or sorted(h) != h:
                errors.append(f"t = {t}, section {s}: {len(prof)} samples, Y {y[:1]} ... {y[-1:]}")
            if any(math.isnan(float(r["u_along [m/s]"])) for r in prof):
                errors.append(f"t = {t}, section {s}: NaN velocity")
        av = by_time(averages, t)
        xl = [float(r["X/L [-]"]) for r in av]
        if len(av) != 36 or xl[0] != 0.0 or not math.isclose(xl[-1], 3.5):
            errors.append(f"t = {t}: {len(av)} section averages over X/L {xl[:1]} ... {xl[-1:]}")
        eta = [float(r["eta [m]"]) for r in by_time(surface, t)]
        # The tank is 2.19 m long at DL = 5 mm; the water is nearly still at t <= 0.05 s, its
        # surface a few mm under y = 0 (the hydrostatic start compresses the column).
        if len(eta) < 400 or abs(statistics.median(eta)) > 0.01:
            errors.append(f"t = {t}: {len(eta)} surface stations, median eta "
                          f"{statistics.median(eta) if eta else None}")
        ca = [r for r in by_time(lines, t) if r["line"] == "C-A"]
        if len(ca) != 101 or not math.isclose(float(ca[-1]["arc_fraction [-]"]), 1.0):
            errors.append(f"t = {t}: line C-A has {len(ca)} samples")
    for e in errors:
        print(e)
    print("ok" if not errors else f"{len(errors)} problems")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
