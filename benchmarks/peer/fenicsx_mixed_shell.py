#!/usr/bin/python3
"""The peer of the mixed formulation: the inflated shell (a follower pressure
P in the cavity, an elastic support of K_SUPPORT N/m^3 outside, no gravity)
solved by FEniCSx (Debian's python3-dolfinx 0.5) on the same gmsh mesh in
the same discretisation as RestShape's Discretization/Formulation = mixed on
quadratic tetrahedra: P2 displacement with a pressure and a dilatation
constant per cell (the three-field Hu-Washizu form of Simo, Taylor and
Pister, which RestShape condenses on the cell), the neo-Hookean law split as
mu/2 (J^-2/3 tr C - 3) + K/2 (ln J)^2, and deal.II's quadrature rules
(QGaussSimplex(3) on cells and faces, given as custom rules). Solved here
with the pressure and dilatation as unknowns, by PETSc's Newton and MUMPS.

Prints the largest difference of the nodes' displacements between the two
programs over the largest displacement, and exits 1 if it is above
--tolerance. Both programs' nodes are matched by their positions.

usage: fenicsx_mixed_shell.py MESH.msh NODES.csv --E E --nu NU --pressure P
       [--support K] [--steps N] [--tolerance T]"""
import argparse
import csv
import sys

import gmsh
import numpy as np
import ufl
import ufl.log
from dolfinx import fem, mesh as dmesh, nls
from dolfinx.fem import petsc as fem_petsc
from dolfinx.io import gmshio
from mpi4py import MPI
from petsc4py import PETSc
from scipy.spatial import cKDTree

# UFL warns that it hashes the custom rules' arrays by str(): harmless here.
ufl.log.ufl_logger.set_level(ufl.log.ERROR)

# deal.II's QGaussSimplex<3>(3) and QGaussSimplex<2>(3): fully symmetric
# rules (14 and 7 points), so the vertex order of a cell does not matter.
CELL_ORBITS = [  # (a, b, multiplicity pattern, weight)
    ((0.067342242210098213, 0.31088591926330061), "abbb", 0.01878132095300265),
    ((0.72179424906732625, 0.092735250310891248), "abbb", 0.012248840519393659),
    ((0.45449629587435036, 0.045503704125649642), "aabb", 0.0070910034628469121),
]
FACE_ORBITS = [
    ((1 / 3, 1 / 3), "abb", 0.1125),
    ((0.79742698535308731, 0.10128650732345632), "abb", 0.062969590272413584),
    ((0.059715871789769781, 0.47014206410511505), "abb", 0.066197076394253096),
]


def rule(orbits):
    """Points (barycentric orbits, the first coordinate dropped) and weights."""
    import itertools
    points, weights = [], []
    for (a, b), pattern, w in orbits:
        values = [a if c == "a" else b for c in pattern]
        for perm in sorted(set(itertools.permutations(values))):
            points.append(perm[1:])
            weights.append(w)
    return np.array(points), np.array(weights)


def metadata(orbits):
    points, weights = rule(orbits)
    return {"quadrature_rule": "custom", "quadrature_points": points,
            "quadrature_weights": weights, "quadrature_degree": 5}


def solve(mesh_file, E, nu, pressure, support, steps):
    """RestShape's mixed P2-P0 shell in FEniCSx; the P2 nodes (m) and u (m)."""
    # gmshio.read_from_msh of dolfinx 0.5.2 returns an undefined name: its
    # own two steps instead.
    gmsh.initialize(["-noenv"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.merge(mesh_file)
    domain, _, _ = gmshio.model_to_mesh(gmsh.model, MPI.COMM_WORLD, 0, gdim=3)
    gmsh.finalize()
    domain.geometry.x[:] *= 1e-3  # mm to m
    mu, K = E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu))
    cell = domain.ufl_cell()
    W = fem.FunctionSpace(domain, ufl.MixedElement(
        [ufl.VectorElement("Lagrange", cell, 2), ufl.FiniteElement("DG", cell, 0),
         ufl.FiniteElement("DG", cell, 0)]))
    w = fem.Function(W)
    w.x.array[:] = 0
    u, p, Jt = ufl.split(w)
    v = ufl.TestFunction(W)
    dim = domain.topology.dim
    radius = lambda x: np.sqrt(x[0] ** 2 + x[1] ** 2 + x[2] ** 2)
    middle = 0.5 * (radius(domain.geometry.x.T).min() + radius(domain.geometry.x.T).max())
    domain.topology.create_connectivity(dim - 1, dim)
    inner = dmesh.locate_entities_boundary(domain, dim - 1, lambda x: radius(x) < middle)
    outer = dmesh.locate_entities_boundary(domain, dim - 1, lambda x: radius(x) > middle)
    facets = np.concatenate([inner, outer])
    order = np.argsort(facets)
    tags = dmesh.meshtags(domain, dim - 1, facets[order],
                          np.concatenate([np.full(len(inner), 1, np.int32),
                                          np.full(len(outer), 2, np.int32)])[order])
    dx = ufl.Measure("dx", domain=domain, metadata=metadata(CELL_ORBITS))
    ds = ufl.Measure("ds", domain=domain, subdomain_data=tags, metadata=metadata(FACE_ORBITS))
    F = ufl.Identity(3) + ufl.grad(u)
    J = ufl.det(F)
    W_iso = mu / 2 * (J ** (-2 / 3) * ufl.tr(F.T * F) - 3)
    U = K / 2 * ufl.ln(Jt) ** 2
    energy = (W_iso + U + p * (J - Jt)) * dx
    load = fem.Constant(domain, PETSc.ScalarType(0))
    N = ufl.FacetNormal(domain)
    residual = (ufl.derivative(energy, w, v) + support * ufl.inner(u, ufl.split(v)[0]) * ds(2) +
                load * J * ufl.inner(ufl.inv(F).T * N, ufl.split(v)[0]) * ds(1))
    # Jt starts at 1 (ln 0 is undefined): the DG0 dilatation's DoFs.
    _, dofs = W.sub(2).collapse()
    w.x.array[dofs] = 1
    problem = fem_petsc.NonlinearProblem(residual, w, bcs=[])
    newton = nls.petsc.NewtonSolver(MPI.COMM_WORLD, problem)
    newton.convergence_criterion = "residual"
    newton.rtol, newton.atol, newton.max_it = 1e-13, 1e-14, 50
    ksp = newton.krylov_solver
    ksp.setType("preonly")
    ksp.getPC().setType("lu")
    ksp.getPC().setFactorSolverType("mumps")
    for step in range(1, steps + 1):
        load.value = pressure * step / steps
        iterations, converged = newton.solve(w)
        print(f"FEniCSx: load {step / steps:.3f}: {iterations} Newton steps", file=sys.stderr)
        if not converged:
            sys.exit("FEniCSx: Newton did not converge")
    V, dofs = W.sub(0).collapse()
    return V.tabulate_dof_coordinates(), w.x.array[dofs].reshape(-1, 3)


def read_ours(path):
    """RestShape's nodes.csv: positions (mm) and displacements (mm)."""
    X, u = [], []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            X.append([float(row[f"{c}_mm"]) for c in "xyz"])
            u.append([float(row[f"u_{c}_mm"]) for c in "xyz"])
    return np.array(X), np.array(u)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("nodes")
    parser.add_argument("--E", type=float, required=True)
    parser.add_argument("--nu", type=float, required=True)
    parser.add_argument("--pressure", type=float, required=True)
    parser.add_argument("--support", type=float, default=0)
    parser.add_argument("--steps", type=int, default=4)
    parser.add_argument("--tolerance", type=float, default=1e-6)
    args = parser.parse_args()
    points, theirs = solve(args.mesh, args.E, args.nu, args.pressure, args.support, args.steps)
    X, ours = read_ours(args.nodes)
    distance, index = cKDTree(points * 1e3).query(X)
    if len(X) != len(points) or distance.max() > 1e-6:
        sys.exit(f"the meshes differ: {len(X)} nodes against {len(points)}, "
                 f"largest distance {distance.max():.3g} mm")
    difference = np.linalg.norm(ours - 1e3 * theirs[index], axis=1).max()
    largest = np.linalg.norm(ours, axis=1).max()
    ratio = difference / largest
    print(f"{len(X)} nodes: largest displacement {largest:.6f} mm, largest "
          f"difference RestShape - FEniCSx {difference:.3g} mm ({ratio:.3g} of it; "
          f"limit {args.tolerance:.3g})")
    return 0 if ratio <= args.tolerance else 1


if __name__ == "__main__":
    sys.exit(main())
