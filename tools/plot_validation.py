#!/usr/bin/python3
"""Draws the figures of docs/validation.md from the CSV files the validation tests write.

    tools/plot_validation.py [BUILD_TESTS_DIR] [-o docs/figures]

BUILD_TESTS_DIR defaults to build/tests (where ctest runs the validation tests).
"""
import argparse, csv, glob, os, re
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt

HERE = os.path.dirname(os.path.abspath(__file__))
SHIFT = 0.15  # tests/validation/test_dambreak.cpp, kShift


def read(path):
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith('#'))]
    if len(rows) < 2:
        return None  # a run still writing it
    head, body = rows[0], rows[1:]
    return {h: [float(r[k]) for r in body] for k, h in enumerate(head)}


def interpolate(xs, ys, x):
    """Linear interpolation of ys(xs) at x (xs increasing); None outside."""
    for k in range(1, len(xs)):
        if xs[k - 1] <= x <= xs[k]:
            w = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
            return ys[k - 1] + w * (ys[k] - ys[k - 1])
    return None


def rms_error(sim, data, shift):
    """rms of Z_sim(T - shift) - Z_exp(T) over the measured points (the test's measure)."""
    errors = [interpolate(sim['T'], sim['Z'], t - shift) for t in data['T']]
    pairs = [(e, z) for e, z in zip(errors, data['Z']) if e is not None]
    return (sum((e - z) ** 2 for e, z in pairs) / len(pairs)) ** 0.5


def dambreak(src, out):
    data = read(os.path.join(HERE, '..', 'cases', 'dambreak', 'martin_moyce_1952.csv'))
    fig, ax = plt.subplots(figsize=(6, 4.2), dpi=110)
    ax.plot(data['T'], data['Z'], 'ko', label='Martin & Moyce (1952)')
    files = sorted(glob.glob(os.path.join(src, 'dambreak_front_dl*mm.csv')),
                   key=lambda p: -float(re.search(r'dl([0-9.]+)mm', p).group(1)))
    for path in files:
        dl = re.search(r'dl([0-9.]+)mm', path).group(1)
        c = read(path)
        if c is None:
            continue
        ax.plot([t + SHIFT for t in c['T']], c['Z'], label='wcmps, DL = %s mm (a/%d)'
                % (dl, round(200 / float(dl))))
        shifts = [k / 100 for k in range(31)]
        best = min(shifts, key=lambda s: rms_error(c, data, s))
        print('dam break DL = %s mm: rms error %.3f at shift %.2f, %.3f without shift, '
              'best shift %.2f (%.3f)' % (dl, rms_error(c, data, SHIFT), SHIFT,
                                          rms_error(c, data, 0.0), best, rms_error(c, data, best)))
    ax.set_xlim(0, 3.6)
    ax.set_ylim(1, 4.5)
    ax.set_xlabel('T = t sqrt(2g/a) (simulation shifted by +%.2f)' % SHIFT)
    ax.set_ylabel('Z = z / a')
    ax.set_title('Dam break: surge front, a = 0.2 m')
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, 'dambreak_front.png'))


def hydrostatic(src, out):
    prof = sorted(glob.glob(os.path.join(src, 'hydrostatic_dl*_profile.csv')))
    if prof:
        c = read(prof[0])
        fig, ax = plt.subplots(figsize=(5, 4.6), dpi=110)
        ax.plot([p / 1000 for p in c['p_Pa']], c['y_m'], '.', ms=2, alpha=0.5,
                label='wcmps, every fluid particle')
        ys = sorted(c['y_m'])
        ax.plot([1000 * 9.81 * (0.7 - y) / 1000 for y in ys], ys, 'k-', lw=1,
                label='rho g (H - y)')
        ax.set_xlabel('pressure (kPa)')
        ax.set_ylabel('y (m)')
        ax.set_title('Still water, H = 0.7 m, DL = %s, t = end'
                     % re.search(r'dl([0-9]+mm)', prof[0]).group(1))
        ax.grid(alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(out, 'hydrostatic_pressure.png'))
    series = sorted(glob.glob(os.path.join(src, 'hydrostatic_dl*_series.csv')))
    if series:
        fig, ax = plt.subplots(figsize=(6, 4.2), dpi=110)
        for path in series:
            dl = re.search(r'dl([0-9]+mm)', path).group(1)
            c = read(path)
            if c is None:
                continue
            ax.semilogy(c['t_s'], c['max_speed_m_s'], label='max, DL = ' + dl)
            ax.semilogy(c['t_s'], c['rms_speed_m_s'], '--', label='rms, DL = ' + dl)
        ax.axhline(0.01 * (9.81 * 0.7) ** 0.5, color='k', lw=0.8, ls=':')
        ax.text(0.1, 0.01 * (9.81 * 0.7) ** 0.5 * 1.15, '0.01 sqrt(gH)')
        ax.set_xlabel('t (s)')
        ax.set_ylabel('spurious speed (m/s)')
        ax.set_title('Still water: speed of the particles')
        ax.grid(alpha=0.3, which='both')
        ax.legend()
        fig.tight_layout()
        fig.savefig(os.path.join(out, 'hydrostatic_speed.png'))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('src', nargs='?', default=os.path.join(HERE, '..', 'build', 'tests'))
    ap.add_argument('-o', '--out', default=os.path.join(HERE, '..', 'docs', 'figures'))
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    dambreak(args.src, args.out)
    hydrostatic(args.src, args.out)


if __name__ == '__main__':
    main()
