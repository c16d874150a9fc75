// What Newton's method asks of the problem it solves: its unknowns, the
// constraints of a step, and the assembly of the residual, the tangent and
// the energy. ForwardProblem implements it; NewtonSolver knows only this.
#ifndef restshape_solver_newton_system_h
#define restshape_solver_newton_system_h

#include <deal.II/lac/affine_constraints.h>

#include <restshape/base/tangent_type.h>
#include <restshape/solver/linear_solver.h>

#include <string>

namespace RestShape
{
  /**
   * A nonlinear system R(d) = f_ext - f_int(d) = 0 whose residual is the
   * negative gradient of a potential energy (where the loads are
   * conservative). Newton asks for the step constraints first, then
   * assembles at the unknowns it sets; the assembled vectors are those of
   * the last assembly.
   */
  class NewtonSystem
  {
  public:
    virtual ~NewtonSystem() = default;

    /// The unknowns (owned entries, m); after changing them, call
    /// unknowns_changed() before the next assembly.
    virtual VectorType &
    unknowns() = 0;
    /// The unknowns with ghost entries (as of the last unknowns_changed()).
    virtual const VectorType &
    ghosted_unknowns() const = 0;
    virtual void
    unknowns_changed() = 0;

    /// Build the constraints of the next step (fixed DoFs, hanging nodes,
    /// the active set) and return them.
    virtual const dealii::AffineConstraints<double> &
    make_step_constraints() = 0;
    /// The tangent the next assemblies use (never `adaptive`).
    virtual void
    set_tangent_type(const TangentType type) = 0;

    /// Assemble the residual and the energy at the unknowns; false if a
    /// cell is inverted there.
    virtual bool
    assemble_residual() = 0;
    /// The same, and the tangent and the step's right-hand side.
    virtual bool
    assemble_step() = 0;

    /// The residual with the step constraints condensed (N).
    virtual const VectorType &
    condensed_residual() const = 0;
    /// The residual condensed for hanging nodes only: minus the support
    /// and contact forces at constrained DoFs (N).
    virtual const VectorType &
    raw_residual() const = 0;
    /// The external forces, condensed (N): the reference of |R|.
    virtual const VectorType &
    external_forces() const = 0;
    /// The total potential energy (J).
    virtual double
    energy() const = 0;
    /// The tangent of the last assemble_step() (constraints condensed).
    virtual MatrixType &
    step_matrix() = 0;
    /// The right-hand side of the last assemble_step(): the residual and
    /// the constraints' inhomogeneities.
    virtual const VectorType &
    step_rhs() const = 0;

    /// What an assembly leaves, to be put back after a trial.
    struct Assembled
    {
      VectorType raw, condensed, external;
      double     energy = 0;
    };
    virtual Assembled
    assembled() const = 0;
    virtual void
    restore(const Assembled &a) = 0;
    /// The unknowns start again from a state of their own (a load step's
    /// start, a checkpoint): what the system predicted from its last
    /// steps no longer applies.
    virtual void
    unknowns_restarted()
    {}

    /// The smallest change of an unknown the state resolves through its
    /// deformation gradient: eps times the smallest cell diameter (m).
    virtual double
    resolution() const = 0;
    /// "3 cells inverted (det F <= 0), e.g. label 1 at ..." of the last
    /// assembly that met inverted cells.
    virtual std::string
    inverted_cells_text() const = 0;
    /// "det F = 0.16, label 1 at (x, y, z) mm of the mesh": the most
    /// compressed cell of the current state.
    virtual std::string
    compression_text() const = 0;
  };
} // namespace RestShape

#endif
