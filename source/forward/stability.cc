// The stability of an equilibrium: shift-invert Lanczos on the constrained
// tangent and the lumped mass, and the tangent's inertia.
#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <restshape/base/progress.h>
#include <restshape/base/units.h>
#include <restshape/forward/forward_problem.h>
#include <restshape/forward/stability.h>

#include <cmath>
#include <cstdio>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// Lanczos steps: the extreme eigenvalues of K^-1 M (the ones of K
    /// nearest zero) converge in far fewer. With inexact (CG) solves,
    /// fewer steps to a relative tolerance: a bounded cost, and a Ritz
    /// value counts as negative beyond that tolerance of the largest.
    /// Measured on the brain as hexahedra (75,072 DoFs, cg-amg): 20 steps
    /// to 1e-6 took 35.8 s against 5.4 s for the forward solve; 10 steps
    /// to 1e-3, 9.8 s, the same smallest eigenvalue to 4 digits (88.26
    /// 1/s^2; on the coarse brain 98.19 with either and with the direct
    /// solver).
    constexpr unsigned int lanczos_steps           = 40;
    constexpr unsigned int inexact_lanczos_steps   = 10;
    constexpr double       inexact_solve_tolerance = 1e-3;
    constexpr double       exact_negative_fraction = 1e-10;
    /// The density (kg/m^3) of the mass the modes are measured against in
    /// cells whose Materials/Density is 0: any positive mass gives the
    /// same signs of the eigenvalues (stable or not); water's is the
    /// scale of tissue's.
    constexpr double reference_density = 1000;

    /// The HRZ-lumped mass matrix (kg): per cell the diagonal of the
    /// consistent mass, scaled to the cell's mass, per component.
    VectorType
    lumped_mass(const ForwardProblem &forward, bool &reference_mass)
    {
      reference_mass          = false;
      VectorType         mass = forward.discretization().zero_vector();
      FEValues<3>        fv(forward.discretization().mapping(),
                     forward.discretization().fe(),
                     forward.discretization().quadrature(),
                     update_values | update_JxW_values);
      const unsigned int n = forward.discretization().fe().n_dofs_per_cell();
      std::vector<types::global_dof_index> dofs(n);
      Vector<double>                       diagonal(n);
      for (const auto &cell :
           forward.discretization().dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fv.reinit(cell);
            cell->get_dof_indices(dofs);
            double rho = forward.materials().density(cell->material_id()) *
                         forward.discretization().mesh().mass_ratio(*cell);
            if (!(rho > 0))
              {
                rho            = reference_density;
                reference_mass = true;
              }
            double volume = 0, sum = 0;
            diagonal = 0;
            for (const unsigned int q : fv.quadrature_point_indices())
              {
                volume += fv.JxW(q);
                for (unsigned int i = 0; i < n; ++i)
                  diagonal[i] +=
                    fv.shape_value(i, q) * fv.shape_value(i, q) * fv.JxW(q);
              }
            for (unsigned int i = 0; i < n; ++i)
              sum += diagonal[i];
            // Every component carries the cell's mass: sum / 3 per
            // component.
            for (unsigned int i = 0; i < n; ++i)
              mass[dofs[i]] += rho * volume * diagonal[i] / (sum / 3);
          }
      mass.compress(VectorOperation::add);
      reference_mass = Utilities::MPI::logical_or(
        reference_mass,
        forward.discretization().dof_handler().get_communicator());
      return mass;
    }

    /// The constraints without their inhomogeneities: admissible variations.
    AffineConstraints<double>
    homogeneous(const ForwardProblem &forward)
    {
      AffineConstraints<double> h(
        forward.discretization().locally_relevant_dofs());
      for (const auto &line : forward.newton_constraints().get_lines())
        {
          h.add_line(line.index);
          h.add_entries(line.index, line.entries);
        }
      h.close();
      return h;
    }

    /// M-inner product.
    double
    dot(const VectorType &a, const VectorType &M, const VectorType &b)
    {
      VectorType Mb = b;
      Mb.scale(M);
      return a * Mb;
    }
  } // namespace

  std::string
  StabilityResult::text() const
  {
    char buffer[400];
    if (stable())
      std::snprintf(buffer,
                    sizeof(buffer),
                    "stable: the smallest eigenvalue of the constrained "
                    "tangent is %.4g 1/s^2 (%.4g Hz), its mode largest at "
                    "(%.1f, %.1f, %.1f) mm (label %u)",
                    smallest_eigenvalue,
                    std::sqrt(smallest_eigenvalue) / (2 * M_PI),
                    mm_per_m * peak[0],
                    mm_per_m * peak[1],
                    mm_per_m * peak[2],
                    static_cast<unsigned int>(label));
    else
      std::snprintf(buffer,
                    sizeof(buffer),
                    "unstable: the constrained tangent has %d negative "
                    "eigenvalue(s) near zero, the smallest %.4g 1/s^2; the "
                    "equilibrium "
                    "is not a minimum of the energy and the body would "
                    "leave it along a mode largest at (%.1f, %.1f, %.1f) mm "
                    "(label %u)",
                    negative_eigenvalues,
                    smallest_eigenvalue,
                    mm_per_m * peak[0],
                    mm_per_m * peak[1],
                    mm_per_m * peak[2],
                    static_cast<unsigned int>(label));
    return buffer;
  }

  std::string
  StabilityResult::mass_text() const
  {
    if (!reference_mass)
      return "";
    char buffer[160];
    std::snprintf(buffer,
                  sizeof(buffer),
                  "eigenvalues against a mass of %g kg/m^3 where "
                  "Materials/Density is 0",
                  reference_density);
    return buffer;
  }

  std::string
  free_dofs_missing(const ForwardProblem &forward)
  {
    const AffineConstraints<double> &c = forward.newton_constraints();
    unsigned long                    n = 0;
    for (const auto i : forward.discretization().locally_owned_dofs())
      n += !c.is_constrained(i);
    n = Utilities::MPI::sum(
      n, forward.discretization().dof_handler().get_communicator());
    return n == 0 ? "no free degree of freedom: every node is fixed or "
                    "constrained" :
                    "";
  }

  std::string
  StabilityResult::variant_text() const
  {
    if (exact_solves)
      return "";
    char buffer[100];
    std::snprintf(buffer,
                  sizeof(buffer),
                  "bounded variant: %u Lanczos steps, CG solves to %.0e",
                  inexact_lanczos_steps,
                  inexact_solve_tolerance);
    return buffer;
  }

  StabilityResult
  check_stability(ForwardProblem &forward)
  {
    const AffineConstraints<double> constraints = homogeneous(forward);
    StabilityResult                 result;
    VectorType M = lumped_mass(forward, result.reference_mass);
    // Constrained DoFs carry no mass: their modes are infinitely stiff.
    for (const auto i : forward.discretization().locally_owned_dofs())
      if (constraints.is_constrained(i))
        M[i] = 0;
    M.compress(VectorOperation::insert);

    // A start vector that does not depend on the number of ranks.
    VectorType q = forward.discretization().zero_vector();
    for (const auto i : forward.discretization().locally_owned_dofs())
      q[i] = std::sin(12.9898 * i + 78.233) + 0.5;
    q.compress(VectorOperation::insert);
    constraints.distribute(q);
    q /= std::sqrt(dot(q, M, q));

    const bool         exact  = forward.tangent_solves_are_exact();
    const unsigned int steps  = exact ? lanczos_steps : inexact_lanczos_steps;
    result.exact_solves       = exact;
    std::vector<VectorType> Q = {q};
    std::vector<double>     alpha, beta;
    VectorType              z = forward.discretization().zero_vector(),
               b              = forward.discretization().zero_vector();
    for (unsigned int j = 0; j < steps; ++j)
      {
        // z = K^-1 M q_j, then into the constrained space. (M is zero at
        // constrained DoFs, so M q_j has nothing to condense onto them.)
        set_progress_phase("stability check: Lanczos step " +
                           std::to_string(j + 1) + " of at most " +
                           std::to_string(steps));
        b = Q[j];
        b.scale(M);
        z = 0;
        if (j == 0)
          forward.prepare_consistent_tangent();
        forward.solve_with_tangent(z, b, inexact_solve_tolerance);
        constraints.distribute(z);
        alpha.push_back(dot(Q[j], M, z));
        // Full re-orthogonalisation (twice is enough).
        for (unsigned int pass = 0; pass < 2; ++pass)
          for (const VectorType &v : Q)
            z.add(-dot(v, M, z), v);
        const double norm = std::sqrt(std::max(dot(z, M, z), 0.));
        if (!(norm > 1e-12 * std::abs(alpha.back())))
          break; // an invariant subspace: its eigenvalues are exact
        beta.push_back(norm);
        z /= norm;
        Q.push_back(z);
      }

    // Ritz values theta of K^-1 M: lambda = 1 / theta.
    const unsigned int       m = alpha.size();
    LAPACKFullMatrix<double> T(m, m);
    for (unsigned int i = 0; i < m; ++i)
      {
        T(i, i) = alpha[i];
        if (i + 1 < m)
          T(i, i + 1) = T(i + 1, i) = beta[i];
      }
    Vector<double>     theta;
    FullMatrix<double> S;
    T.compute_eigenvalues_symmetric(-1e300, 1e300, 0, theta, S);
    // A negative Ritz value is a Rayleigh quotient of K^-1 M: K then has
    // a negative eigenvalue (beyond round-off of the largest theta).
    unsigned int k             = 0; // the most negative theta, else the largest
    double       largest_theta = 0;
    for (unsigned int i = 0; i < theta.size(); ++i)
      largest_theta = std::max(largest_theta, std::abs(theta[i]));
    for (unsigned int i = 0; i < theta.size(); ++i)
      {
        if (theta[i] <
            -(exact ? exact_negative_fraction : inexact_solve_tolerance) *
              largest_theta)
          ++result.negative_eigenvalues;
        if (theta[k] >= 0 ? (theta[i] < 0 || theta[i] > theta[k]) :
                            theta[i] < theta[k])
          k = i;
      }
    result.smallest_eigenvalue = 1 / theta[k];

    // The mode and where it is largest.
    VectorType mode = forward.discretization().zero_vector();
    for (unsigned int i = 0; i < m; ++i)
      mode.add(S(i, k), Q[i]);
    double largest = 0;
    for (const auto &cell :
         forward.discretization().dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            if (!forward.discretization().locally_owned_dofs().is_element(
                  cell->vertex_dof_index(v, 0)))
              continue;
            Tensor<1, 3> value;
            for (unsigned int c = 0; c < 3; ++c)
              value[c] = mode[cell->vertex_dof_index(v, c)];
            if (value.norm() > largest)
              {
                largest      = value.norm();
                result.peak  = cell->vertex(v);
                result.label = cell->material_id();
              }
          }
    const MPI_Comm comm = forward.discretization()
                            .dof_handler()
                            .get_triangulation()
                            .get_communicator();
    const std::vector<double> mine = {largest,
                                      result.peak[0],
                                      result.peak[1],
                                      result.peak[2],
                                      double(result.label)};
    for (const auto &r : Utilities::MPI::all_gather(comm, mine))
      if (r[0] > largest)
        {
          largest      = r[0];
          result.peak  = Point<3>(r[1], r[2], r[3]);
          result.label = Label(r[4]);
        }
    return result;
  }
} // namespace RestShape
