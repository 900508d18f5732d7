"""What the pvpython scripts of paraview/ share: finding and loading the WCMPSFilters plugin,
opening a run (its series.pvd and the case.toml that `wcmps run` copies next to it), picking
the frames of the case's output times, and writing files atomically.

Exit codes of the scripts (docs/paraview.md):
  0  done
  2  bad arguments, no run at the path, or a time the series has no frame for
  3  the plugin was not found or did not load
  4  an output file could not be written
  5  no X display to render with
"""
import os
import sys
import tomllib
import types
from pathlib import Path

EXIT_USAGE = 2
EXIT_PLUGIN = 3
EXIT_IO = 4
EXIT_DISPLAY = 5

PLUGIN = "WCMPSFilters"
# Frames are written at the output times to within a step; a frame within this of a requested
# time is its frame (the smallest time step of the shipped cases is 2.5e-5 s).
TIME_TOLERANCE = 1e-6


class ScriptError(Exception):
    """An error with its exit code; the scripts print its message on one line."""

    def __init__(self, message, code):
        super().__init__(message)
        self.code = code


def run_main(prog, main):
    """Runs main(), turning a ScriptError into 'prog: error: message' and its exit code."""
    try:
        main()
    except ScriptError as e:
        print(f"{prog}: error: {e}", file=sys.stderr)
        sys.exit(e.code)


def plugin_candidates(explicit=None):
    """Where the plugin may be, first found first: --plugin, $WCMPS_PLUGIN, each directory of
    $PV_PLUGIN_PATH, the build tree next to this file, the install tree around it."""
    if explicit:
        yield Path(explicit)
        return
    if os.environ.get("WCMPS_PLUGIN"):
        yield Path(os.environ["WCMPS_PLUGIN"])
    for d in filter(None, os.environ.get("PV_PLUGIN_PATH", "").split(os.pathsep)):
        yield Path(d) / f"{PLUGIN}.so"
        yield Path(d) / PLUGIN / f"{PLUGIN}.so"
    here = Path(__file__).resolve().parent
    # source tree: paraview/ next to build/
    yield here.parent / "build" / "lib" / "paraview-plugins" / PLUGIN / f"{PLUGIN}.so"
    # installed: <prefix>/share/wcmps/paraview next to <prefix>/lib/paraview-plugins
    yield here.parents[2] / "lib" / "paraview-plugins" / PLUGIN / f"{PLUGIN}.so"


def load_plugin(explicit=None):
    """Loads the plugin into pvpython (unless ParaView has already loaded it from
    PV_PLUGIN_PATH). Returns the path and paraview.simple's functions with the plugin's
    filters (MPSSections, MPSParticlesToGrid, ...) as attributes."""
    from paraview import servermanager
    from paraview import simple

    tried = []
    for path in plugin_candidates(explicit):
        tried.append(str(path))
        if path.is_file():
            break
    else:
        raise ScriptError(
            f"plugin {PLUGIN} not found (looked at {', '.join(tried)}); build the project "
            "(tools/bootstrap) or give --plugin PATH", EXIT_PLUGIN)
    namespace = dict(vars(simple))
    if servermanager.ProxyManager().GetPrototypeProxy("filters", "MPSSections") is None:
        try:
            simple.LoadPlugin(str(path), remote=False, ns=namespace)
        except Exception as e:  # ParaView raises a plain RuntimeError
            raise ScriptError(f"{path}: the plugin did not load: {e}", EXIT_PLUGIN)
    else:
        simple._add_functions(namespace)
    if servermanager.ProxyManager().GetPrototypeProxy("filters", "MPSSections") is None:
        raise ScriptError(f"{path}: loaded, but it has no MPSSections filter", EXIT_PLUGIN)
    return path, types.SimpleNamespace(**namespace)


_held_display = None


def require_display():
    """ParaView 5.11 as Debian builds it renders through X only, and a render window with no
    X server kills the process (docs/paraview.md): check before anything renders.

    The connection is kept open until the process ends. An X server started without -noreset
    (as xvfb-run starts it) resets whenever its last client leaves, and a connection attempted
    during a reset fails; VTK's render window makes one attempt and aborts the process if it
    fails. While this connection is open the server cannot reset. The check itself tries 20
    times 0.05 s apart to ride out a reset caused by another client (docs/figures.md, "X server
    resets")."""
    import ctypes
    import ctypes.util
    import time

    global _held_display
    if _held_display is not None:
        return
    name = os.environ.get("DISPLAY")
    lib = ctypes.util.find_library("X11")
    if name and lib:
        x11 = ctypes.CDLL(lib)
        x11.XOpenDisplay.restype = ctypes.c_void_p
        x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
        for _ in range(20):
            display = x11.XOpenDisplay(name.encode())
            if display:
                _held_display = display
                return
            time.sleep(0.05)
    raise ScriptError(
        f"no X display to render with (DISPLAY={name or 'unset'}); run under "
        "`xvfb-run -a pvpython ...` (Debian package xvfb)", EXIT_DISPLAY)


class Run:
    """A run directory of `wcmps run`: its series and what its case file says."""

    def __init__(self, path):
        self.dir = Path(path)
        if not self.dir.is_dir():
            raise ScriptError(f"{path}: no such run directory", EXIT_USAGE)
        self.series = self.dir / "series.pvd"
        if not self.series.is_file():
            raise ScriptError(f"{path}: no series.pvd: not a run of `wcmps run`", EXIT_USAGE)
        self.case = {}
        case_file = self.dir / "case.toml"
        if case_file.is_file():
            try:
                self.case = tomllib.loads(case_file.read_text())
            except tomllib.TOMLDecodeError as e:
                raise ScriptError(f"{case_file}: {e}", EXIT_USAGE)
        self.name = self.case.get("case", {}).get("name", self.dir.name)

    def output_times(self):
        """The case's [output] times (the study's figure times), or None."""
        return self.case.get("output", {}).get("times")

    def frames_at(self, series_times, wanted):
        """The series time of each wanted time (all the case's output times if none given)."""
        if not wanted:
            wanted = self.output_times() or list(series_times)
        picked = []
        for t in wanted:
            near = [s for s in series_times if abs(s - t) <= TIME_TOLERANCE]
            if not near:
                raise ScriptError(f"{self.series} has no frame at t = {t:g} s", EXIT_USAGE)
            picked.append(near[0])
        return picked


    def last_output_frame(self, series_times):
        """The last frame at one of the case's output times, else the last frame."""
        outputs = self.output_times() or []
        at_outputs = [s for s in series_times
                      if any(abs(s - t) <= TIME_TOLERANCE for t in outputs)]
        return (at_outputs or list(series_times))[-1]


def replace_atomically(write, final):
    """Calls write(tmp) for a temporary name in final's directory with final's extension
    (ParaView picks the writer by it), then renames it to final."""
    final = Path(final)
    tmp = final.with_name(f".tmp-{os.getpid()}-{final.name}")
    try:
        write(str(tmp))
        if not tmp.is_file():
            raise ScriptError(f"{final}: ParaView wrote nothing", EXIT_IO)
        os.replace(tmp, final)
    except OSError as e:
        raise ScriptError(f"{final}: cannot write: {e.strerror}", EXIT_IO)
    finally:
        if tmp.exists():
            tmp.unlink()


def make_output_dir(path):
    try:
        Path(path).mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise ScriptError(f"{path}: cannot create the output directory: {e.strerror}", EXIT_IO)
    return Path(path)
