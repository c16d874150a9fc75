#!/usr/bin/python3
"""The patch test (tests/data/patch_test.prm): a cube of distorted cells on
rollers on the planes x, y, z = 0, pulled by a dead traction t on its face
x = L. The exact solution is homogeneous uniaxial tension, u = (F - I) X
with F = diag(a, b, b), the principal nominal stresses P_1 = t and
P_2 = P_3 = 0 of the law:

  mixed neo-Hookean   W = mu/2 (J^-2/3 I1 - 3) + K/2 (ln J)^2,
                      P_i = mu J^-2/3 (l_i - I1 / (3 l_i)) + K ln J / l_i;
  neo-Hookean         W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,
                      P_i = mu (l_i - 1 / l_i) + lambda ln J / l_i;
  none                any law: the field must be homogeneous, F is not
                      checked against a law.

An element passes when, on the distorted patch,
  - the nodes' displacements (nodes.csv, 10 digits) are the linear field
    u = A X: the least-squares fit's largest residual at most --tolerance
    times the largest displacement, and A = F - I of the law to the same
    tolerance (relative to a - 1);
  - every cell's volume_ratio and pressure_Pa (the VTU or, under MPI, the
    PVTU, read with VTK) is the exact J = a b^2 and the exact pressure
    -tr(sigma) / 3 (K ln J / J for the mixed law) to 1e-5 of J and of t.

usage: check_patch_test.py OUTPUT_DIR --law mixed-neo-Hookean|neo-Hookean|none
       --young E --poisson NU --traction T [--tolerance REL]"""
import argparse
import csv
import glob
import sys

import numpy as np
from scipy.optimize import fsolve
from vtk.util.numpy_support import vtk_to_numpy

from vtk_grid import read_grid

FIELD_TOLERANCE = 1e-5  # float32 fields of the VTU, relative


def principal_stresses(law, mu, K, lam, l):
    """Principal nominal stresses P_i of the stretches l (3,)."""
    J = l.prod()
    if law == "mixed-neo-Hookean":
        I1 = (l ** 2).sum()
        return mu * J ** (-2 / 3) * (l - I1 / (3 * l)) + K * np.log(J) / l
    return mu * (l - 1 / l) + lam * np.log(J) / l


def exact_stretches(law, E, nu, t):
    mu = E / (2 * (1 + nu))
    K = E / (3 * (1 - 2 * nu))
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))

    def equations(ab):
        l = np.array([ab[0], ab[1], ab[1]])
        P = principal_stresses(law, mu, K, lam, l)
        return [(P[0] - t) / mu, P[1] / mu]

    a, b = fsolve(equations, [1 + t / E, 1 - nu * t / E], xtol=1e-13)
    l = np.array([a, b, b])
    J = l.prod()
    # Cauchy mean stress: sum l_i P_i / (3 J).
    mean_stress = (l * principal_stresses(law, mu, K, lam, l)).sum() / (3 * J)
    return a, b, J, -mean_stress


def read_nodes(directory):
    with open(f"{directory}/nodes.csv") as f:
        rows = list(csv.DictReader(f))
    x = np.array([[float(r[k]) for k in ("x_mm", "y_mm", "z_mm")] for r in rows])
    u = np.array([[float(r[k]) for k in ("u_x_mm", "u_y_mm", "u_z_mm")] for r in rows])
    return x, u


def read_cell_fields(directory):
    # Under MPI the .pvtu gathers the ranks' pieces.
    files = (sorted(glob.glob(f"{directory}/solution-*.pvtu")) or
             sorted(glob.glob(f"{directory}/solution-*.vtu")))
    grid = read_grid(files[-1]) if files else None
    if grid is None:
        sys.exit(f"check_patch_test.py: {directory}: no readable solution-*.vtu")
    cells = grid.GetCellData()
    return (vtk_to_numpy(cells.GetArray("volume_ratio")),
            vtk_to_numpy(cells.GetArray("pressure_Pa")))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("directory")
    parser.add_argument("--law", required=True,
                        choices=("mixed-neo-Hookean", "neo-Hookean", "none"))
    parser.add_argument("--young", type=float, required=True)
    parser.add_argument("--poisson", type=float, required=True)
    parser.add_argument("--traction", type=float, required=True)
    parser.add_argument("--tolerance", type=float, default=1e-8)
    args = parser.parse_args()

    x, u = read_nodes(args.directory)
    design = np.hstack([x, np.ones((len(x), 1))])
    coefficients = np.linalg.lstsq(design, u, rcond=None)[0]
    A = coefficients[:3].T
    scale = np.abs(u).max()
    residual = np.abs(design @ coefficients - u).max() / scale
    J_cells, p_cells = read_cell_fields(args.directory)
    J_fit = np.linalg.det(np.eye(3) + A)
    print(f"{len(x)} nodes, largest |u| {scale:.6f} mm; linear fit: largest "
          f"residual {residual:.2e} of it; F = diag({1 + A[0, 0]:.10f}, "
          f"{1 + A[1, 1]:.10f}, {1 + A[2, 2]:.10f}), largest off-diagonal "
          f"{np.abs(A - np.diag(np.diag(A))).max():.1e}")
    print(f"{len(J_cells)} cells: volume_ratio {J_cells.min():.8f} to "
          f"{J_cells.max():.8f}, pressure_Pa {p_cells.min():.6g} to "
          f"{p_cells.max():.6g}")
    failures = []
    if residual > args.tolerance:
        failures.append(f"the displacement is not linear ({residual:.2e})")
    field_scale = abs(args.traction)
    if np.abs(J_cells - J_fit).max() > FIELD_TOLERANCE * J_fit:
        failures.append("volume_ratio is not the fit's J in every cell")
    if np.ptp(p_cells) > FIELD_TOLERANCE * field_scale:
        failures.append("pressure_Pa differs from cell to cell")
    if args.law != "none":
        a, b, J, p = exact_stretches(args.law, args.young, args.poisson,
                                     args.traction)
        print(f"exact ({args.law}): F = diag({a:.10f}, {b:.10f}, {b:.10f}), "
              f"J = {J:.8f}, pressure {p:.6g} Pa")
        exact = np.diag([a - 1, b - 1, b - 1])
        error = np.abs(A - exact).max() / (a - 1)
        print(f"F - I against the exact: {error:.2e} of a - 1")
        if error > args.tolerance:
            failures.append(f"F differs from the exact one ({error:.2e})")
        if np.abs(J_cells - J).max() > FIELD_TOLERANCE * J:
            failures.append("volume_ratio differs from the exact J")
        if np.abs(p_cells - p).max() > FIELD_TOLERANCE * field_scale:
            failures.append("pressure_Pa differs from the exact pressure")
    for f in failures:
        print(f"FAIL: {f}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
