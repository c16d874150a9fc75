#!/usr/bin/python3
"""The Lame shell against its closed form: a thick spherical shell (radii a
and b), the pressure p_i in its cavity and p_o outside, an elastic support
of stiffness k (N/m^3) on its outer surface (a traction -k u), linear
elasticity with shear modulus mu and bulk modulus K:

    u(r) = A r + B / r^2,  sigma_rr = 3 K A - 4 mu B / r^3,
    sigma_rr(a) = -p_i,    sigma_rr(b) = -p_o - k u(b).

Reads nodes.csv (positions in mm, displacements in mm), prints the RMS
error of the radial displacement relative to the RMS of the exact one and
the cavity's mean radial displacement over the exact one, and fails (exit
1) if the RMS error is above --tolerance or the cavity ratio outside
--cavity (a range).

usage: check_lame_shell.py NODES.csv --E E --nu NU --p-inner P [--p-outer P]
       [--support K] [--radii A,B] [--tolerance T] [--cavity LO,HI]
       [--label TEXT]"""
import argparse
import csv
import math
import sys


def closed_form(mu, bulk, a, b, p_i, p_o, k):
    """A (1) and B (m^3) of u = A r + B / r^2 (SI)."""
    # 3K A - 4 mu B / a^3 = -p_i;  (3K + k b) A + (k / b^2 - 4 mu / b^3) B = -p_o
    m11, m12, r1 = 3 * bulk, -4 * mu / a**3, -p_i
    m21, m22, r2 = 3 * bulk + k * b, k / b**2 - 4 * mu / b**3, -p_o
    det = m11 * m22 - m12 * m21
    return (r1 * m22 - m12 * r2) / det, (m11 * r2 - r1 * m21) / det


def add_shell_arguments(parser):
    """The shell's options (material, loads, radii, label), shared with
    check_pressure_field.py."""
    parser.add_argument("--E", type=float, required=True)
    parser.add_argument("--nu", type=float, required=True)
    parser.add_argument("--p-inner", type=float, required=True)
    parser.add_argument("--p-outer", type=float, default=0)
    parser.add_argument("--support", type=float, default=0)
    parser.add_argument("--radii", default="10,20")
    parser.add_argument("--label", default="shell")


def shell_solution(args):
    """(a, b, K, A, B) of the shell the options describe (SI)."""
    a, b = (float(x) * 1e-3 for x in args.radii.split(","))
    mu = args.E / (2 * (1 + args.nu))
    bulk = args.E / (3 * (1 - 2 * args.nu))
    A, B = closed_form(mu, bulk, a, b, args.p_inner, args.p_outer, args.support)
    return a, b, bulk, A, B


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("nodes")
    add_shell_arguments(parser)
    parser.add_argument("--tolerance", type=float, default=1)
    parser.add_argument("--cavity", default="0,1e300")
    args = parser.parse_args()
    a, b, _, A, B = shell_solution(args)
    errors, exact_sq, cavity, cavity_exact = [], [], [], []
    with open(args.nodes, newline="") as f:
        for row in csv.DictReader(f):
            x = [float(row[c]) * 1e-3 for c in ("x_mm", "y_mm", "z_mm")]
            u = [float(row[c]) * 1e-3 for c in ("u_x_mm", "u_y_mm", "u_z_mm")]
            r = math.sqrt(sum(c * c for c in x))
            u_r = sum(ui * xi for ui, xi in zip(u, x)) / r
            exact = A * r + B / r**2
            errors.append((u_r - exact) ** 2)
            exact_sq.append(exact**2)
            if r < a * (1 + 1e-3):
                cavity.append(u_r)
                cavity_exact.append(exact)
    rms = math.sqrt(sum(errors) / sum(exact_sq))
    ratio = (sum(cavity) / len(cavity)) / (sum(cavity_exact) / len(cavity_exact))
    lo, hi = (float(x) for x in args.cavity.split(","))
    print(f"{args.label}: {len(errors)} nodes, RMS error of the radial "
          f"displacement {100 * rms:.3f} % (limit {100 * args.tolerance:.3g} %), "
          f"cavity displacement / exact {ratio:.4f} (in [{lo}, {hi}])")
    ok = rms <= args.tolerance and lo <= ratio <= hi
    if not ok:
        print(f"{args.label}: FAILED")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
