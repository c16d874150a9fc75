#!/usr/bin/python3
"""The inflated neo-Hookean shell at large strain against its radial
equilibrium: a thick spherical shell, a follower pressure p in its cavity,
an elastic support of stiffness k (N/m^3, a traction -k u per unit rest
area) on its outer surface, no gravity. A radial deformation r(R) with the
stretches lambda_r = r', lambda_t = r / R has the nominal stresses
P_i = dW/dlambda_i and the equilibrium

    d P_r / dR + 2 (P_r - P_t) / R = 0,
    P_r = -p lambda_t^2 on the cavity,  P_r = -k (r - R) outside,

an ODE solved to 1e-11 (scipy) with one shooting parameter (the cavity's
current radius in a forward solve, its rest radius in an inverse one).

Laws (--law): "mixed", the neo-Hookean of the mixed formulation,
mu/2 (J^-2/3 tr C - 3) + K/2 (ln J)^2; "displacement", the compressible
neo-Hookean mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2.

Forward (--mode forward): nodes.csv's mesh position is the rest shape; the
error is that of the current position X + u against r(|X|) X / |X|.
Inverse (--mode inverse): the mesh position is the loaded shape; the error
is that of the rest position X + rest_shift against R(|X|) X / |X|. Either is
printed as the RMS of the error vector over the RMS of the exact
displacement, with the cavity's mean radius against the exact one; exit 1
if the RMS ratio is above --tolerance.

usage: check_inflated_shell.py NODES.csv --mode forward|inverse --E E --nu NU
       --p-inner P [--support K] [--radii A,B] [--law mixed|displacement]
       [--tolerance T] [--label TEXT]"""
import argparse
import csv
import math
import sys

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

TOLERANCE = 1e-11  # relative and absolute (mm) of the ODE's integration
STEP = 1e-30  # the complex step of the derivatives of the stresses


class Law:
    """Nominal stresses P_i(l1, l2, l3) of a neo-Hookean energy (Pa)."""

    def __init__(self, kind, E, nu):
        self.mu = E / (2 * (1 + nu))
        self.K = E / (3 * (1 - 2 * nu))
        self.kind = kind

    def stress(self, l, i):
        J = l[0] * l[1] * l[2]
        if self.kind == "mixed":
            I1 = l[0] ** 2 + l[1] ** 2 + l[2] ** 2
            return (self.mu * J ** (-2 / 3) * (l[i] - I1 / (3 * l[i])) +
                    self.K * np.log(J) / l[i])
        lam = self.K - 2 * self.mu / 3
        return self.mu * (l[i] - 1 / l[i]) + lam * np.log(J) / l[i]

    def radial(self, lr, lt):
        return self.stress((lr, lt, lt), 0).real

    def derivative(self, lr, lt, i, j):
        """d P_i / d l_j by the complex step (exact to round-off)."""
        l = [complex(lr), complex(lt), complex(lt)]
        l[j] += 1j * STEP
        return self.stress(l, i).imag / STEP

    def curvature(self, R, r, lr):
        """r'' from the radial equilibrium."""
        lt = r / R
        p_r, p_t = self.radial(lr, lt), self.stress((lr, lt, lt), 1).real
        cross = self.derivative(lr, lt, 0, 1) + self.derivative(lr, lt, 0, 2)
        return (-2 * (p_r - p_t) / R - cross * (lr - lt) / R) / \
            self.derivative(lr, lt, 0, 0)

    def radial_stretch(self, lt, traction):
        """lambda_r with P_r(lambda_r, lt) = traction."""
        return brentq(lambda lr: self.radial(lr, lt) - traction, 1e-3, 1e3,
                      xtol=1e-15, rtol=1e-15)


def radial_solution(law, inner, outer, p, k, extend, inverse):
    """The radius of the other configuration as a function of the radius t
    of the mesh's, on [inner (1 - extend), outer (1 + extend)] (mm): r(R)
    forward (the mesh is the rest shape), R(r) inverse (the mesh is the
    loaded shape). The state is (the other radius, lambda_r) along t."""

    def radii(t, s):  # (rest, current)
        return (s, t) if inverse else (t, s)

    def rhs(t, y):
        R, r = radii(t, y[0])
        curvature = law.curvature(R, r, y[1])
        return [1 / y[1], curvature / y[1]] if inverse else [y[1], curvature]

    def shoot(s0, span):
        R, r = radii(inner, s0)
        lt = r / R
        lr = law.radial_stretch(lt, -p * lt * lt)
        return solve_ivp(rhs, span, [s0, lr], method="DOP853", rtol=TOLERANCE,
                         atol=TOLERANCE, dense_output=True)

    def outer_condition(s0):
        s, lr = shoot(s0, (inner, outer)).y[:, -1]
        R, r = radii(outer, s)
        return law.radial(lr, r / R) + k * 1e-3 * (r - R)

    s0 = root(outer_condition, inner)
    out = shoot(s0, (inner, outer * (1 + extend)))
    inside = shoot(s0, (inner, inner * (1 - extend)))
    return lambda t: np.where(t >= inner, out.sol(t)[0], inside.sol(t)[0])


def root(f, x0):
    """A zero of f near x0 (a radius, mm): bracketed outward from x0."""
    step = 0.01 * x0
    lo, hi = x0, x0
    while f(lo) * f(hi) > 0:
        lo, hi = lo - step, hi + step
        step *= 1.5
        if lo <= 0.2 * x0:
            sys.exit("check_inflated_shell.py: no radial equilibrium found")
    return brentq(f, lo, hi, xtol=1e-13, rtol=1e-15)


def read_nodes(path, mode):
    """Mesh positions X and the other configuration's positions Y (mm)."""
    column = "u" if mode == "forward" else "rest_shift"
    X, Y = [], []
    with open(path, newline="") as f:
        rows = csv.DictReader(f)
        names = [f"{column}_{c}_mm" for c in "xyz"]
        if not set(names) <= set(rows.fieldnames or []):
            sys.exit(f"{path}: no columns {', '.join(names)}")
        for row in rows:
            x = [float(row[f"{c}_mm"]) for c in "xyz"]
            X.append(x)
            Y.append([xi + float(row[n]) for xi, n in zip(x, names)])
    return np.array(X), np.array(Y)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("nodes")
    parser.add_argument("--mode", choices=("forward", "inverse"), required=True)
    parser.add_argument("--E", type=float, required=True)
    parser.add_argument("--nu", type=float, required=True)
    parser.add_argument("--p-inner", type=float, required=True)
    parser.add_argument("--support", type=float, default=0)
    parser.add_argument("--radii", default="10,20")
    parser.add_argument("--law", choices=("mixed", "displacement"), default="mixed")
    parser.add_argument("--tolerance", type=float, default=1)
    parser.add_argument("--label", default="inflated shell")
    args = parser.parse_args()
    a, b = (float(x) for x in args.radii.split(","))
    law = Law(args.law, args.E, args.nu)
    exact_radius = radial_solution(law, a, b, args.p_inner, args.support, 0.2,
                                   args.mode == "inverse")
    X, Y = read_nodes(args.nodes, args.mode)
    R = np.linalg.norm(X, axis=1)
    exact = exact_radius(R)[:, None] * X / R[:, None]
    rms = math.sqrt(((Y - exact) ** 2).sum() / ((exact - X) ** 2).sum())
    cavity = R < a * (1 + 1e-3)
    radius, radius_exact = np.linalg.norm(Y[cavity], axis=1).mean(), \
        np.linalg.norm(exact[cavity], axis=1).mean()
    print(f"{args.label}: {len(R)} nodes, {args.mode}, RMS error of the "
          f"positions / RMS exact displacement {100 * rms:.3f} % (limit "
          f"{100 * args.tolerance:.3g} %), cavity radius {radius:.5f} mm, exact "
          f"{radius_exact:.5f} mm (hoop stretch {max(radius, a) / min(radius, a):.4f})")
    if rms > args.tolerance:
        print(f"{args.label}: FAILED")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
