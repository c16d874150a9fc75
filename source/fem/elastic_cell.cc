// ElasticCell: the material law's part of a cell's residual and tangent,
// summed by scalar shape functions in flat arrays.
#include <restshape/fem/elastic_cell.h>

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

    /// The residual's terms of one component c at one point, for the
    /// scalar functions k < @p n: f_ext = phi_k f_c JxW, f_int = (P_c .
    /// b_k) dV, summed into @p external, @p rhs (f_ext - f_int) and, if not
    /// null, @p magnitude (|f_ext| + |f_int|).
    void
    residual_terms(const unsigned int n,
                   const double *__restrict phi,
                   const double *__restrict bx,
                   const double *__restrict by,
                   const double *__restrict bz,
                   const Tensor<1, 3> &P_c,
                   const double        f_c,
                   const double        JxW,
                   const double        dV,
                   double *__restrict external,
                   double *__restrict rhs,
                   double *__restrict magnitude)
    {
      const double P0 = P_c[0], P1 = P_c[1], P2 = P_c[2];
      for (unsigned int k = 0; k < n; ++k)
        {
          const double f_ext = phi[k] * f_c * JxW;
          const double f_int = ((P0 * bx[k] + P1 * by[k]) + P2 * bz[k]) * dV;
          external[k] += f_ext;
          rhs[k] += f_ext - f_int;
        }
      if (magnitude != nullptr)
        for (unsigned int k = 0; k < n; ++k)
          {
            const double f_ext = phi[k] * f_c * JxW;
            const double f_int = ((P0 * bx[k] + P1 * by[k]) + P2 * bz[k]) * dV;
            magnitude[k] += std::abs(f_ext) + std::abs(f_int);
          }
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
    , phi(n_scalar)
    , v(v_size * n_scalar)
    , blocks(block_size * pair_index(n_scalar, 0))
    , rhs(3 * n_scalar)
    , external(3 * n_scalar)
    , magnitude(3 * n_scalar)
    , volume_gradient(max_pressure_modes * 3 * n_scalar)
  {
    AssertThrow(fe.n_base_elements() == 1 && fe.n_components() == 3 &&
                  fe.element_multiplicity(0) == 3,
                ExcMessage("expected 3 copies of one scalar element"));
    for (unsigned int c = 0; c < 3; ++c)
      for (unsigned int k = 0; k < n_scalar; ++k)
        index[c * n_scalar + k] = fe.component_to_system_index(c, k);
    // Entry (ci, k), (cj, l) of the pair k >= l is sum_K v_l[K][cj][ci]
    // b_k[K]: the sum with the row of (ci, k). Of the two sums of an entry
    // on a diagonal block, that with the row of the larger index.
    const unsigned int n = 3 * n_scalar;
    for (unsigned int k = 0; k < n_scalar; ++k)
      for (unsigned int l = 0; l <= k; ++l)
        for (unsigned int ci = 0; ci < 3; ++ci)
          for (unsigned int cj = 0; cj < 3; ++cj)
            {
              const unsigned int i = index[ci * n_scalar + k];
              const unsigned int j = index[cj * n_scalar + l];
              if (k == l && i < j)
                continue;
              const unsigned int from =
                block_size * pair_index(k, l) + 3 * cj + ci;
              copies.push_back({i * n + j, from});
              if (i != j)
                copies.push_back({j * n + i, from});
            }
  }

  void
  ElasticCell::reinit(const bool sum_magnitudes, const unsigned int modes)
  {
    AssertIndexRange(modes - 1, max_pressure_modes);
    magnitudes = sum_magnitudes;
    n_modes    = modes;
    first      = true;
    std::fill(rhs.begin(), rhs.end(), 0.);
    std::fill(external.begin(), external.end(), 0.);
    std::fill(volume_gradient.begin(),
              volume_gradient.begin() + n_modes * 3 * n_scalar,
              0.);
    if (magnitudes)
      std::fill(magnitude.begin(), magnitude.end(), 0.);
  }

  void
  ElasticCell::add_terms(const Point &p)
  {
    add_residual(p);
    if (p.A != nullptr)
      add_tangent(p);
    if (p.dJ != nullptr)
      for (unsigned int a = 0; a < n_modes; ++a)
        {
          const double weight = p.modes == nullptr ? 1. : p.modes[a];
          double      *g      = &volume_gradient[a * 3 * n_scalar];
          for (unsigned int c = 0; c < 3; ++c)
            for (unsigned int k = 0; k < n_scalar; ++k)
              g[c * n_scalar + k] +=
                weight * p.dV_rest *
                ((*p.dJ)[c][0] * b[k] + (*p.dJ)[c][1] * b[n_scalar + k] +
                 (*p.dJ)[c][2] * b[2 * n_scalar + k]);
        }
    first = false;
  }

  void
  ElasticCell::add_volumetric_stiffness(FullMatrix<double> &M,
                                        const double        factor) const
  {
    for (unsigned int r = 0; r < index.size(); ++r)
      for (unsigned int s = 0; s < index.size(); ++s)
        M(index[r], index[s]) +=
          factor * volume_gradient[r] * volume_gradient[s];
  }

  void
  ElasticCell::add_volumetric_stiffness(FullMatrix<double>       &M,
                                        const FullMatrix<double> &K) const
  {
    const unsigned int n = index.size();
    // t_r = sum_a G_a[r] K_ab, then M_rs += sum_b t_r[b] G_b[s].
    std::vector<double> t(n * n_modes, 0.);
    for (unsigned int r = 0; r < n; ++r)
      for (unsigned int a = 0; a < n_modes; ++a)
        for (unsigned int b = 0; b < n_modes; ++b)
          t[r * n_modes + b] += volume_gradient[a * n + r] * K(a, b);
    for (unsigned int r = 0; r < n; ++r)
      for (unsigned int s = 0; s < n; ++s)
        {
          double sum = 0;
          for (unsigned int b = 0; b < n_modes; ++b)
            sum += t[r * n_modes + b] * volume_gradient[b * n + s];
          M(index[r], index[s]) += sum;
        }
  }

  void
  ElasticCell::volume_gradient_in_dof_order(std::vector<double> &g,
                                            const unsigned int   mode) const
  {
    g.resize(index.size());
    for (unsigned int r = 0; r < index.size(); ++r)
      g[index[r]] = volume_gradient[mode * index.size() + r];
  }

  void
  ElasticCell::add_residual(const Point &p)
  {
    const double *bx = &b[0], *by = &b[n_scalar], *bz = &b[2 * n_scalar];
    for (unsigned int c = 0; c < 3; ++c)
      residual_terms(n_scalar,
                     phi.data(),
                     bx,
                     by,
                     bz,
                     p.P[c],
                     p.f_body[c],
                     p.JxW,
                     p.dV_rest,
                     &external[c * n_scalar],
                     &rhs[c * n_scalar],
                     magnitudes ? &magnitude[c * n_scalar] : nullptr);
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
    const double *bx = &b[0], *by = &b[n_scalar], *bz = &b[2 * n_scalar];
    for (unsigned int l = 0; l < n_scalar; ++l)
      contract(At, bx[l], by[l], bz[l], p.dV_rest, &v[v_size * l]);
    for (unsigned int k = 0; k < n_scalar; ++k)
      for (unsigned int l = 0; l <= k; ++l)
        add_block(&v[v_size * l],
                  bx[k],
                  by[k],
                  bz[k],
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
    AssertDimension(M.m(), 3 * n_scalar);
    double *const       m   = &M(0, 0);
    const double *const all = blocks.data();
    for (const auto &[to, from] : copies)
      m[to] = all[from];
  }
} // namespace RestShape
