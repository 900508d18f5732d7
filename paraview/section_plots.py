"""Velocity profiles along a run's measuring sections, through ParaView's own views.

    pvpython paraview/section_plots.py RUN_DIR [-o DIR] [--times T ...] [--sections A,C]

For each of the case's output times (its [output] times, the study's 0.1 ... 0.4 s) the
plugin's "MPS Sections" filter samples every section of the case from the bed (or the
block) to the free surface; then for each section a line chart (ParaView's XY chart view)
shows the along-bed and bed-normal velocity against Y = h/H, written as
section_<name>_t<time>.png, and the samples and the sections' depth averages are written
with ParaView's CSV writer as sections_t<time>.csv and section_summary_t<time>.csv.
A section that meets no water at a time (the trough over the block can draw the surface
below the bed) gets no plot, and the script says so.
"""
import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import wcmps_paraview as wp  # noqa: E402


def parse_args():
    p = argparse.ArgumentParser(
        prog="section_plots.py",
        description="Velocity profiles (PNG, through ParaView's chart view) and CSVs along "
        "each measuring section of a wcmps run, at the case's output times.",
        epilog="Exit codes: 0 done, 2 no run / bad arguments / missing time, 3 plugin not "
        "found, 4 cannot write, 5 no X display (use xvfb-run -a). See docs/paraview.md.")
    p.add_argument("run", help="run directory of `wcmps run` (holds series.pvd)")
    p.add_argument("-o", "--output", help="output directory (default RUN/section_plots)")
    p.add_argument("--times", type=float, nargs="+",
                   help="times in s (default: the case's [output] times)")
    p.add_argument("--sections", help="comma-separated section names (default: all)")
    p.add_argument("--samples", type=int, default=51,
                   help="samples per section, both ends included (default 51)")
    p.add_argument("--size", type=int, nargs=2, default=[640, 480], metavar=("W", "H"),
                   help="image size in pixels (default 640 480)")
    p.add_argument("--plugin", help="path of WCMPSFilters.so (default: searched, see "
                   "docs/paraview.md)")
    return p.parse_args()


def section_table(sections):
    """The summary output (one row per section) as a list of dicts."""
    from paraview import servermanager

    table = servermanager.Fetch(sections, idx=1)
    rows = []
    for r in range(table.GetNumberOfRows()):
        rows.append({table.GetColumnName(c): table.GetValue(r, c).ToString()
                     for c in range(table.GetNumberOfColumns())})
    return rows


def plot_section(simple, profiles, index, t, title, size, png):
    """One chart: u_along and u_normal (horizontal) against Y (vertical) for one section at
    time t."""
    # A line chart plots its series against one x array per representation, and a source
    # has one representation per view: the section is extracted twice, once per component.
    along, normal = (simple.Threshold(Input=profiles, Scalars=["POINTS", "section"],
                                      LowerThreshold=index - 0.5, UpperThreshold=index + 0.5,
                                      ThresholdMethod="Between") for _ in range(2))
    view = simple.CreateView("XYChartView")
    view.ViewSize = size
    view.ViewTime = t
    view.ChartTitle = title
    view.ChartTitleFontSize = 16
    view.LeftAxisTitle = "Y = h/H [-]"
    view.BottomAxisTitle = "velocity [m/s]"
    view.LeftAxisUseCustomRange = 1
    view.LeftAxisRangeMinimum = 0.0
    view.LeftAxisRangeMaximum = 1.0
    view.ShowLegend = 1
    view.LegendLocation = "TopRight"
    for src, x, label, rgb in ((along, "u_along", "along the bed", ["0.12", "0.35", "0.75"]),
                               (normal, "u_normal", "normal to the bed",
                                ["0.85", "0.33", "0.10"])):
        rep = simple.Show(src, view, "XYChartRepresentation")
        rep.AttributeType = "Point Data"
        rep.UseIndexForXAxis = 0
        rep.XArrayName = x
        rep.SeriesVisibility = ["Y"]
        rep.SeriesLabel = ["Y", label]
        rep.SeriesColor = ["Y"] + rgb
        rep.SeriesLineThickness = ["Y", "2"]
        rep.SeriesMarkerStyle = ["Y", "4"]
    simple.Render(view)
    wp.replace_atomically(
        lambda tmp: simple.SaveScreenshot(tmp, view, ImageResolution=size), png)
    simple.Delete(view)
    for p in (normal, along):
        simple.Delete(p)


def main():
    args = parse_args()
    run = wp.Run(args.run)
    if args.samples < 2:
        raise wp.ScriptError("--samples must be at least 2", wp.EXIT_USAGE)
    wp.require_display()
    plugin, simple = wp.load_plugin(args.plugin)
    out = wp.make_output_dir(args.output or run.dir / "section_plots")
    reader = simple.PVDReader(FileName=str(run.series.resolve()))
    reader.UpdatePipelineInformation()
    times = run.frames_at(reader.TimestepValues, args.times)
    sections = simple.MPSSections(Input=reader, NumberOfSamples=args.samples)
    wanted = set(args.sections.split(",")) if args.sections else None
    print(f"plugin {plugin}")
    written = 0
    for t in times:
        sections.UpdatePipeline(t)
        rows = section_table(sections)
        if not rows:
            raise wp.ScriptError(f"{run.series}: the frame at t = {t:g} s has no sections",
                                 wp.EXIT_USAGE)
        names = [r["section"] for r in rows]
        if wanted and not wanted <= set(names):
            missing = ", ".join(sorted(wanted - set(names)))
            raise wp.ScriptError(f"no section {missing} in {run.name} (it has "
                                 f"{', '.join(names)})", wp.EXIT_USAGE)
        stamp = f"t{t:.3f}"
        wp.replace_atomically(lambda tmp: simple.SaveData(
            tmp, proxy=simple.OutputPort(sections, 0), Precision=9,
            FieldAssociation="Point Data"), out / f"sections_{stamp}.csv")
        wp.replace_atomically(lambda tmp: simple.SaveData(
            tmp, proxy=simple.OutputPort(sections, 1), Precision=9,
            FieldAssociation="Row Data"), out / f"section_summary_{stamp}.csv")
        written += 2
        for index, row in enumerate(rows):
            name = row["section"]
            if wanted and name not in wanted:
                continue
            if float(row["H"]) <= 0.0:
                print(f"section {name} at t = {t:g} s: no water there, no plot")
                continue
            png = out / f"section_{name}_{stamp}.png"
            plot_section(simple, simple.OutputPort(sections, 0), index, t,
                         f"{run.name}: section {name}, t = {t:.2f} s", args.size, png)
            written += 1
    print(f"wrote {written} files for {len(times)} times to {out}")


if __name__ == "__main__":
    wp.run_main("section_plots.py", main)
