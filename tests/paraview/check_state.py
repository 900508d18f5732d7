"""Loads the state that open_run.py saved (with the plugin loaded first, as the GUI does from
PV_PLUGIN_PATH) and checks what it holds: the series with its times, the plugin's speed
filter, the fluid, walls, block and time annotation shown, and a render with the speed
colours.

usage: pvpython check_state.py PLUGIN STATE.pvsm NUMBER_OF_TIMES

The checks run inside main(): the Programmable Filter runs its script in this process and
leaves numpy's names (block, max, ...) in __main__'s namespace.
"""
import sys

from paraview import simple



def main():
    plugin, state, n_times = sys.argv[1], sys.argv[2], int(sys.argv[3])
    simple.LoadPlugin(plugin, remote=False, ns=dict(vars(simple)))
    simple.LoadState(state)
    problems = []
    reader = simple.FindSource("series.pvd")
    if reader is None or len(reader.TimestepValues) != n_times:
        problems.append(f"series: {None if reader is None else len(reader.TimestepValues)} times, "
                        f"expected {n_times}")
    speed = simple.FindSource("speed and vorticity")
    if speed is None or speed.GetXMLName() != "MPSSpeedVorticity":
        problems.append("no MPSSpeedVorticity filter named 'speed and vorticity'")
    view = simple.GetActiveViewOrCreate("RenderView")
    for name in ("fluid", "walls", "block", "time"):
        src = simple.FindSource(name)
        if src is None:
            problems.append(f"no source '{name}'")
        elif not simple.GetDisplayProperties(src, view).Visibility:
            problems.append(f"'{name}' is not shown")
    fluid = simple.FindSource("fluid")
    if fluid is not None:
        rep = simple.GetDisplayProperties(fluid, view)
        if list(rep.ColorArrayName) != ["POINTS", "speed"]:
            problems.append(f"fluid coloured by {list(rep.ColorArrayName)}, expected speed")
    block = simple.FindSource("block")
    if block is not None:
        block.UpdatePipeline(view.ViewTime)
        if block.GetDataInformation().GetNumberOfPoints() != 3:
            problems.append("the block is not the triangle C, A, G")
    if problems:
        print("\n".join(problems))
        return 1
    print(f"ok: t = {view.ViewTime:g} s")
    return 0


sys.exit(main())
