// The interface of a material law at one quadrature point.
#ifndef restshape_material_material_law_h
#define restshape_material_material_law_h

#include <deal.II/base/tensor.h>

#include <restshape/base/tangent_type.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace RestShape
{
  using Tensor2 = dealii::Tensor<2, 3>;
  using Tensor4 = dealii::Tensor<4, 3>;

  /// What a law is given for one label: its small-strain moduli, and the
  /// values of the parameters the law declares itself (LawParameter).
  struct LawParameters
  {
    double youngs_modulus = 0; // Pa
    double poissons_ratio = 0; // -
    /// By parameter name (e.g. "Ogden alpha").
    std::map<std::string, double> values;

    /// The value of @p name, or @p fallback where it was not given.
    double
    value(const std::string &name, const double fallback) const
    {
      const auto v = values.find(name);
      return v == values.end() ? fallback : v->second;
    }
  };

  /// A parameter of a law, declared in subsection Materials with a value
  /// per label (one value or a 'label:value' list).
  struct LawParameter
  {
    std::string name;          // "Ogden alpha"
    std::string default_value; // "-19"
    std::string help;          // what it does, its unit, its range
    std::string symbol;        // its name in an error: "alpha = 0 ..."
    /// What is expected of a value ("a nonzero exponent with |alpha| <=
    /// 100"), or "" if @p value is admissible.
    std::function<std::string(double)> check;
  };

  /**
   * A hyperelastic law W(F): the first Piola-Kirchhoff stress P = dW/dF and
   * its tangent A[i][J][k][L] = d P_iJ / d F_kL. Every law is parameterised
   * by Young's modulus and Poisson's ratio, its linearisation at F = I
   * (Lame parameters mu and lambda). Laws are created by name
   * (law_registry.h) and chosen per label by Materials/Material law.
   */
  class MaterialLaw
  {
  public:
    explicit MaterialLaw(const LawParameters &parameters);
    virtual ~MaterialLaw() = default;

    /**
     * P at @p F and, if @p tangent is not null, dP/dF of the kind @p type:
     * consistent (exact), projected (exact with its negative eigenvalues
     * removed) or warped (a law's simplified tangent where it has one,
     * else the exact one). Returns false (an inverted point) if det F <= 0.
     * @p energy, if not null, gets W(F) (J/m^3).
     */
    virtual bool
    evaluate(const Tensor2    &F,
             Tensor2          &P,
             Tensor4          *tangent,
             const TangentType type,
             double           *energy = nullptr) const = 0;

    /// W(F) (J/m^3), infinity where det F <= 0.
    double
    energy_density(const Tensor2 &F) const;

    /**
     * The law's part at constant volume, for the mixed formulation
     * (Discretization/Formulation = mixed), where the volume change is
     * volumetric()'s: W_iso(F), unchanged by a dilation (W_iso(a F) =
     * W_iso(F), a > 0), with its stress P = dW_iso/dF and, if @p tangent
     * is not null, its derivative. By default the law at the isochoric
     * part of F, W_iso(F) = W(J^-1/3 F) (for the hyperelastic laws the
     * terms of ln J vanish there: neo-Hookean mu/2 (J^-2/3 tr C - 3)),
     * with the chain rule's exact derivatives. false if det F <= 0.
     */
    virtual bool
    evaluate_isochoric(const Tensor2    &F,
                       Tensor2          &P,
                       Tensor4          *tangent,
                       const TangentType type,
                       double           *energy = nullptr) const;

    /// The volumetric energy of the mixed formulation U(J) = K/2 (ln J)^2
    /// (J/m^3) and its derivatives dU/dJ (Pa) and d^2U/dJ^2, K the bulk
    /// modulus.
    struct Volumetric
    {
      double U = 0, dU = 0, d2U = 0;
    };
    Volumetric
    volumetric(const double J) const;

    /// Lame parameters of the linearisation at F = I (Pa).
    double mu     = 0;
    double lambda = 0;
    /// Bulk modulus K = lambda + 2 mu / 3 (Pa).
    double bulk_modulus = 0;
  };

  /// What the registry (law_registry.h) knows of a law; a law class gives
  /// it by a static info().
  struct LawInfo
  {
    /// The name Materials/Material law takes ("neo-Hookean").
    std::string name;
    /// What it is, for the help of Materials/Material law and the manual:
    /// its energy and where it serves.
    std::string description;
    /// Makes the law for one label.
    std::function<std::unique_ptr<MaterialLaw>(const LawParameters &)> make;
    /// Its own parameters (subsection Materials), if any.
    std::vector<LawParameter> parameters = {};
  };

  /// The factory of a law class constructed from LawParameters.
  template <typename Law>
  std::function<std::unique_ptr<MaterialLaw>(const LawParameters &)>
  law_factory()
  {
    return [](const LawParameters &p) { return std::make_unique<Law>(p); };
  }

  /**
   * Remove the negative eigenvalues of a tangent (as a symmetric 9 x 9
   * matrix of the pairs (iJ), (kL)): the projected Newton tangent of any
   * law.
   */
  void
  project_negative_eigenvalues(Tensor4 &A);
} // namespace RestShape

#endif
