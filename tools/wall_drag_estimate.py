#!/usr/bin/python3
"""The artificial viscosity's drag at a wall, and the loss it gives the standing wave: an
estimate for docs/validation.md ("The artificial viscosity's drag at the walls: an estimate").

usage: tools/wall_drag_estimate.py [--alpha 0.02] [--c0 22.15] [--dl 0.01] [--re 3.5]
                                   [--length 1.0] [--depth 0.5]

The drag: fluid rows 1, 2, 3, ... DL in front of the wall row (the wall row DL/2 behind the
surface, the fluid's first row DL/2 in front of it, solver/scene/SceneBuilder.h), the wall row
and its ghost rows behind it (k DL < re) at rest, the fluid sliding along the wall at u. Each
fluid particle gets the artificial viscosity's acceleration of physics/Viscosity.h from the wall
particles ahead of it (the approaching pairs; those behind recede and give nothing):

    a_x = -alpha c0 (re / 2) (2 / n0) sum_j u dx_j^2 W(r_j) / ((r_j^2 + 0.01 h^2) r_j^2),

with W = (1 - r/re)^3 (operators/Kernel.h) and n0 of the square lattice. Summed over the rows
(a_x DL each) it is a wall stress rho k u: a linear drag, k in m/s. In DL units every sum is a
number, so k = alpha c0 times a constant of the kernel: it does not depend on DL.

The loss: the first sloshing mode of a tank of length L and depth h, eta = a cos(kx) cos(wt),
k = pi / L, w^2 = g k tanh(kh), its energy rho g a^2 L / 4 (per unit width). With the linear
drag at the bed and at both side walls, against the slip velocities of potential flow,

    bed:  rho k <u_b^2> L,   u_b = a w sin(kx) / sinh(kh),
    side: 2 rho k <w^2> integrated over the depth, w = a w cosh(k (y + h)) / sinh(kh),

and the amplitude decays at gamma = dissipation / (2 E), a share gamma T per period. An
estimate: the wall rows are taken straight and the flow beside them as potential flow (the drag
does not slow the rows it acts on).
"""
import argparse
import math


def kernel(r, re):
    """The study's weight (operators/Kernel.h), (1 - r/re)^3 within re; 0 at r = 0 (no self)."""
    return (1.0 - r / re) ** 3 if 0.0 < r < re else 0.0


def n0_of(re):
    reach = int(math.ceil(re)) + 1
    return sum(kernel(math.hypot(i, j), re)
               for i in range(-reach, reach + 1) for j in range(-reach, reach + 1))


def drag(alpha, c0, dl, re_dl):
    """k (m/s) of the wall stress rho k u."""
    n0 = n0_of(re_dl)
    h = 0.5 * re_dl
    walls = [-k for k in range(0, int(math.ceil(re_dl)))]  # the wall row and the ghost rows
    reach = int(math.ceil(re_dl)) + 1
    total = 0.0
    for yf in range(1, reach + 1):  # the fluid rows, in DL from the wall row
        s = 0.0
        for yw in walls:
            for xw in range(1, reach + 1):  # ahead of the particle: the approaching pairs
                dx, dy = float(xw), float(yw - yf)
                r = math.hypot(dx, dy)
                if r >= re_dl:
                    continue
                s += dx * dx * kernel(r, re_dl) / ((r * r + 0.01 * h * h) * r * r)
        # a_x / u in 1/s: the scale alpha c0 (re / 2) 2 / n0 (re in m) over DL^2 (the sum's unit)
        a_over_u = alpha * c0 * (0.5 * re_dl * dl) * 2.0 / n0 * s / (dl * dl)
        total += a_over_u * dl  # the row's share of the stress per rho u
    return total


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--alpha", type=float, default=0.02)
    ap.add_argument("--c0", type=float, default=10.0 * math.sqrt(9.81 * 0.5),
                    help="sound speed (m/s); the standing wave's is 10 sqrt(g h)")
    ap.add_argument("--dl", type=float, default=0.01)
    ap.add_argument("--re", type=float, default=3.5, help="re / DL")
    ap.add_argument("--length", type=float, default=1.0)
    ap.add_argument("--depth", type=float, default=0.5)
    args = ap.parse_args()
    g = 9.81
    k_drag = drag(args.alpha, args.c0, args.dl, args.re)
    kw = math.pi / args.length
    kh = kw * args.depth
    w = math.sqrt(g * kw * math.tanh(kh))
    period = 2.0 * math.pi / w
    sh2 = math.sinh(kh) ** 2
    # per rho a^2 w^2, time-averaged (the factor 1/2 of cos^2(wt))
    bed = 0.5 * 0.5 * args.length / sh2  # <sin^2(kx)> = 1/2 over the bed
    depth_integral = 0.5 * args.depth + math.sinh(2.0 * kh) / (4.0 * kw)
    side = 2.0 * 0.5 * depth_integral / sh2
    energy = 0.25 * g * args.length  # per rho a^2
    gamma_bed = k_drag * w * w * bed / (2.0 * energy)
    gamma_side = k_drag * w * w * side / (2.0 * energy)
    print(f"n0 = {n0_of(args.re):.4f} (re = {args.re} DL); drag k = {k_drag:.4f} m/s "
          f"(alpha {args.alpha}, c0 {args.c0:.2f} m/s, DL {args.dl} m)")
    print(f"standing wave L = {args.length} m, h = {args.depth} m: T = {period:.4f} s")
    print(f"amplitude lost per period: bed {100 * gamma_bed * period:.2f} %, side walls "
          f"{100 * gamma_side * period:.2f} %, together "
          f"{100 * (1.0 - math.exp(-(gamma_bed + gamma_side) * period)):.2f} %")


if __name__ == "__main__":
    main()
