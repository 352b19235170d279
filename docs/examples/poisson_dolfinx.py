#!/usr/bin/python3
"""Poisson's equation on a madd mesh with DOLFINx: a convergence study.

Solves -Δu = f on the key domain (data/key.poly) with P1 Lagrange elements
and a manufactured solution, on three meshes from madd, each with a quarter
of the previous largest triangle area, so that h halves each time.
P1 elements should show an L2 error falling as h² and an H1 seminorm error
as h; the script prints both and fails if the L2 rate is not about 2.

    python3 docs/examples/poisson_dolfinx.py [data/key.poly]

Written against DOLFINx 0.5 (Debian 12's python3-dolfinx). It runs
serially, and also under mpirun: rank 0 makes the mesh and DOLFINx
distributes it.
"""
import sys

import numpy as np
import ufl
from mpi4py import MPI

import dolfinx
import dolfinx.fem.petsc
import madd

comm = MPI.COMM_WORLD


def u_exact(x, m):
    """The manufactured solution: smooth, and not in any polynomial space.

    x is the coordinate pair and m the module providing sin, cos and pi,
    so that the one definition serves as a UFL expression (m = ufl) and
    as a numpy function (m = np)."""
    return m.sin(m.pi * x[0]) * m.cos(m.pi * x[1]) + x[0] * x[1]


def largest_edge(points, triangles):
    """The mesh size h: the length of the longest edge of any triangle."""
    corners = points[triangles]                       # (M, 3, 2)
    edges = corners - np.roll(corners, 1, axis=1)     # the three edge vectors
    return float(np.sqrt((edges ** 2).sum(axis=2)).max())


def madd_mesh(domain, max_area):
    """A madd mesh as a DOLFINx mesh, with its triangle count and h."""
    if comm.rank == 0:
        m = madd.mesh(domain, 8, q=30, max_area=max_area)
        cells = m.triangles.astype(np.int64)
        x = np.array(m.points, dtype=np.float64)
        stats = (len(cells), largest_edge(m.points, m.triangles))
    else:
        # The other ranks contribute no cells; create_mesh distributes rank 0's.
        cells = np.empty((0, 3), dtype=np.int64)
        x = np.empty((0, 2), dtype=np.float64)
        stats = None
    num_triangles, h = comm.bcast(stats, root=0)
    # The coordinate element: P1 on triangles, in two dimensions.
    coordinate_element = ufl.Mesh(ufl.VectorElement("Lagrange", ufl.triangle, 1))
    msh = dolfinx.mesh.create_mesh(comm, cells, x, coordinate_element)
    return msh, num_triangles, h


def solve_poisson(msh):
    """Solve -Δu = f, u = u_exact on the boundary; return the P1 solution."""
    V = dolfinx.fem.FunctionSpace(msh, ("Lagrange", 1))

    # The right-hand side f = -Δu_exact, differentiated symbolically by UFL.
    x = ufl.SpatialCoordinate(msh)
    f = -ufl.div(ufl.grad(u_exact(x, ufl)))

    # Dirichlet data on every boundary facet (the outer boundary and the hole).
    tdim = msh.topology.dim
    msh.topology.create_connectivity(tdim - 1, tdim)
    boundary_facets = dolfinx.mesh.exterior_facet_indices(msh.topology)
    boundary_dofs = dolfinx.fem.locate_dofs_topological(V, tdim - 1, boundary_facets)
    u_boundary = dolfinx.fem.Function(V)
    u_boundary.interpolate(lambda p: u_exact(p, np))
    bc = dolfinx.fem.dirichletbc(u_boundary, boundary_dofs)

    # The weak form: find u in V with (grad u, grad v) = (f, v) for all v.
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
    a = ufl.inner(ufl.grad(u), ufl.grad(v)) * ufl.dx
    L = f * v * ufl.dx
    # A direct solver: conjugate gradients would do as well, but LU is
    # robust, and fast at these sizes.
    problem = dolfinx.fem.petsc.LinearProblem(
        a, L, bcs=[bc], petsc_options={"ksp_type": "preonly", "pc_type": "lu"})
    return problem.solve()


def errors(uh):
    """The L2 error and the H1 seminorm error of uh against u_exact."""
    msh = uh.function_space.mesh
    # The exact solution enters as a UFL expression, so the error is not
    # polluted by interpolating it; a higher quadrature degree than the
    # default keeps the quadrature error well below the discretisation error.
    e = uh - u_exact(ufl.SpatialCoordinate(msh), ufl)
    dx = ufl.dx(metadata={"quadrature_degree": 6})

    def norm(integrand):
        local = dolfinx.fem.assemble_scalar(dolfinx.fem.form(integrand * dx))
        return np.sqrt(comm.allreduce(local, op=MPI.SUM))  # sum over ranks

    return norm(e * e), norm(ufl.inner(ufl.grad(e), ufl.grad(e)))


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "data/key.poly"
    domain = madd.read_domain(path)

    # The key spans about 10 x 4 units (area 17.5); a0 = 0.01 gives some
    # 2800 triangles. Each refinement quarters the largest area, halving h.
    a0 = 0.01
    rows = []
    for max_area in (a0, a0 / 4, a0 / 16):
        msh, num_triangles, h = madd_mesh(domain, max_area)
        uh = solve_poisson(msh)
        rows.append((num_triangles, h, *errors(uh)))

    # The observed rate between consecutive meshes: log(e_i/e_{i+1}) / log(h_i/h_{i+1}).
    def rate(i, column):
        return np.log(rows[i - 1][column] / rows[i][column]) / np.log(rows[i - 1][1] / rows[i][1])

    l2_rates = [rate(i, 2) for i in range(1, len(rows))]
    if comm.rank == 0:
        print(f"P1 Lagrange on {path}, u = sin(pi x) cos(pi y) + x y, {comm.size} rank(s)")
        print(f"{'triangles':>10} {'h':>10} {'L2 error':>11} {'rate':>5} {'H1 error':>11} {'rate':>5}")
        for i, (num_triangles, h, l2, h1) in enumerate(rows):
            l2_rate = f"{rate(i, 2):5.2f}" if i else ""
            h1_rate = f"{rate(i, 3):5.2f}" if i else ""
            print(f"{num_triangles:>10} {h:10.4f} {l2:11.3e} {l2_rate:>5} {h1:11.3e} {h1_rate:>5}")

    # Fail loudly if the discretisation does not converge at the expected rate.
    low, high = 1.8, 2.3
    assert all(low <= r <= high for r in l2_rates), f"L2 rates {l2_rates} not in [{low}, {high}]"


if __name__ == "__main__":
    main()
