// Newton's stagnation rule (solver/newton_progress.h): when a load step is
// given back before the iteration cap. Histories of relative residuals,
// the last one the current residual, tolerance 1e-8, 80 steps left:
// - near an equilibrium (below 1e-2) at 2 % per step: given back;
// - near an equilibrium but speeding up, or fast enough: not;
// - above 1e-2 on a plateau (full and short steps in turn, 1.02e-2 to
//   1.03e-2, as on the P1 brain against the cutting skull at 2 g along
//   -y): given back;
// - above 1e-2 falling slowly (5 % per step: it leaves the plateau band),
//   or jumping by orders while the energy's line search leads Newton: not;
// - a history shorter than the window: never.
#include <restshape/solver/newton_progress.h>

#include <cmath>
#include <string>
#include <vector>

#include "checks.h"

using namespace RestShape;
using namespace checks;

namespace
{
  constexpr double       tolerance  = 1e-8;
  constexpr unsigned int steps_left = 80;
  constexpr unsigned int cap        = 100;

  /// @p n residuals from @p start, each @p rate times the one before.
  std::vector<double>
  geometric(const double start, const double rate, const unsigned int n)
  {
    std::vector<double> h;
    for (unsigned int i = 0; i < n; ++i)
      h.push_back(start * std::pow(rate, i));
    return h;
  }

  /// Whether Newton gives the load step back with history @p h.
  bool
  gives_back(const std::vector<double> &h)
  {
    return !stagnation(h, h.back(), steps_left, tolerance, cap).empty();
  }
} // namespace

int
main()
{
  expect(gives_back(geometric(1e-3, 0.98, 12)),
         "near an equilibrium, 2 % per step: given back");
  expect(!gives_back(geometric(1e-3, 0.5, 12)),
         "near an equilibrium, halved per step: Newton goes on");
  std::vector<double> faster = geometric(1e-3, 0.95, 11);
  faster.push_back(faster.back() * 1e-4);
  expect(!gives_back(faster), "a slow stretch that ends fast: Newton goes on");

  std::vector<double> plateau;
  for (unsigned int i = 0; i < 12; ++i)
    plateau.push_back(i % 2 == 0 ? 1.031e-2 : 1.022e-2);
  const std::string why =
    stagnation(plateau, plateau.back(), steps_left, tolerance, cap);
  expect(!why.empty() && why.find("Newton stagnates at |R|/|f| = 1.022e-02") !=
                           std::string::npos,
         "above 1e-2 on a plateau: given back (" + why + ")");
  expect(!gives_back(geometric(0.5, 0.95, 12)),
         "above 1e-2 at 5 % per step: Newton goes on");
  std::vector<double> jumping;
  for (unsigned int i = 0; i < 12; ++i)
    jumping.push_back(i % 2 == 0 ? 1.1 : 30.);
  expect(!gives_back(jumping),
         "far from an equilibrium, jumping by orders: Newton goes on");
  expect(!gives_back(std::vector<double>(10, 1.03e-2)),
         "fewer steps than the window: Newton goes on");
  return failures == 0 ? 0 : 1;
}
