// Every material law of the registry (Materials/Material law):
//
// 1. Its tangent against central differences of P, and P against central
//    differences of W (consistent tangent, a general deformation).
// 2. Objectivity: W(Q F) = W(F), P(Q F) = Q P(F); a rigid rotation is
//    stress-free; at small strain P is linear elasticity with the label's
//    mu and lambda.
// 3. The projected tangent has no negative eigenvalue and is the exact one
//    where that is positive definite.
// 4. The neo-Hookean law against its closed forms: simple shear (Cauchy
//    stress mu gamma and mu gamma^2), confined compression, uniaxial
//    stretch with nu = 0 (no lateral stress at lateral stretch 1) and a
//    uniform dilatation.
// 5. The Ogden law: alpha = 2 gives the neo-Hookean law (stress and
//    tangent), uniaxial stretch with nu = 0 against its closed form, the
//    tangent where stretches coincide (F = I, a uniaxial stretch).
// 6. The Mooney-Rivlin law: r = 0 is the neo-Hookean law; simple shear
//    against its closed forms (shear stress and both normal stress
//    differences).
// 7. An unknown law's name is an error that lists the laws.
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <restshape/material/law_registry.h>
#include <restshape/material/material_table.h>

#include <cmath>

#include "checks.h"
#include "test_utilities.h"

using namespace dealii;
using namespace RestShape;
using namespace RestShape::Test;

namespace
{
  constexpr double E = 1500, nu = 0.45;

  /// A general deformation with det F > 0 (stretch, shear, rotation).
  Tensor2
  general_F()
  {
    Tensor2      F;
    const double values[3][3] = {{1.21, 0.13, -0.07},
                                 {-0.09, 0.86, 0.18},
                                 {0.05, -0.11, 1.07}};
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        F[i][j] = values[i][j];
    return F;
  }

  Tensor2
  rotation(const double angle, Tensor<1, 3> axis)
  {
    axis /= axis.norm();
    const Tensor2 K = skew_matrix(axis);
    return Tensor2(unit_symmetric_tensor<3>()) + std::sin(angle) * K +
           (1 - std::cos(angle)) * K * K;
  }

  double
  stress_error(const MaterialLaw &law, const Tensor2 &F)
  {
    Tensor2 P;
    law.evaluate(F, P, nullptr, TangentType::consistent);
    double error = 0;
    for (unsigned int k = 0; k < 3; ++k)
      for (unsigned int L = 0; L < 3; ++L)
        {
          constexpr double h  = 1e-6;
          Tensor2          Fp = F, Fm = F;
          Fp[k][L] += h;
          Fm[k][L] -= h;
          const double fd =
            (law.energy_density(Fp) - law.energy_density(Fm)) / (2 * h);
          error = std::max(error, std::abs(fd - P[k][L]));
        }
    return error / P.norm();
  }

  double
  smallest_eigenvalue(const Tensor4 &A)
  {
    LAPACKFullMatrix<double> M(9, 9);
    for (unsigned int a = 0; a < 9; ++a)
      for (unsigned int b = 0; b < 9; ++b)
        M(a, b) = A[a / 3][a % 3][b / 3][b % 3];
    Vector<double>     values;
    FullMatrix<double> vectors;
    M.compute_eigenvalues_symmetric(-1e300, 1e300, 0., values, vectors);
    return values.size() == 0 ? 0. : values[0];
  }

  void
  general_checks(const std::string &name)
  {
    const auto    law = create_material_law(name, LawParameters{E, nu, {}});
    const Tensor2 F   = general_F();
    const Tensor2 Q   = rotation(0.7, Tensor<1, 3>({1., -2., 0.5}));
    check_below(name + ": tangent against differences of P",
                tangent_error(*law, F),
                1e-6);
    check_below(name + ": tangent against differences of P, compressed",
                tangent_error(*law, 0.7 * F),
                1e-6);
    check_below(name + ": P against differences of W",
                stress_error(*law, F),
                1e-6);
    Tensor2 P, P_rotated, P_rigid;
    law->evaluate(F, P, nullptr, TangentType::consistent);
    law->evaluate(Q * F, P_rotated, nullptr, TangentType::consistent);
    law->evaluate(Q, P_rigid, nullptr, TangentType::consistent);
    check_below(name + ": P(Q F) = Q P(F)",
                (P_rotated - Q * P).norm() / P.norm(),
                1e-12);
    check_below(name + ": W(Q F) = W(F)",
                std::abs(law->energy_density(Q * F) - law->energy_density(F)) /
                  law->energy_density(F),
                1e-12);
    check_below(name + ": a rigid rotation is stress-free",
                P_rigid.norm() / E,
                1e-12);
    // Small strain: linear elasticity.
    Tensor2 H = general_F() - Tensor2(unit_symmetric_tensor<3>());
    H *= 1e-6;
    law->evaluate(Tensor2(unit_symmetric_tensor<3>()) + H,
                  P,
                  nullptr,
                  TangentType::warped);
    const Tensor2 linear =
      2 * law->mu * Tensor2(symmetrize(H)) +
      law->lambda * trace(H) * Tensor2(unit_symmetric_tensor<3>());
    check_below(name + ": small strain is linear elasticity",
                (P - linear).norm() / linear.norm(),
                1e-5);
    check_between(name + ": mu from E and nu (Pa)",
                  law->mu,
                  E / (2 * (1 + nu)) * (1 - 1e-12),
                  E / (2 * (1 + nu)) * (1 + 1e-12));
    // Projected tangent: in compression and in dilatation, where the exact
    // tangents of the laws lose definiteness (one of them at least must).
    Tensor4 A, A_projected;
    double  exact = 1e300, projected = 1e300, size = 0;
    for (const double scale : {0.6, 1.4})
      {
        law->evaluate(scale * F, P, &A, TangentType::consistent);
        law->evaluate(scale * F, P, &A_projected, TangentType::projected);
        exact     = std::min(exact, smallest_eigenvalue(A));
        projected = std::min(projected, smallest_eigenvalue(A_projected));
        size      = std::max(size, A.norm());
      }
    check_between(name + ": exact tangent indefinite, smallest eigenvalue / mu",
                  exact / law->mu,
                  -1e10,
                  -1e-3);
    check_between(name + ": projected tangent, smallest eigenvalue / |A|",
                  projected / size,
                  -1e-13,
                  1e10);
    law->evaluate(F, P, &A, TangentType::consistent);
    law->evaluate(F, P, &A_projected, TangentType::projected);
    if (smallest_eigenvalue(A) > 0)
      check_below(name + ": projected = exact where that is positive",
                  (A - A_projected).norm() / A.norm(),
                  1e-10);
  }

  Tensor2
  diagonal(const double a, const double b, const double c)
  {
    Tensor2 F;
    F[0][0] = a;
    F[1][1] = b;
    F[2][2] = c;
    return F;
  }

  void
  neo_hookean_closed_forms()
  {
    const auto   law    = create_material_law("neo-Hookean", {E, nu, {}});
    const double mu     = law->mu;
    const double lambda = law->lambda;
    const double gamma  = 0.8;
    Tensor2      F      = diagonal(1, 1, 1);
    Tensor2      P;
    F[0][1] = gamma;
    law->evaluate(F, P, nullptr, TangentType::consistent);
    const SymmetricTensor<2, 3> sigma = cauchy_stress(F, P);
    check_below("neo-Hookean simple shear: sigma_12 = mu gamma",
                std::abs(sigma[0][1] - mu * gamma) / (mu * gamma),
                1e-12);
    check_below("neo-Hookean simple shear: sigma_11 = mu gamma^2",
                std::abs(sigma[0][0] - mu * gamma * gamma) / (mu * gamma),
                1e-12);
    check_below("neo-Hookean simple shear: sigma_22 = sigma_33 = 0",
                (std::abs(sigma[1][1]) + std::abs(sigma[2][2])) / mu,
                1e-12);

    const double stretch = 0.55;
    law->evaluate(diagonal(stretch, 1, 1), P, nullptr, TangentType::warped);
    const double ln_s = std::log(stretch);
    check_below("neo-Hookean confined compression: P_11",
                std::abs(P[0][0] - (mu * (stretch - 1 / stretch) +
                                    lambda * ln_s / stretch)) /
                  mu,
                1e-12);
    check_below("neo-Hookean confined compression: P_22 = lambda ln(stretch)",
                std::abs(P[1][1] - lambda * ln_s) / mu,
                1e-12);

    const auto free_law = create_material_law("neo-Hookean", {E, 0., {}});
    free_law->evaluate(diagonal(1.7, 1, 1), P, nullptr, TangentType::warped);
    check_below("neo-Hookean uniaxial stretch, nu = 0: P_11 = mu (s - 1/s)",
                std::abs(P[0][0] - free_law->mu * (1.7 - 1 / 1.7)) / E,
                1e-12);
    check_below("neo-Hookean uniaxial stretch, nu = 0: no lateral stress",
                (std::abs(P[1][1]) + std::abs(P[2][2])) / E,
                1e-12);

    const double s = 0.8;
    law->evaluate(diagonal(s, s, s), P, nullptr, TangentType::warped);
    const double p = mu * (s - 1 / s) + 3 * lambda * std::log(s) / s;
    check_below("neo-Hookean uniform dilatation: P = p I",
                (P - p * Tensor2(unit_symmetric_tensor<3>())).norm() / mu,
                1e-12);
    Tensor4 A;
    check_below("neo-Hookean: det F <= 0 is refused",
                law->evaluate(diagonal(-0.1, 1, 1), P, &A, TangentType::warped),
                0);
  }
  void
  ogden_closed_forms()
  {
    // alpha = 2 is the neo-Hookean law, stress and tangent.
    LawParameters two{E, nu, {{"Ogden alpha", 2.}}};
    const auto    ogden = create_material_law("Ogden", two);
    const auto    neo   = create_material_law("neo-Hookean", two);
    Tensor2       P_ogden, P_neo;
    Tensor4       A_ogden, A_neo;
    for (const double scale : {0.7, 1.0, 1.3})
      {
        const Tensor2 F = scale * general_F();
        ogden->evaluate(F, P_ogden, &A_ogden, TangentType::consistent);
        neo->evaluate(F, P_neo, &A_neo, TangentType::consistent);
        check_below("Ogden with alpha = 2 is neo-Hookean: P, scale " +
                      std::to_string(scale),
                    (P_ogden - P_neo).norm() / P_neo.norm(),
                    1e-12);
        check_below("Ogden with alpha = 2 is neo-Hookean: tangent, scale " +
                      std::to_string(scale),
                    (A_ogden - A_neo).norm() / A_neo.norm(),
                    1e-10);
      }
    // Near F = I (nearly equal stretches, the divided differences of the
    // tangent at their limit): still the neo-Hookean law.
    for (const double eps : {0., 1e-12, 1e-8, 1e-4})
      {
        const Tensor2 F =
          Tensor2(unit_symmetric_tensor<3>()) + eps * general_F();
        ogden->evaluate(F, P_ogden, &A_ogden, TangentType::consistent);
        neo->evaluate(F, P_neo, &A_neo, TangentType::consistent);
        check_below("Ogden with alpha = 2 near F = I: P - P_neo-Hookean, "
                    "relative to mu, eps " +
                      std::to_string(eps),
                    (P_ogden - P_neo).norm() / neo->mu,
                    1e-12);
        check_below("Ogden with alpha = 2 near F = I: tangent, eps " +
                      std::to_string(eps),
                    (A_ogden - A_neo).norm() / A_neo.norm(),
                    1e-8);
      }
    // Uniaxial stretch with nu = 0: no lateral stress at lateral stretch 1,
    // P_11 = 2 mu / alpha (s^(alpha - 1) - 1/s); and at a repeated
    // eigenvalue (the lateral ones) the tangent is still exact.
    for (const double alpha : {-19., 5.})
      {
        const auto law =
          create_material_law("Ogden",
                              LawParameters{E, 0., {{"Ogden alpha", alpha}}});
        Tensor2 F = diagonal(0.8, 1, 1), P;
        law->evaluate(F, P, nullptr, TangentType::warped);
        const double P_11 =
          2 * law->mu / alpha * (std::pow(0.8, alpha - 1) - 1 / 0.8);
        const std::string a = " (alpha = " + std::to_string(int(alpha)) + ")";
        check_below("Ogden uniaxial, nu = 0: P_11" + a,
                    std::abs(P[0][0] - P_11) / std::abs(P_11),
                    1e-12);
        check_below("Ogden uniaxial, nu = 0: no lateral stress" + a,
                    (std::abs(P[1][1]) + std::abs(P[2][2])) / std::abs(P_11),
                    1e-12);
        check_below("Ogden tangent at repeated stretches" + a,
                    tangent_error(*law, F),
                    1e-6);
        check_below("Ogden tangent at F = I" + a,
                    tangent_error(*law, diagonal(1, 1, 1)),
                    1e-6);
      }
  }
  /// The Mooney-Rivlin law: r = 0 is the neo-Hookean law; simple shear
  /// (isochoric) against its closed forms, the Cauchy shear stress
  /// mu gamma and the normal stress differences sigma_11 - sigma_22 =
  /// mu gamma^2 and sigma_22 - sigma_33 = -2 C01 gamma^2 (the second
  /// invariant's signature; neo-Hookean: 0).
  void
  mooney_rivlin_closed_forms()
  {
    const LawParameters zero{E, nu, {{"Mooney-Rivlin ratio", 0.}}};
    const auto          mooney = create_material_law("Mooney-Rivlin", zero);
    const auto          neo    = create_material_law("neo-Hookean", zero);
    Tensor2             P_mooney, P_neo;
    Tensor4             A_mooney, A_neo;
    for (const double scale : {0.7, 1.0, 1.3})
      {
        const Tensor2 F = scale * general_F();
        mooney->evaluate(F, P_mooney, &A_mooney, TangentType::consistent);
        neo->evaluate(F, P_neo, &A_neo, TangentType::consistent);
        check_below("Mooney-Rivlin with r = 0 is neo-Hookean: P, scale " +
                      std::to_string(scale),
                    (P_mooney - P_neo).norm() / P_neo.norm(),
                    1e-12);
        check_below("Mooney-Rivlin with r = 0 is neo-Hookean: tangent, "
                    "scale " +
                      std::to_string(scale),
                    (A_mooney - A_neo).norm() / A_neo.norm(),
                    1e-12);
      }
    const double r = 0.3;
    const auto   law =
      create_material_law("Mooney-Rivlin",
                          LawParameters{E, nu, {{"Mooney-Rivlin ratio", r}}});
    const double mu = law->mu, c01 = r * mu / 2;
    for (const double gamma : {0.1, 0.5, 1.0})
      {
        Tensor2 F = unit_symmetric_tensor<3>(), P;
        F[0][1]   = gamma;
        law->evaluate(F, P, nullptr, TangentType::consistent);
        const SymmetricTensor<2, 3> sigma = cauchy_stress(F, P);
        const std::string g = " (gamma = " + std::to_string(gamma) + ")";
        check_below("Mooney-Rivlin simple shear: sigma_12 = mu gamma" + g,
                    std::abs(sigma[0][1] - mu * gamma) / (mu * gamma),
                    1e-12);
        check_below("Mooney-Rivlin simple shear: sigma_11 - sigma_22 = mu "
                    "gamma^2" +
                      g,
                    std::abs(sigma[0][0] - sigma[1][1] - mu * gamma * gamma) /
                      (mu * gamma * gamma),
                    1e-12);
        check_below("Mooney-Rivlin simple shear: sigma_22 - sigma_33 = -2 "
                    "C01 gamma^2" +
                      g,
                    std::abs(sigma[1][1] - sigma[2][2] +
                             2 * c01 * gamma * gamma) /
                      (c01 * gamma * gamma),
                    1e-11);
      }
  }

  /// The isochoric part W_iso(F) of a law and the volumetric U(J) of the
  /// mixed formulation: exact derivatives (against central differences),
  /// W_iso unchanged by a dilation and a rotation, and W_iso + U(J) linear
  /// elasticity with the law's mu and bulk modulus at small strain.
  void
  isochoric_checks(const std::string &name)
  {
    const auto law   = create_material_law(name, LawParameters{E, nu, {}});
    const auto W_iso = [&](const Tensor2 &F) {
      Tensor2 P;
      double  W = 0;
      law->evaluate_isochoric(F, P, nullptr, TangentType::consistent, &W);
      return W;
    };
    const auto P_iso = [&](const Tensor2 &F) {
      Tensor2 P;
      law->evaluate_isochoric(F, P, nullptr, TangentType::consistent);
      return P;
    };
    constexpr double h = 1e-6;
    for (const double scale : {1.0, 0.7})
      {
        const Tensor2 F = scale * general_F();
        Tensor2       P;
        Tensor4       A;
        law->evaluate_isochoric(F, P, &A, TangentType::consistent);
        double stress = 0, tangent = 0;
        for (unsigned int k = 0; k < 3; ++k)
          for (unsigned int L = 0; L < 3; ++L)
            {
              Tensor2 Fp = F, Fm = F;
              Fp[k][L] += h;
              Fm[k][L] -= h;
              stress =
                std::max(stress,
                         std::abs((W_iso(Fp) - W_iso(Fm)) / (2 * h) - P[k][L]));
              const Tensor2 dP = (P_iso(Fp) - P_iso(Fm)) / (2 * h);
              for (unsigned int i = 0; i < 3; ++i)
                for (unsigned int J = 0; J < 3; ++J)
                  tangent =
                    std::max(tangent, std::abs(dP[i][J] - A[i][J][k][L]));
            }
        const std::string at = " (F scaled by " + std::to_string(scale) + ")";
        check_below(name + ": isochoric P against differences of W_iso" + at,
                    stress / P.norm(),
                    1e-6);
        check_below(name + ": isochoric tangent against differences of P" + at,
                    tangent / A.norm(),
                    1e-6);
      }
    const Tensor2 F = general_F();
    const Tensor2 Q = rotation(0.7, Tensor<1, 3>({1., -2., 0.5}));
    check_below(name + ": W_iso(a F) = W_iso(F)",
                std::abs(W_iso(1.3 * F) - W_iso(F)) / W_iso(F),
                1e-12);
    check_below(name + ": P_iso(a F) = P_iso(F) / a",
                (1.3 * P_iso(1.3 * F) - P_iso(F)).norm() / P_iso(F).norm(),
                1e-12);
    check_below(name + ": W_iso(Q F) = W_iso(F)",
                std::abs(W_iso(Q * F) - W_iso(F)) / W_iso(F),
                1e-12);
    // Small strain: W_iso + U is linear elasticity with mu and K.
    const Tensor2 I = unit_symmetric_tensor<3>();
    Tensor2       H = general_F() - I;
    H *= 1e-6;
    const Tensor2 F_small = I + H;
    const double  J       = determinant(F_small);
    const Tensor2 P_small =
      P_iso(F_small) + law->volumetric(J).dU * J * transpose(invert(F_small));
    const double  K      = law->bulk_modulus;
    const Tensor2 linear = 2 * law->mu * Tensor2(symmetrize(H)) +
                           (K - 2 * law->mu / 3) * trace(H) * I;
    check_below(name + ": W_iso + U(J) at small strain is linear elasticity",
                (P_small - linear).norm() / linear.norm(),
                1e-5);
    check_below(name + ": bulk modulus E / (3 (1 - 2 nu))",
                std::abs(K - E / (3 * (1 - 2 * nu))) / K,
                1e-12);
    for (const double j : {0.8, 1.0, 1.25})
      {
        const auto v = law->volumetric(j), vp = law->volumetric(j + h),
                   vm = law->volumetric(j - h);
        check_below(name + ": dU/dJ and d2U/dJ2 against differences, J = " +
                      std::to_string(j),
                    std::abs((vp.U - vm.U) / (2 * h) - v.dU) / K +
                      std::abs((vp.dU - vm.dU) / (2 * h) - v.d2U) / K,
                    1e-6);
      }
  }
} // namespace

int
main()
{
  for (const std::string &name : material_law_names())
    {
      general_checks(name);
      isochoric_checks(name);
    }
  neo_hookean_closed_forms();
  ogden_closed_forms();
  mooney_rivlin_closed_forms();
  const std::string error = checks::error_of(
    [] { material_law_index("Mooney", "Materials/Material law"); });
  check_below("an unknown law names the laws: '" + error + "'",
              error.find("corotational, neo-Hookean") == std::string::npos,
              0);
  return exit_code();
}
