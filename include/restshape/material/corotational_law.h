// The co-rotational linear elastic law.
#ifndef restshape_material_corotational_law_h
#define restshape_material_corotational_law_h

#include <restshape/material/material_law.h>

namespace RestShape
{
  /// The skew matrix W with W v = w x v.
  Tensor2
  skew_matrix(const dealii::Tensor<1, 3> &w);

  /**
   * Polar decomposition F = R S with R a proper rotation and S symmetric,
   * by Higham's scaled Newton iteration. Returns false (and leaves R, S
   * unchanged) if det F <= 0.
   */
  bool
  polar_decomposition(const Tensor2 &F, Tensor2 &R, Tensor2 &S);

  /**
   * Co-rotational linear elasticity (Mueller et al. 2002; the "corotated"
   * model of McAdams et al. 2011 and Sifakis & Barbic 2012):
   *   W(F) = mu |F - R|^2 + lambda/2 tr(S - I)^2,
   *   P    = 2 mu (F - R) + lambda tr(S - I) R.
   * The rotation-free part S of F carries all the stress: a rigid motion
   * gives P = 0 exactly.
   */
  class CorotationalLaw : public MaterialLaw
  {
  public:
    /// Its name, description and factory for the registry.
    static LawInfo
    info();

    explicit CorotationalLaw(const LawParameters &parameters);
    CorotationalLaw(const double youngs_modulus, const double poissons_ratio);

    /**
     * First Piola-Kirchhoff stress and, if @p tangent is not null, dP/dF as
     * A[i][J][k][L] = d P_iJ / d F_kL. consistent: exact derivative (with
     * dR/dF from W S + S W = skew(R^T dF - dF^T R)); projected: consistent
     * with the negative eigenvalues removed; warped: R C0 sym(R^T dF)
     * with R held fixed (SOFA's R K0 R^T). Returns false if det F <= 0.
     */
    bool
    evaluate(const Tensor2    &F,
             Tensor2          &P,
             Tensor4          *tangent,
             const TangentType type,
             double           *energy = nullptr) const override;

    /// The deviatoric part mu |S - I|^2 - mu/3 (tr(S - I))^2 (the law with
    /// lambda = -2 mu/3) of the isochoric stretch S of J^-1/3 F: unchanged
    /// by a dilation, the volume change being the mixed formulation's
    /// volumetric().
    bool
    evaluate_isochoric(const Tensor2    &F,
                       Tensor2          &P,
                       Tensor4          *tangent,
                       const TangentType type,
                       double           *energy = nullptr) const override;

    /**
     * Subtract from the consistent tangent @p A its negative eigenvalues:
     * those of the rotational ("twist") modes R skew(q_k) of compressed
     * points, q_k the eigenvectors of S (projected Newton).
     */
    void
    project_twist_modes(const Tensor2 &R,
                        const Tensor2 &S,
                        const double   tr_E,
                        Tensor4       &A) const;
  };

} // namespace RestShape

#endif
