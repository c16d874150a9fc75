#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>

#include <restshape/postprocess/error_estimator.h>

namespace RestShape
{
  using namespace dealii;

  namespace
  {
    /// Traction-jump indicators (see estimate_error()) of the owned cells.
    /// Each cell integrates the whole jump over each of its faces from its
    /// own side (as Kelly's indicator, every face counts for both of its
    /// cells); the neighbour's values are matched to the cell's quadrature
    /// points by position, whatever the faces' orientations.
    class TractionJump
    {
    public:
      TractionJump(const ForwardProblem &problem,
                   const VectorType     &u,
                   const Quadrature<2>  &quadrature,
                   Vector<float>        &indicators)
        : problem(problem)
        , u(u)
        , flags(update_gradients | update_quadrature_points |
                update_JxW_values | update_normal_vectors)
        , cell_face(problem.discretization().mapping(),
                    problem.discretization().fe(),
                    quadrature,
                    flags)
        , neighbor_face(problem.discretization().mapping(),
                        problem.discretization().fe(),
                        quadrature,
                        flags)
        , indicators(indicators)
      {
        if (!problem.discretization().mesh().is_simplex())
          {
            cell_subface = std::make_unique<FESubfaceValues<3>>(
              problem.discretization().mapping(),
              problem.discretization().fe(),
              quadrature,
              flags);
            neighbor_subface = std::make_unique<FESubfaceValues<3>>(
              problem.discretization().mapping(),
              problem.discretization().fe(),
              quadrature,
              flags);
          }
      }

      void
      run()
      {
        const auto &dof_handler = problem.discretization().dof_handler();
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned() && !rigid(cell))
            {
              double sum = 0;
              for (const unsigned int f : cell->face_indices())
                sum += face(cell, f);
              indicators[cell->active_cell_index()] =
                std::sqrt(cell->diameter() / 24 * sum);
            }
      }

    private:
      using Cell = DoFHandler<3>::active_cell_iterator;

      /// Every DoF of the cell is fixed: it does not deform.
      bool
      rigid(const Cell &cell)
      {
        dofs.resize(cell->get_fe().n_dofs_per_cell());
        cell->get_dof_indices(dofs);
        for (const auto dof : dofs)
          if (!problem.discretization().is_fixed(dof))
            return false;
        return true;
      }

      /// int_F |[P n]|^2 / E_min^2 over face @p f of @p cell (all of it,
      /// in pieces where the neighbour is finer).
      double
      face(const Cell &cell, const unsigned int f)
      {
        if (cell->at_boundary(f))
          return 0;
        if (cell->face(f)->has_children())
          {
            double sum = 0;
            for (unsigned int sf = 0; sf < cell->face(f)->n_children(); ++sf)
              {
                const Cell child = cell->neighbor_child_on_subface(f, sf);
                if (rigid(child))
                  continue;
                cell_subface->reinit(cell, f, sf);
                neighbor_face.reinit(child, cell->neighbor_of_neighbor(f));
                sum += jump(cell, *cell_subface, child, neighbor_face);
              }
            return sum;
          }
        const Cell neighbor = cell->neighbor(f);
        if (rigid(neighbor))
          return 0;
        cell_face.reinit(cell, f);
        if (cell->neighbor_is_coarser(f))
          {
            const auto [nf, nsf] = cell->neighbor_of_coarser_neighbor(f);
            neighbor_subface->reinit(neighbor, nf, nsf);
            return jump(cell, cell_face, neighbor, *neighbor_subface);
          }
        neighbor_face.reinit(neighbor, cell->neighbor_of_neighbor(f));
        return jump(cell, cell_face, neighbor, neighbor_face);
      }

      /// First Piola stress of the law of @p label at I + grad u (the
      /// linearised stress where the law cannot evaluate it).
      Tensor<2, 3>
      stress(const types::material_id label, const Tensor<2, 3> &grad_u)
      {
        const MaterialLaw &law = problem.materials().law(label);
        Tensor<2, 3>       P;
        if (law.evaluate(unit_symmetric_tensor<3>() + grad_u,
                         P,
                         nullptr,
                         TangentType::consistent))
          return P;
        const SymmetricTensor<2, 3> eps = symmetrize(grad_u);
        return Tensor<2, 3>(2 * law.mu * eps + law.lambda * trace(eps) *
                                                 unit_symmetric_tensor<3>());
      }

      double
      jump(const Cell                &cell,
           const FEFaceValuesBase<3> &mine,
           const Cell                &neighbor,
           const FEFaceValuesBase<3> &theirs)
      {
        const FEValuesExtractors::Vector displacement(0);
        const unsigned int               n = mine.n_quadrature_points;
        grad_mine.resize(n);
        grad_theirs.resize(n);
        mine[displacement].get_function_gradients(u, grad_mine);
        theirs[displacement].get_function_gradients(u, grad_theirs);
        const double E =
          std::min(problem.materials().youngs_modulus(cell->material_id()),
                   problem.materials().youngs_modulus(neighbor->material_id()));
        double sum = 0;
        for (unsigned int q = 0; q < n; ++q)
          {
            // The neighbour's point at the same position.
            unsigned int match = 0;
            for (unsigned int r = 1; r < n; ++r)
              if (theirs.quadrature_point(r).distance_square(
                    mine.quadrature_point(q)) <
                  theirs.quadrature_point(match).distance_square(
                    mine.quadrature_point(q)))
                match = r;
            const Tensor<1, 3> t =
              (stress(cell->material_id(), grad_mine[q]) -
               stress(neighbor->material_id(), grad_theirs[match])) *
              mine.normal_vector(q);
            sum += t.norm_square() / (E * E) * mine.JxW(q);
          }
        return sum;
      }

      const ForwardProblem                &problem;
      const VectorType                    &u;
      const UpdateFlags                    flags;
      FEFaceValues<3>                      cell_face, neighbor_face;
      std::unique_ptr<FESubfaceValues<3>>  cell_subface, neighbor_subface;
      Vector<float>                       &indicators;
      std::vector<types::global_dof_index> dofs;
      std::vector<Tensor<2, 3>>            grad_mine, grad_theirs;
    };
  } // namespace

  ErrorEstimate
  estimate_error(const ForwardProblem                 &problem,
                 const VectorType                     &u,
                 const RefinementParameters::Estimator estimator)
  {
    const auto      &dof_handler = problem.discretization().dof_handler();
    const auto      &tria        = dof_handler.get_triangulation();
    const VectorType ghosted     = problem.discretization().ghosted_copy(
      problem.discretization().owned_copy(u));

    const unsigned int  q = problem.discretization().fe().degree + 1;
    const Quadrature<2> face_quadrature =
      problem.discretization().mesh().is_simplex() ?
        Quadrature<2>(QGaussSimplex<2>(q)) :
        Quadrature<2>(QGauss<2>(q));
    ErrorEstimate estimate;
    estimate.indicators.reinit(tria.n_active_cells());
    if (estimator == RefinementParameters::Estimator::traction_jump)
      TractionJump(problem, ghosted, face_quadrature, estimate.indicators)
        .run();
    else
      KellyErrorEstimator<3>::estimate(
        problem.discretization().mapping(),
        dof_handler,
        face_quadrature,
        std::map<types::boundary_id, const Function<3> *>(),
        ghosted,
        estimate.indicators,
        ComponentMask(),
        nullptr,
        numbers::invalid_unsigned_int,
        // Ghost cells are estimated by their
        // owners: estimate on the owned ones.
        tria.locally_owned_subdomain());
    const double eta = VectorTools::compute_global_error(tria,
                                                         estimate.indicators,
                                                         VectorTools::L2_norm);

    // |grad u|_L2 over the body.
    Vector<float>       cellwise(tria.n_active_cells());
    const Quadrature<3> quadrature =
      problem.discretization().mesh().is_simplex() ?
        Quadrature<3>(QGaussSimplex<3>(q)) :
        Quadrature<3>(QGauss<3>(q));
    Functions::ZeroFunction<3> zero(3);
    VectorTools::integrate_difference(problem.discretization().mapping(),
                                      dof_handler,
                                      ghosted,
                                      zero,
                                      cellwise,
                                      quadrature,
                                      VectorTools::H1_seminorm);
    const double gradient =
      VectorTools::compute_global_error(tria,
                                        cellwise,
                                        VectorTools::H1_seminorm);
    estimate.relative = gradient > 0 ? eta / gradient : 0;
    return estimate;
  }
} // namespace RestShape
