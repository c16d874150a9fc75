// ElasticCell: the material law's part of a cell's residual and tangent,
// summed by scalar shape functions in flat arrays.
#include <restshape/forward/elastic_cell.h>

#include <algorithm>
#include <cmath>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    // Sizes padded to even numbers, so that the loops below run in pairs of
    // doubles (vectorised without a remainder): a slice of 9 entries
    // (cj, ci) takes 10.
    constexpr unsigned int slice      = 10;        // (cj, ci), padded
    constexpr unsigned int block_size = slice;     // of a pair of functions
    constexpr unsigned int v_size     = 3 * slice; // (K, cj, ci) of one

    /// out = first ? s : out + s, s[m] = (v[m] b0 + v[10 + m] b1) +
    /// v[20 + m] b2: one block of a pair of scalar functions.
    void
    add_block(const double *__restrict v,
              const double b0,
              const double b1,
              const double b2,
              const bool   first,
              double *__restrict out)
    {
      if (first)
        for (unsigned int m = 0; m < slice; ++m)
          out[m] = (v[m] * b0 + v[slice + m] * b1) + v[2 * slice + m] * b2;
      else
        for (unsigned int m = 0; m < slice; ++m)
          out[m] += (v[m] * b0 + v[slice + m] * b1) + v[2 * slice + m] * b2;
    }

    /// v = ((At[r] b0 + At[30 + r] b1) + At[60 + r] b2) dV: the products
    /// of one scalar function.
    void
    contract(const double *__restrict At,
             const double b0,
             const double b1,
             const double b2,
             const double dV,
             double *__restrict v)
    {
      for (unsigned int r = 0; r < v_size; ++r)
        v[r] =
          ((At[r] * b0 + At[v_size + r] * b1) + At[2 * v_size + r] * b2) * dV;
    }

    /// The position of the pair k >= l among the pairs of scalar functions.
    unsigned int
    pair_index(const unsigned int k, const unsigned int l)
    {
      return k * (k + 1) / 2 + l;
    }
  } // namespace

  ElasticCell::ElasticCell(const FiniteElement<3> &fe)
    : n_scalar(fe.base_element(0).n_dofs_per_cell())
    , index(3 * n_scalar)
    , b(3 * n_scalar)
    , v(v_size * n_scalar)
    , blocks(block_size * pair_index(n_scalar, 0))
    , rhs(3 * n_scalar)
    , external(3 * n_scalar)
    , magnitude(3 * n_scalar)
  {
    AssertThrow(fe.n_base_elements() == 1 && fe.n_components() == 3 &&
                  fe.element_multiplicity(0) == 3,
                ExcMessage("expected 3 copies of one scalar element"));
    for (unsigned int c = 0; c < 3; ++c)
      for (unsigned int k = 0; k < n_scalar; ++k)
        index[c * n_scalar + k] = fe.component_to_system_index(c, k);
  }

  void
  ElasticCell::reinit(const bool sum_magnitudes)
  {
    magnitudes = sum_magnitudes;
    first      = true;
  }

  void
  ElasticCell::add(const FEValues<3> &fe_values, const Point &p)
  {
    for (unsigned int k = 0; k < n_scalar; ++k)
      {
        const Tensor<1, 3> g = p.G_inv_T * fe_values.shape_grad(k, p.q);
        for (unsigned int L = 0; L < 3; ++L)
          b[3 * k + L] = g[L];
      }
    add_residual(fe_values, p);
    if (p.A != nullptr)
      add_tangent(p);
    first = false;
  }

  void
  ElasticCell::add_residual(const FEValues<3> &fe_values, const Point &p)
  {
    for (unsigned int c = 0; c < 3; ++c)
      for (unsigned int k = 0; k < n_scalar; ++k)
        {
          const double *bk = &b[3 * k];
          const double  f_ext =
            fe_values.shape_value(k, p.q) * p.f_body[c] * p.JxW;
          const double f_int =
            ((p.P[c][0] * bk[0] + p.P[c][1] * bk[1]) + p.P[c][2] * bk[2]) *
            p.dV_rest;
          const unsigned int r = c * n_scalar + k;
          if (first)
            {
              external[r] = f_ext;
              rhs[r]      = f_ext - f_int;
              if (magnitudes)
                magnitude[r] = std::abs(f_ext) + std::abs(f_int);
              continue;
            }
          external[r] += f_ext;
          rhs[r] += f_ext - f_int;
          if (magnitudes)
            magnitude[r] += std::abs(f_ext) + std::abs(f_int);
        }
  }

  void
  ElasticCell::add_tangent(const Point &p)
  {
    // A[ci][K][cj][L] as At[30 L + 10 K + 3 cj + ci] (padded with zeros):
    // the inner loops below then run over contiguous entries.
    double              At[3 * v_size] = {};
    const Tensor<4, 3> &A              = *p.A;
    for (unsigned int ci = 0; ci < 3; ++ci)
      for (unsigned int K = 0; K < 3; ++K)
        for (unsigned int cj = 0; cj < 3; ++cj)
          for (unsigned int L = 0; L < 3; ++L)
            At[v_size * L + slice * K + 3 * cj + ci] = A[ci][K][cj][L];
    for (unsigned int l = 0; l < n_scalar; ++l)
      contract(
        At, b[3 * l], b[3 * l + 1], b[3 * l + 2], p.dV_rest, &v[v_size * l]);
    for (unsigned int k = 0; k < n_scalar; ++k)
      for (unsigned int l = 0; l <= k; ++l)
        add_block(&v[v_size * l],
                  b[3 * k],
                  b[3 * k + 1],
                  b[3 * k + 2],
                  first,
                  &blocks[block_size * pair_index(k, l)]);
  }

  void
  ElasticCell::vectors(Vector<double> &cell_rhs,
                       Vector<double> &cell_external,
                       Vector<double> &cell_magnitude) const
  {
    for (unsigned int r = 0; r < index.size(); ++r)
      {
        cell_rhs(index[r])      = rhs[r];
        cell_external(index[r]) = external[r];
        if (magnitudes)
          cell_magnitude(index[r]) = magnitude[r];
      }
  }

  void
  ElasticCell::matrix(FullMatrix<double> &M) const
  {
    // Entry (ci, k), (cj, l) of the pair k >= l is sum_K v_l[K][cj][ci]
    // b_k[K]: the sum with the row of (ci, k). Of the two sums of an entry
    // on a diagonal block, that with the row of the larger index.
    for (unsigned int k = 0; k < n_scalar; ++k)
      for (unsigned int l = 0; l <= k; ++l)
        {
          const double *block = &blocks[block_size * pair_index(k, l)];
          for (unsigned int ci = 0; ci < 3; ++ci)
            for (unsigned int cj = 0; cj < 3; ++cj)
              {
                const unsigned int i = index[ci * n_scalar + k];
                const unsigned int j = index[cj * n_scalar + l];
                if (k == l && i < j)
                  continue;
                M(i, j) = M(j, i) = block[3 * cj + ci];
              }
        }
  }
} // namespace RestShape
