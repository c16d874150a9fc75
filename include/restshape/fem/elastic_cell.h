// The material law's part of one cell's residual and tangent, summed over
// the cell's quadrature points by the scalar shape functions of the
// element (a system of 3 copies of one scalar element): each scalar
// function's gradient is transformed once per point, not once per vector
// component, and the tangent is summed in 3 x 3 blocks, one per pair of
// scalar functions, in flat arrays the compiler can vectorise. Each entry
// gets the same products, added in the same order, as a loop over the
// vector element's shape functions: the same numbers.
#ifndef restshape_fem_elastic_cell_h
#define restshape_fem_elastic_cell_h

#include <deal.II/base/tensor.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <utility>
#include <vector>

namespace RestShape
{
  class ElasticCell
  {
  public:
    /// For the shape functions of @p fe (3 copies of one scalar element).
    explicit ElasticCell(const dealii::FiniteElement<3> &fe);

    /// What one quadrature point contributes.
    struct Point
    {
      unsigned int                q;       // its index in the FEValues
      dealii::Tensor<2, 3>        G_inv_T; // (d X_rest / d X)^-T
      dealii::Tensor<2, 3>        P;       // first Piola-Kirchhoff stress
      const dealii::Tensor<4, 3> *A;       // dP/dF, or null (no tangent)
      double                      JxW;     // mesh volume weight (m^3)
      double                      dV_rest; // rest volume weight (m^3)
      dealii::Tensor<1, 3>        f_body;  // body force (N/m^3 of mesh)
      /// Mixed formulation: J F^-T = dJ/dF at the point, whose integral
      /// against the shape functions is the gradient of the cell's volume
      /// (null: displacement formulation).
      const dealii::Tensor<2, 3> *dJ = nullptr;
      /// With dJ: the values at the point of the cell's pressure modes
      /// (reinit()'s number of them; null: one mode, the constant 1).
      const double *modes = nullptr;
    };

    /// Start a cell; @p magnitudes: also sum |f_ext| + |f_int|; @p
    /// pressure_modes: how many volume gradients to sum (mixed formulation,
    /// at most max_pressure_modes).
    void
    reinit(const bool magnitudes, const unsigned int pressure_modes);
    static constexpr unsigned int max_pressure_modes = 4;

    /// Add the point @p p, @p values being of the scalar element (an
    /// FEValues or a SimplexValues).
    template <typename Values>
    void
    add(const Values &values, const Point &p)
    {
      const dealii::Tensor<2, 3> &G = p.G_inv_T;
      for (unsigned int k = 0; k < n_scalar; ++k)
        {
          const dealii::Tensor<1, 3> &g = values.shape_grad(k, p.q);
          for (unsigned int L = 0; L < 3; ++L)
            b[L * n_scalar + k] =
              (G[L][0] * g[0] + G[L][1] * g[1]) + G[L][2] * g[2];
          phi[k] = values.shape_value(k, p.q);
        }
      add_terms(p);
    }

    /// The cell's f_ext - f_int, f_ext and, if asked at reinit(), the
    /// magnitudes, by the vector element's shape functions.
    void
    vectors(dealii::Vector<double> &rhs,
            dealii::Vector<double> &external,
            dealii::Vector<double> &magnitude) const;

    /// The cell's tangent -d(f_ext - f_int)/du (symmetric; the body force
    /// does not depend on u), overwriting @p matrix.
    void
    matrix(dealii::FullMatrix<double> &matrix) const;

    /// Mixed formulation: add @p factor g g^T to @p matrix (after
    /// matrix()), g the cell's integral of dJ against the shape functions
    /// (the derivative of its current volume): the stiffness of its mean
    /// dilatation, factor = U''(J_mean) / V_rest.
    void
    add_volumetric_stiffness(dealii::FullMatrix<double> &matrix,
                             const double                factor) const;
    /// With several pressure modes: add sum_ab @p stiffness_ab G_a G_b^T,
    /// G_a the integral of dJ against the shape functions weighted by the
    /// mode N_a.
    void
    add_volumetric_stiffness(dealii::FullMatrix<double>       &matrix,
                             const dealii::FullMatrix<double> &stiffness) const;

    /// The volume gradient G_@p mode of the points added (mixed
    /// formulation; mode 0 with Point::modes null: g = dv/dd), in the
    /// cell's local DoF order (m^2).
    void
    volume_gradient_in_dof_order(std::vector<double> &g,
                                 const unsigned int   mode) const;

  private:
    /// The point's terms, with b and phi set.
    void
    add_terms(const Point &p);
    void
    add_residual(const Point &p);
    void
    add_tangent(const Point &p);

    unsigned int n_scalar;
    /// The vector element's shape function of (component c, scalar k):
    /// index[c * n_scalar + k].
    std::vector<unsigned int> index;
    bool                      magnitudes = false;
    bool                      first      = true; // no point added yet
    /// Per scalar function k: its rest-configuration gradient
    /// b[L n_scalar + k], and its value phi[k], at the current point.
    std::vector<double> b, phi;
    /// Per scalar function k: v[30 k + 10 K + 3 cj + ci] =
    /// dV_rest sum_L A[ci][K][cj][L] b_k[L] (10 entries per K, 9 used).
    std::vector<double> v;
    /// Per pair k >= l of scalar functions, 10 entries [3 cj + ci] (9 used):
    /// the tangent's entry of (ci, k), (cj, l).
    std::vector<double> blocks;
    /// Each entry of the cell matrix (row-major) and where in blocks it
    /// is: the matrix is a gather.
    std::vector<std::pair<unsigned int, unsigned int>> copies;
    /// By (component c, scalar k), c * n_scalar + k.
    std::vector<double> rhs, external, magnitude;
    /// By (mode a, component c, scalar k), a 3 n_scalar + c n_scalar + k:
    /// the integral of dJ (Point::dJ) weighted by the mode.
    std::vector<double> volume_gradient;
    unsigned int        n_modes = 1;
  };
} // namespace RestShape

#endif
