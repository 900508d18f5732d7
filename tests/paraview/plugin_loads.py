"""Loads the WCMPSFilters plugin into pvpython and checks that every filter is there, in the
"wcmps" menu category, and that every property of every filter has its documentation.

usage: pvpython plugin_loads.py PLUGIN
Prints one line per filter ("MPSSections: 5 properties documented") and "ok", or the
problems and exits 1.
"""
import sys

from paraview import servermanager
from paraview import simple

FILTERS = ["MPSSpeedVorticity", "MPSParticlesToGrid", "MPSSections", "MPSSectionAverages",
           "MPSFreeSurface", "MPSPolylineProbe"]

simple.LoadPlugin(sys.argv[1], remote=False, ns=dict(vars(simple)))
pxm = servermanager.ProxyManager()
problems = []
for name in FILTERS:
    proto = pxm.GetPrototypeProxy("filters", name)
    if proto is None:
        problems.append(f"{name}: not in the plugin")
        continue
    hints = proto.GetHints()
    menu = hints.FindNestedElementByName("ShowInMenu") if hints else None
    if menu is None or menu.GetAttribute("category") != "wcmps":
        problems.append(f"{name}: not in the wcmps menu category")
    if not (proto.GetDocumentation() and proto.GetDocumentation().GetDescription()):
        problems.append(f"{name}: no documentation")
    it = proto.NewPropertyIterator()
    count = 0
    it.Begin()
    while not it.IsAtEnd():
        prop = it.GetProperty()
        doc = prop.GetDocumentation()
        if not (doc and doc.GetDescription() and doc.GetDescription().strip()):
            problems.append(f"{name}.{it.GetKey()}: no documentation")
        count += 1
        it.Next()
    print(f"{name}: {count} properties documented")
if problems:
    print("\n".join(problems))
    sys.exit(1)
print("ok")
