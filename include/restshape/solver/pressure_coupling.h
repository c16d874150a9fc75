// The pressure unknowns of the mixed formulation, which the assembly
// condenses out of the tangent, kept for a block preconditioner. Each one
// (a cell's pressure, or a mode of a cell's linear pressure, or a vertex's
// averaged nodal pressure) adds k g g^T to the condensed tangent K: g the
// gradient of its volume in the displacements (m^2), k its volumetric
// stiffness (U''(J) / V, Pa/m^3). K is the Schur complement, onto the
// displacements, of the uncondensed system
//
//   [ A  G^T  ] [du]   [r]
//   [ G  -D   ] [dp] = [0],    D = diag(1 / k),  A = K - G^T D^-1 G,
//
// whose displacement block A carries the shear stiffness, not the bulk
// modulus. Of each unknown's k the assembly hands over the fraction
// coupled_fraction(): A keeps a bulk modulus of block_bulk_to_shear times
// the shear modulus, so that it stays an elasticity operator (Poisson's
// ratio 0.125) whose near-kernel is the rigid-body modes AMG is built
// with. The isochoric part alone leaves dilations nearly free: with AMG on
// it, CG (2,000 iterations) and GMRES (5,000) failed in the first Newton
// step of step-44's block (16^3 Q1-P0, nu = 0.4999); with this bulk
// modulus kept, CG took 660 iterations there (127 with schur_safety).
#ifndef restshape_solver_pressure_coupling_h
#define restshape_solver_pressure_coupling_h

#include <deal.II/base/index_set.h>
#include <deal.II/lac/affine_constraints.h>

#include <restshape/base/linear_algebra_types.h>

#include <algorithm>
#include <vector>

namespace RestShape
{
  /// The bulk modulus the displacement block keeps, in shear moduli.
  constexpr double block_bulk_to_shear = 1;

  /// The fraction of a pressure unknown's volumetric stiffness that goes
  /// into the pressure block, for a law of shear modulus @p mu and bulk
  /// modulus @p K (Pa): 1 - block_bulk_to_shear mu / K, at least 0.
  inline double
  coupled_fraction(const double mu, const double K)
  {
    return K > 0 ? std::max(0., 1 - block_bulk_to_shear * mu / K) : 0.;
  }

  /**
   * sum_j G_ij^2 / A_jj underestimates G A^-1 G^T; where the approximation
   * of the Schur complement lies below it, the block preconditioner is
   * indefinite and CG stalls. Measured, CG iterations of the first Newton
   * step on the Lame shell (tests/data/lame_shell.prm, 4 mm, nu = 0.4999):
   * P1 with the averaged nodal pressure 554, 39 and 55 with this factor 1,
   * 3 and 10; P2-P0 44, 48 and 52 with 2, 3 and 5.
   */
  constexpr double schur_safety = 3;

  class PressureCoupling
  {
  public:
    /// Forget the unknowns of the last assembly.
    void
    clear();

    /// One pressure unknown of this process: @p factor g g^T was added to
    /// the tangent at @p dofs through @p constraints. Its row of G is g
    /// with the constraints resolved (their inhomogeneities are in the
    /// right-hand side already).
    void
    add(const std::vector<dealii::types::global_dof_index> &dofs,
        const double                                       *g,
        const double                                        factor,
        const dealii::AffineConstraints<double>            &constraints);

    /// Build G from the unknowns added (rows: each process's unknowns in
    /// turn; columns: the DoFs, partitioned as @p owned_dofs). Collective.
    void
    finish(const dealii::IndexSet &owned_dofs, const MPI_Comm communicator);

    /// The number of pressure unknowns of all processes (as of finish()).
    dealii::types::global_dof_index
    n_global() const
    {
      return n_total;
    }

    /// A = @p K - G^T D^-1 G into @p A (K's sparsity pattern).
    void
    displacement_block(const MatrixType &K, MatrixType &A) const;

    /// The diagonal approximation of the pressure Schur complement
    /// D + G A^-1 G^T: 1 / k_i + schur_safety sum_j G_ij^2 / A_jj, with
    /// @p A_diagonal the diagonal of A (owned entries), inverted: one
    /// entry per pressure unknown of this process.
    VectorType
    inverse_schur_diagonal(const VectorType &A_diagonal) const;

    /// G (pressure unknowns x DoFs).
    const MatrixType &
    rows() const
    {
      return G;
    }

  private:
    // The rows in compressed form: unknown i has the columns
    // columns[start[i] .. start[i + 1]) (sorted, distinct).
    std::vector<std::size_t>                     start = {0};
    std::vector<dealii::types::global_dof_index> columns;
    std::vector<double>                          values;
    std::vector<double>                          factors; // k (Pa/m^3)
    dealii::types::global_dof_index              n_total = 0;
    dealii::types::global_dof_index              first   = 0; // own rows'
    MatrixType                                   G, G_squared;
  };
} // namespace RestShape

#endif
