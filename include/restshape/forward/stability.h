// Whether an equilibrium is stable: the smallest eigenvalues of its
// constrained tangent.
#ifndef restshape_forward_stability_h
#define restshape_forward_stability_h

#include <deal.II/base/point.h>

#include <restshape/base/label_values.h>

#include <string>

namespace RestShape
{
  class ForwardProblem;

  /**
   * The stability of the forward problem's current equilibrium: the
   * eigenvalues lambda (1/s^2, squared angular frequencies) of
   * K x = lambda M x, K the consistent tangent with the constraints of the
   * last Newton step (fixed DoFs; active contact nodes move along the
   * obstacle only), M the lumped mass (HRZ). A stable equilibrium is a
   * local minimum of the potential energy: every lambda > 0.
   */
  struct StabilityResult
  {
    /// The smallest eigenvalue found (1/s^2): the most negative one when
    /// the equilibrium is unstable, else the smallest positive one.
    double smallest_eigenvalue = 0;
    /// Negative eigenvalues found (negative Ritz values of K^-1 M: each
    /// proves one; a lower bound on their number).
    int negative_eigenvalues = 0;
    /// Where the softest mode is largest: mesh position (m) and label.
    dealii::Point<3> peak;
    Label            label = 0;
    /// Solves by the direct solver (else inexact CG solves: a bounded
    /// variant).
    bool exact_solves = true;
    /// Some cells have Density = 0: their mass is a reference density's
    /// (the signs of the eigenvalues do not depend on it).
    bool reference_mass = false;
    /// "eigenvalues against a mass of ..." ("" with the real mass).
    std::string
    mass_text() const;
    /// How it was computed, for a bounded variant ("" with exact solves).
    std::string
    variant_text() const;

    bool
    stable() const
    {
      return negative_eigenvalues == 0 && smallest_eigenvalue > 0;
    }
    /// "stable: smallest eigenvalue ... (... Hz)" or "unstable: ...".
    std::string
    text() const;
  };

  /**
   * Shift-invert Lanczos (K^-1 M, 40 steps with full re-orthogonalisation,
   * one factorisation) at the current equilibrium of @p forward: the
   * eigenvalues nearest zero on both sides. With CG + AMG: a bounded
   * variant (fewer steps, inexact inner solves; variant_text()). Needs a
   * symmetric tangent. Throws SolverFailure if an inner solve fails.
   */
  StabilityResult
  check_stability(ForwardProblem &forward);

  /// Why the check cannot run on @p forward's constrained system ("" if
  /// it can): no free degree of freedom.
  std::string
  free_dofs_missing(const ForwardProblem &forward);
} // namespace RestShape

#endif
