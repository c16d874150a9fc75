#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/error_estimator.h>
#include <deal.II/numerics/vector_tools.h>

#include <restshape/error_estimator.h>

namespace RestShape
{
  using namespace dealii;

  ErrorEstimate
  estimate_error(const ForwardProblem &problem, const VectorType &u)
  {
    const auto &dof_handler = problem.dof_handler();
    const auto &tria        = dof_handler.get_triangulation();
    const auto  comm        = tria.get_communicator();
    VectorType  ghosted(problem.locally_owned_dofs(),
                       problem.locally_relevant_dofs(),
                       comm);
    VectorType  owned(problem.locally_owned_dofs(), comm);
    owned   = u;
    ghosted = owned;

    const unsigned int  q               = problem.fe().degree + 1;
    const Quadrature<2> face_quadrature = problem.mesh().is_simplex() ?
                                            Quadrature<2>(QGaussSimplex<2>(q)) :
                                            Quadrature<2>(QGauss<2>(q));
    ErrorEstimate       estimate;
    estimate.indicators.reinit(tria.n_active_cells());
    KellyErrorEstimator<3>::estimate(
      problem.mapping(),
      dof_handler,
      face_quadrature,
      std::map<types::boundary_id, const Function<3> *>(),
      ghosted,
      estimate.indicators,
      ComponentMask(),
      nullptr,
      numbers::invalid_unsigned_int,
      // A shared triangulation stores every
      // cell: estimate on the owned ones.
      tria.locally_owned_subdomain());
    const double eta = VectorTools::compute_global_error(tria,
                                                         estimate.indicators,
                                                         VectorTools::L2_norm);

    // |grad u|_L2 over the body.
    Vector<float>              cellwise(tria.n_active_cells());
    const Quadrature<3>        quadrature = problem.mesh().is_simplex() ?
                                              Quadrature<3>(QGaussSimplex<3>(q)) :
                                              Quadrature<3>(QGauss<3>(q));
    Functions::ZeroFunction<3> zero(3);
    VectorTools::integrate_difference(problem.mapping(),
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
