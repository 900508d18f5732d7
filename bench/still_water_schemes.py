#!/usr/bin/python3
"""Still water (cases/hydrostatic, DL = 10 mm) with the study's scheme and with each change of
the defaults added in turn: whether the run survives, and the rms / max particle speed at
given times. Prints the Markdown table of docs/method.md.

    bench/still_water_schemes.py [--wcmps build/bin/wcmps] [--end 4] [--out /tmp/wcmps-schemes]

Runs the variants two at a time, one thread each; results do not depend on the thread count.
"""
import argparse, concurrent.futures, glob, json, math, os, re, subprocess, sys
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, '..', 'cases', 'hydrostatic', 'case.toml')

from physics_options import NO_COLLISION, OLD  # bench/, beside the script; OLD: 3a85288

# (label, extra [physics] keys, [particles] initial_state)
NO_WALL_COLLISION = {'wall_collision': '"none"'}
VARIANTS = [
    ('study: Eq. 2.19, EOS walls, lattice start, alpha = 0',
     {'pressure_gradient': '"koshizuka1998-min"', 'wall_pressure': '"eos"',
      'artificial_viscosity': '0.0', **NO_WALL_COLLISION, **OLD}, 'lattice'),
    ('+ walls extrapolated from the fluid',
     {'pressure_gradient': '"koshizuka1998-min"', 'artificial_viscosity': '0.0',
      **NO_WALL_COLLISION, **OLD}, 'lattice'),
    ('+ hydrostatic start',
     {'pressure_gradient': '"koshizuka1998-min"', 'artificial_viscosity': '0.0',
      **NO_WALL_COLLISION, **OLD}, 'hydrostatic'),
    ('+ artificial viscosity 0.02',
     {'pressure_gradient': '"koshizuka1998-min"', **NO_WALL_COLLISION, **OLD}, 'hydrostatic'),
    ('+ variational gradient', dict(NO_WALL_COLLISION, **OLD), 'hydrostatic'),
    ('+ wall collisions (the defaults of 3a85288)', dict(OLD), 'hydrostatic'),
    ('+ continuity number density with diffusion',
     dict(OLD, number_density='"continuity"'), 'hydrostatic'),
    ('+ free surface by scan (Marrone 2010)',
     dict(OLD, number_density='"continuity"', free_surface='"marrone2010"'), 'hydrostatic'),
    ('+ negative pressure, tensile switch',
     {'shifting': '"none"', **NO_COLLISION}, 'hydrostatic'),
    ('+ particle shifting (the defaults before 2026-12-08)', dict(NO_COLLISION), 'hydrostatic'),
    ('defaults before 2026-12-08 without artificial viscosity',
     {'artificial_viscosity': '0.0', **NO_COLLISION}, 'hydrostatic'),
    ('+ particle collision (the defaults)', {}, 'hydrostatic'),
    ('defaults without artificial viscosity', {'artificial_viscosity': '0.0'}, 'hydrostatic'),
]


def variant_text(physics, initial_state, end):
    text = open(CASE).read()
    text = re.sub(r'(?m)^end = .*$', 'end = %g' % end, text)
    text = re.sub(r'(?m)^interval = .*$', 'interval = 0.5', text)
    text = text.replace('[particles]\n', '[particles]\ninitial_state = "%s"\n' % initial_state)
    keys = ''.join('%s = %s\n' % kv for kv in physics.items())
    return text.replace('[physics]\n', '[physics]\n' + keys)


def speeds(path):
    r = vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    pd = r.GetOutput()
    kind = vtk_to_numpy(pd.GetPointData().GetArray('kind'))
    v = vtk_to_numpy(pd.GetPointData().GetArray('velocity'))[kind == 0]
    s = (v[:, 0] ** 2 + v[:, 1] ** 2) ** 0.5
    t = pd.GetFieldData().GetArray('TimeValue').GetValue(0)
    # the pressure against rho g (H - y), H = 0.7 m, over the water deeper than 3 DL (the top
    # rows are at p = 0 by construction), in % of rho g H
    y = vtk_to_numpy(pd.GetPoints().GetData())[kind == 0][:, 1]
    p = vtk_to_numpy(pd.GetPointData().GetArray('pressure'))[kind == 0]
    deep = y < 0.7 - 0.03
    e = (p[deep] - 1000.0 * 9.81 * (0.7 - y[deep])) / (1000.0 * 9.81 * 0.7)
    return t, math.sqrt((s ** 2).mean()), s.max(), 100.0 * math.sqrt((e ** 2).mean())


def run(args, k):
    label, physics, initial = VARIANTS[k]
    d = os.path.join(args.out, 'v%d' % k)
    os.makedirs(d, exist_ok=True)
    case = os.path.join(d, 'case.toml')
    with open(case, 'w') as f:
        f.write(variant_text(physics, initial, args.end))
    p = subprocess.run([args.wcmps, 'run', case, '-o', os.path.join(d, 'run'), '--overwrite',
                        '--threads', '1'], capture_output=True, text=True)
    summary = json.load(open(os.path.join(d, 'run', 'run.json')))
    frames = {round(t, 6): (rms, mx, pe) for t, rms, mx, pe in
              map(speeds, sorted(glob.glob(os.path.join(d, 'run', 'frame_*.vtp'))))}
    return label, p.returncode, summary, frames


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--wcmps', default=os.path.join(HERE, '..', 'build', 'bin', 'wcmps'))
    ap.add_argument('--end', type=float, default=4.0)
    ap.add_argument('--out', default='/tmp/wcmps-schemes')
    args = ap.parse_args()
    times = [t for t in (0.5, 1.0, 2.0, 4.0, 8.0) if t <= args.end + 1e-9]
    with concurrent.futures.ThreadPoolExecutor(2) as pool:
        results = list(pool.map(lambda k: run(args, k), range(len(VARIANTS))))
    print('| scheme | outcome | ' + ' | '.join('rms / max speed at %g s (m/s)' % t for t in times) +
          ' | p rms error at %g s (%% of rho g H) |' % times[-1])
    print('|---|---|' + '---|' * (len(times) + 1))
    for label, code, summary, frames in results:
        if code == 0:
            outcome = 'ran to %g s' % summary['time']['simulated']
        else:
            inst = summary.get('instability', {})
            outcome = 'stopped at %.2f s: %s' % (inst.get('time', float('nan')), inst.get('reason', '?'))
        cells = []
        for t in times:
            v = frames.get(round(t, 6))
            cells.append('%.4f / %.3f' % v[:2] if v else '-')
        v = frames.get(round(times[-1], 6))
        cells.append('%.2f' % v[2] if v else '-')
        print('| %s | %s | %s |' % (label, outcome, ' | '.join(cells)))


if __name__ == '__main__':
    sys.exit(main())
