"""A ready ParaView state for a wcmps run: particles coloured by speed, the block, the time.

    pvpython paraview/open_run.py RUN_DIR [-o STATE.pvsm] [--screenshot PNG]
    paraview --state=RUN_DIR/run.pvsm     (with the plugin on PV_PLUGIN_PATH)

The state reads RUN_DIR/series.pvd and holds:
  - "MPS Speed Vorticity" (the plugin) on the series, then the fluid particles (kind 0)
    drawn as discs that tile the lattice, coloured by the speed U, with a colour bar in m/s whose
    range is the speed range of the last output time;
  - the walls and ghost particles (kind 1, 2) in grey;
  - the block, filled, from each frame's BlockOutline (a Programmable Filter, so it moves
    with the frames);
  - the time as "t = 0.100 s" in the upper left corner;
  - a 2D camera on the water, at the case's last output time (of those the series has;
    else its last frame).
"""
import argparse
import builtins
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import wcmps_paraview as wp  # noqa: E402

# The block polygon from the frame's field data, run by ParaView's Programmable Filter (so
# the saved state needs no file of ours beyond the series and the plugin).
BLOCK_SCRIPT = """
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray
frame = self.GetPolyDataInput()
outline = frame.GetFieldData().GetArray("BlockOutline")
out = self.GetPolyDataOutput()
out.Initialize()  # the filter starts from a copy of the input: keep none of its particles
if outline is not None:
    points = vtkPoints()
    cells = vtkCellArray()
    cells.InsertNextCell(outline.GetNumberOfTuples())
    for i in range(outline.GetNumberOfTuples()):
        cells.InsertCellPoint(points.InsertNextPoint(outline.GetTuple3(i)))
    out.SetPoints(points)
    out.SetPolys(cells)
"""


def parse_args():
    p = argparse.ArgumentParser(
        prog="open_run.py",
        description="Build a ready ParaView state (.pvsm) for a wcmps run: speed-coloured "
        "particles, the block, the time.",
        epilog="Exit codes: 0 done, 2 no run / bad arguments, 3 plugin not found, 4 cannot "
        "write, 5 no X display (use xvfb-run -a). See docs/paraview.md.")
    p.add_argument("run", help="run directory of `wcmps run` (holds series.pvd)")
    p.add_argument("-o", "--output", help="state file to write (default RUN/run.pvsm)")
    p.add_argument("--time", type=float,
                   help="time to show (default: the case's last output time the series "
                   "has, else its last frame)")
    p.add_argument("--screenshot", help="also write the view as this PNG")
    p.add_argument("--size", type=int, nargs=2, default=[1200, 600], metavar=("W", "H"),
                   help="view size in pixels (default 1200 600)")
    p.add_argument("--plugin", help="path of WCMPSFilters.so (default: searched, see "
                   "docs/paraview.md)")
    return p.parse_args()


# ParaView's Programmable Filter runs its script in this process and leaves numpy's
# reductions (max, min, ...) in __main__'s namespace, hence builtins.max below.


def main():
    args = parse_args()
    run = wp.Run(args.run)
    state = Path(args.output) if args.output else run.dir / "run.pvsm"
    if state.suffix != ".pvsm":
        raise wp.ScriptError(f"{state}: a state file must end in .pvsm", wp.EXIT_USAGE)
    wp.require_display()
    plugin, pv = wp.load_plugin(args.plugin)

    reader = pv.PVDReader(registrationName="series.pvd", FileName=str(run.series.resolve()))
    reader.UpdatePipelineInformation()
    if args.time is not None:
        t = run.frames_at(reader.TimestepValues, [args.time])[0]
    else:
        t = run.last_output_frame(reader.TimestepValues)
    reader.UpdatePipeline(t)
    dl = reader.FieldData["DL"].GetRange()[0]

    speed = pv.MPSSpeedVorticity(registrationName="speed and vorticity", Input=reader)
    fluid = pv.Threshold(registrationName="fluid", Input=speed, Scalars=["POINTS", "kind"],
                         LowerThreshold=-0.5, UpperThreshold=0.5, ThresholdMethod="Between")
    walls = pv.Threshold(registrationName="walls", Input=reader, Scalars=["POINTS", "kind"],
                         LowerThreshold=0.5, UpperThreshold=2.5, ThresholdMethod="Between")
    block = pv.ProgrammableFilter(registrationName="block", Input=reader,
                                  OutputDataSetType="vtkPolyData", Script=BLOCK_SCRIPT)
    clock = pv.AnnotateTimeFilter(registrationName="time", Input=reader,
                                  Format="t = {time:.3f} s")

    view = pv.CreateView("RenderView")
    # In a layout, so that the GUI shows the view when it loads the state.
    pv.AssignViewToLayout(view=view, layout=pv.CreateLayout("wcmps"), hint=0)
    view.ViewSize = args.size
    view.ViewTime = t
    view.OrientationAxesVisibility = 0
    view.InteractionMode = "2D"
    view.Background = [1.0, 1.0, 1.0]
    view.UseColorPaletteForBackground = 0
    pv.SetActiveView(view)
    scene = pv.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = t

    def discs(source, colour=None):
        rep = pv.Show(source, view, "GeometryRepresentation")
        rep.SetRepresentationType("Point Gaussian")
        rep.ShaderPreset = "Plain circle"
        # Discs of radius DL / sqrt(2) cover the square lattice of spacing DL without gaps.
        rep.GaussianRadius = 0.71 * dl
        if colour:
            rep.ColorArrayName = ["POINTS", ""]
            rep.AmbientColor = rep.DiffuseColor = colour
        return rep

    discs(walls, [0.55, 0.55, 0.55])
    particles = discs(fluid)
    pv.ColorBy(particles, ("POINTS", "speed"))
    lut = pv.GetColorTransferFunction("speed")
    lut.ApplyPreset("Viridis (matplotlib)", True)
    fluid.UpdatePipeline(t)
    lo, hi = fluid.PointData["speed"].GetRange()
    lut.RescaleTransferFunction(0.0, builtins.max(hi, 1e-6))
    lut.AutomaticRescaleRangeMode = "Never"
    particles.SetScalarBarVisibility(view, True)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = "U [m/s]"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Horizontal"
    bar.Position = [0.62, 0.02]
    bar.ScalarBarLength = 0.3
    bar.RangeLabelFormat = "%.2f"

    solid = pv.Show(block, view, "GeometryRepresentation")
    solid.ColorArrayName = ["POINTS", ""]
    solid.AmbientColor = solid.DiffuseColor = [0.35, 0.22, 0.12]
    label = pv.Show(clock, view, "TextSourceRepresentation")
    label.WindowLocation = "Upper Left Corner"
    label.FontSize = 24
    label.Color = [0.0, 0.0, 0.0]

    # The camera on the water (the tank's walls reach far below and beyond it).
    bounds = fluid.GetDataInformation().GetBounds()
    view.CameraPosition = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 10.0]
    view.CameraFocalPoint = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]), 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelProjection = 1
    pv.ResetCamera(view)
    aspect = args.size[0] / args.size[1]
    view.CameraParallelScale = 0.55 * builtins.max(bounds[3] - bounds[2], (bounds[1] - bounds[0]) / aspect)
    pv.Render(view)

    wp.make_output_dir(state.parent)
    wp.replace_atomically(lambda tmp: pv.SaveState(tmp), state)
    print(f"plugin {plugin}")
    print(f"state {state} (t = {t:g} s)")
    if args.screenshot:
        wp.make_output_dir(Path(args.screenshot).parent)
        wp.replace_atomically(
            lambda tmp: pv.SaveScreenshot(tmp, view, ImageResolution=args.size),
            args.screenshot)
        print(f"screenshot {args.screenshot}")


if __name__ == "__main__":
    wp.run_main("open_run.py", main)
