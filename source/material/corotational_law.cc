#include <deal.II/base/symmetric_tensor.h>

#include <restshape/material/corotational_law.h>

#include <cmath>

namespace RestShape
{
  using namespace dealii;

  LawInfo
  CorotationalLaw::info()
  {
    LawInfo i;
    i.name = "corotational";
    i.description =
      "linear elasticity in the rotated frame of each point (stiffness "
      "constant, fast; cells can collapse under compressive strains of "
      "order one)";
    i.make = law_factory<CorotationalLaw>();
    return i;
  }

  Tensor2
  skew_matrix(const Tensor<1, 3> &w)
  {
    Tensor2 W;
    W[0][1] = -w[2];
    W[0][2] = w[1];
    W[1][0] = w[2];
    W[1][2] = -w[0];
    W[2][0] = -w[1];
    W[2][1] = w[0];
    return W;
  }

  bool
  polar_decomposition(const Tensor2 &F, Tensor2 &R, Tensor2 &S)
  {
    if (!(determinant(F) > 0))
      return false;
    // Scaled Newton iteration X <- (g X + X^-T / g) / 2 (Higham 1986); it
    // converges quadratically to the rotation of F when det F > 0.
    Tensor2 X = F;
    for (unsigned int it = 0; it < 100; ++it)
      {
        const Tensor2 X_inv_T = transpose(invert(X));
        const double  g =
          std::sqrt(std::sqrt(X_inv_T.norm_square() / X.norm_square()));
        const Tensor2 X_new  = 0.5 * (g * X + X_inv_T / g);
        const double  change = (X_new - X).norm();
        X                    = X_new;
        if (change < 1e-14)
          break;
      }
    R = X;
    S = transpose(R) * F;
    S = 0.5 * (S + transpose(S));
    return true;
  }

  void
  CorotationalLaw::project_twist_modes(const Tensor2 &R,
                                       const Tensor2 &S,
                                       const double   tr_E,
                                       Tensor4       &A) const
  {
    // With S = sum_k s_k q_k q_k^T, the rotational variations
    // dF = R skew(q_k) / sqrt(2) are eigenvectors of dP/dF (the "twist"
    // modes of Smith et al. 2019, "Analytic eigensystems for isotropic
    // distortion energies") with eigenvalues
    //   (2 mu (s_i + s_j - 2) + 2 lambda tr E) / (s_i + s_j),  {i, j, k}
    // distinct. They turn negative under compression, the only way the
    // co-rotational tangent loses definiteness (the other six eigenvalues
    // are 2 mu and those of 2 mu I + lambda 1 1^T). Remove the negative ones.
    const auto eig = eigenvectors(symmetrize(S));
    for (unsigned int k = 0; k < 3; ++k)
      {
        const double s_ij  = eig[(k + 1) % 3].first + eig[(k + 2) % 3].first;
        const double value = (2 * mu * (s_ij - 2) + 2 * lambda * tr_E) / s_ij;
        if (value >= 0)
          continue;
        const Tensor2 D =
          (1. / std::sqrt(2.)) * (R * skew_matrix(eig[k].second));
        A -= value * outer_product(D, D);
      }
  }

  namespace
  {
    /// The exact dP/dF of the co-rotational law at P = 2 mu (F - R) +
    /// lambda tr(E) R, M = (tr S I - S)^-1.
    void
    consistent_tangent(const double   mu,
                       const double   lambda,
                       const Tensor2 &R,
                       const Tensor2 &M,
                       const double   tr_E,
                       Tensor4       &A)
    {
      // dP = 2 mu dF + (lambda tr E - 2 mu) dR + lambda tr(R^T dF) R, with
      // dR = R skew(omega), omega = M a and a the axial vector of
      // R^T dF - dF^T R. For dF = e_k (x) e_L: a = e_L x r, r = R^T e_k, and
      // tr(R^T dF) = R_kL; column J of skew(omega) is omega x e_J.
      const double c = lambda * tr_E - 2 * mu;
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int L = 0; L < 3; ++L)
          {
            Tensor<1, 3> e_L;
            e_L[L]                     = 1;
            const Tensor<1, 3> r       = R[k];
            const Tensor<1, 3> omega   = M * cross_product_3d(e_L, r);
            const double       w[3][3] = {{0, omega[2], -omega[1]},
                                          {-omega[2], 0, omega[0]},
                                          {omega[1], -omega[0], 0}};
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int J = 0; J < 3; ++J)
                {
                  const double dR =
                    R[i][0] * w[J][0] + R[i][1] * w[J][1] + R[i][2] * w[J][2];
                  A[i][J][k][L] = c * dR + lambda * R[k][L] * R[i][J];
                }
            A[k][L][k][L] += 2 * mu;
          }
    }

    /// The warped tangent R K0 R^T (no dR term).
    void
    warped_tangent(const double   mu,
                   const double   lambda,
                   const Tensor2 &R,
                   Tensor4       &A)
    {
      // dP = R (2 mu sym(Z) + lambda tr(Z) I), Z = R^T dF.
      const Tensor2 R_T = transpose(R);
      for (unsigned int k = 0; k < 3; ++k)
        for (unsigned int L = 0; L < 3; ++L)
          {
            // dF = e_k (x) e_L; Z = R^T dF has only column L: Z_mL = R_km.
            Tensor2 Z;
            for (unsigned int m = 0; m < 3; ++m)
              Z[m][L] = R_T[m][k];
            const Tensor2 sym_Z = 0.5 * (Z + transpose(Z));
            const Tensor2 dP =
              R * (2 * mu * sym_Z +
                   lambda * trace(Z) * Tensor2(unit_symmetric_tensor<3>()));
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int J = 0; J < 3; ++J)
                A[i][J][k][L] = dP[i][J];
          }
    }
  } // namespace

  CorotationalLaw::CorotationalLaw(const LawParameters &parameters)
    : MaterialLaw(parameters)
  {}

  CorotationalLaw::CorotationalLaw(const double E, const double nu)
    : MaterialLaw(LawParameters{E, nu, {}})
  {}

  bool
  CorotationalLaw::evaluate_isochoric(const Tensor2    &F,
                                      Tensor2          &P,
                                      Tensor4          *tangent,
                                      const TangentType type,
                                      double           *energy) const
  {
    // The law with lambda = -2 mu / 3 at the isochoric part J^-1/3 F
    // (the default's chain rule): mu |S - I|^2 - mu/3 (tr(S - I))^2 of the
    // isochoric stretch, unchanged by a dilation.
    CorotationalLaw deviatoric(*this);
    deviatoric.lambda = -2 * mu / 3;
    return deviatoric.MaterialLaw::evaluate_isochoric(
      F, P, tangent, type, energy);
  }

  bool
  CorotationalLaw::evaluate(const Tensor2    &F,
                            Tensor2          &P,
                            Tensor4          *tangent,
                            const TangentType type,
                            double           *energy) const
  {
    Tensor2 R, S;
    if (!polar_decomposition(F, R, S))
      return false;
    const double tr_E = trace(S) - 3.;
    P                 = 2 * mu * (F - R) + lambda * tr_E * R;
    if (energy != nullptr)
      *energy = mu * (F - R).norm_square() + 0.5 * lambda * tr_E * tr_E;
    if (tangent == nullptr)
      return true;

    if (type == TangentType::warped)
      warped_tangent(mu, lambda, R, *tangent);
    else
      // (tr S I - S)^-1 maps the axial vector of W S + S W to that of W.
      consistent_tangent(mu,
                         lambda,
                         R,
                         invert(trace(S) * unit_symmetric_tensor<3>() - S),
                         tr_E,
                         *tangent);
    if (type == TangentType::projected)
      project_twist_modes(R, S, tr_E, *tangent);
    return true;
  }

} // namespace RestShape
