#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <restshape/base/input_error.h>
#include <restshape/postprocess/verification.h>

#include <array>
#include <cmath>
#include <iostream>
#include <sstream>

namespace RestShape
{
  using namespace dealii;

  /// The parsed expressions, with SI input and output.
  class ExactDisplacement::SIFunction : public Function<3>
  {
  public:
    SIFunction(const std::string &expressions, const double unit)
      : Function<3>(3)
      , parser(3, 0., 1e-3)
      , unit(unit)
    {
      std::map<std::string, double> constants;
      parser.initialize("x,y,z", expressions, constants);
      parser.set_formula(AutoDerivativeFunction<3>::FourthOrder);
    }

    double
    value(const Point<3> &p, const unsigned int c) const override
    {
      return unit * parser.value(Point<3>(p / unit), c);
    }

    Tensor<1, 3>
    gradient(const Point<3> &p, const unsigned int c) const override
    {
      return parser.gradient(Point<3>(p / unit), c);
    }

  private:
    FunctionParser<3> parser;
    const double      unit;
  };

  ExactDisplacement::ExactDisplacement(const std::string &expressions,
                                       const double       length_unit,
                                       const std::string &parameter)
    : parameter(parameter)
  {
    // deal.II's FunctionParser prints muparser's messages to std::cerr
    // before it throws; keep them off the terminal (we report one line).
    std::ostringstream silenced;
    std::streambuf    *cerr_buffer = std::cerr.rdbuf(silenced.rdbuf());
    try
      {
        auto f = std::make_unique<SIFunction>(expressions, length_unit);
        for (unsigned int c = 0; c < 3; ++c)
          f->value(Point<3>(), c); // muparser reports some errors only here
        function = std::move(f);
        std::cerr.rdbuf(cerr_buffer);
      }
    catch (const std::exception &exc)
      {
        std::cerr.rdbuf(cerr_buffer);
        throw InputError("",
                         parameter,
                         "cannot parse '" + expressions + "' (" +
                           one_line_message(exc) +
                           "); expected three muparser expressions of x, y, "
                           "z separated by ';'");
      }
  }

  void
  ExactDisplacement::check_finite_on(const Triangulation<3> &tria) const
  {
    std::vector<Point<3>> points;
    const auto           &used = tria.get_used_vertices();
    for (unsigned int v = 0; v < used.size(); ++v)
      if (used[v])
        points.push_back(tria.get_vertices()[v]);
    for (const auto &cell : tria.active_cell_iterators())
      if (cell->is_locally_owned())
        points.push_back(cell->center());

    // Beyond this (m), the squares and integrals of the errors overflow.
    constexpr double      largest_value = 1e100;
    std::array<double, 4> where         = {{0, 0, 0, 0}}; // found?, x, y, z
    for (const Point<3> &p : points)
      for (unsigned int c = 0; c < 3 && where[0] == 0; ++c)
        if (!(std::abs(function->value(p, c)) <= largest_value))
          where = {{1, p[0], p[1], p[2]}};
    const auto comm = tria.get_communicator();
    if (Utilities::MPI::max(where[0], comm) == 0)
      return;
    // The place reported is the one of the lowest rank that found one.
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const unsigned int first =
      Utilities::MPI::min(where[0] > 0 ? rank : ~0u, comm);
    where = Utilities::MPI::broadcast(comm, where, first);
    std::ostringstream at;
    at << "(" << where[1] << ", " << where[2] << ", " << where[3] << ") m";
    throw InputError("",
                     parameter,
                     "the expressions give a value that is not a finite "
                     "number (or beyond 1e100 m, whose square overflows) "
                     "at " +
                       at.str() +
                       "; expected an exact solution defined on the whole "
                       "mesh");
  }

  DisplacementErrors
  ExactDisplacement::errors(const ForwardProblem &problem,
                            const VectorType     &field) const
  {
    const auto      &dof_handler = problem.discretization().dof_handler();
    const auto       comm = dof_handler.get_triangulation().get_communicator();
    const VectorType u    = problem.discretization().ghosted_copy(
      problem.discretization().owned_copy(field));

    const unsigned int  degree = problem.discretization().fe().degree + 2;
    const Quadrature<3> quadrature =
      problem.discretization().mesh().is_simplex() ?
        Quadrature<3>(QGaussSimplex<3>(std::min(degree, 4u))) :
        Quadrature<3>(QGauss<3>(degree));
    const auto &tria = dof_handler.get_triangulation();

    const auto norm_of = [&](const VectorType           &v,
                             const Function<3>          &f,
                             const VectorTools::NormType norm) {
      Vector<float> cellwise(tria.n_active_cells());
      VectorTools::integrate_difference(problem.discretization().mapping(),
                                        dof_handler,
                                        v,
                                        f,
                                        cellwise,
                                        quadrature,
                                        norm);
      return VectorTools::compute_global_error(tria, cellwise, norm);
    };
    const VectorType zero = problem.discretization().ghosted_copy(
      problem.discretization().zero_vector());
    Functions::ZeroFunction<3> zero_function(3);

    DisplacementErrors e;
    const double l2_exact = norm_of(zero, *function, VectorTools::L2_norm);
    const double h1_exact = norm_of(zero, *function, VectorTools::H1_seminorm);
    e.l2_relative = norm_of(u, *function, VectorTools::L2_norm) / l2_exact;
    // A translation has no gradient (up to the round-off of the function's
    // difference quotients): the H1 error is then absolute.
    const double l2_scale =
      l2_exact / problem.discretization().mesh().diameter();
    e.h1_relative = norm_of(u, *function, VectorTools::H1_seminorm) /
                    (h1_exact > 1e-8 * l2_scale ? h1_exact : 1.0);

    for (const Node &node : problem.discretization().owned_nodes())
      {
        Tensor<1, 3> diff;
        for (unsigned int c = 0; c < 3; ++c)
          diff[c] = u[node.dofs[c]] - function->value(node.position, c);
        e.max_nodal_error = std::max(e.max_nodal_error, diff.norm());
      }
    e.max_nodal_error = Utilities::MPI::max(e.max_nodal_error, comm);
    return e;
  }
} // namespace RestShape
