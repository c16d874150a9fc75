// TangentStrategy: the tangent and diagonal shift of each Newton step from
// what the line searches found (Discretization/Tangent, Solver/Tangent
// shift): fixed tangents never change; adaptive takes one projected step
// after a shortened one and the projected tangent when no step helps; with
// a shift, mu = s, 10 mu, ... up to the cap, mu / 10 after full steps and
// 0 below s / 1000.
#include <restshape/solver/tangent_strategy.h>

#include <iostream>
#include <string>

#include "checks.h"

using namespace RestShape;
using namespace checks;

int
main()
{
  using Retry = TangentStrategy::Retry;
  for (const TangentType fixed :
       {TangentType::consistent, TangentType::projected, TangentType::warped})
    {
      TangentStrategy s(fixed, 1e-3);
      const bool      ok = s.accepted(true) && s.tangent() == fixed &&
                      s.shift() == 0 && s.rejected() == Retry::none &&
                      s.tangent() == fixed;
      expect(ok, "a fixed tangent never changes and is never shifted");
    }

  TangentStrategy a(TangentType::adaptive, 0);
  expect(a.tangent() == TangentType::consistent, "adaptive starts consistent");
  a.accepted(true);
  expect(a.tangent() == TangentType::projected,
         "after a shortened step: one projected step");
  a.accepted(true);
  expect(a.tangent() == TangentType::consistent,
         "after the projected step: consistent again, shortened or not");
  expect(a.rejected() == Retry::projected &&
           a.tangent() == TangentType::projected,
         "no step helps along the consistent tangent: the projected one");
  expect(a.rejected() == Retry::none,
         "no step helps along the projected one either: Newton fails");

  TangentStrategy m(TangentType::adaptive, 1e-3);
  expect(m.shift() == 0, "the shift starts at 0");
  m.accepted(false);
  expect(m.shift() == 0, "full steps keep it at 0");
  m.accepted(true);
  expect(m.shift() == 1e-3 && m.tangent() == TangentType::consistent,
         "a shortened step: mu = s, the consistent tangent kept");
  expect(m.rejected() == Retry::larger_shift && m.shift() == 1e-2,
         "no step helps: mu = 10 mu from the same state");
  m.accepted(false);
  expect(m.shift() == 1e-3, "a full step: mu / 10");
  m.accepted(false);
  m.accepted(false);
  expect(m.shift() > 0 && m.shift() < 2e-5, "mu / 10 again (1e-5)");
  double       last  = m.shift();
  unsigned int steps = 0;
  while (m.shift() > 0 && steps < 10)
    {
      last = m.shift();
      m.accepted(false);
      ++steps;
    }
  expect(m.shift() == 0 && last < 1.01e-6 && steps == 3,
         "full steps: 1e-6, 1e-7, then 0 below s / 1000 (Newton exact again)");
  bool         within = true;
  unsigned int raises = 0;
  while (within && raises < 20)
    {
      within = m.accepted(true);
      ++raises;
    }
  expect(!within && raises == 9 && m.shift() > TangentStrategy::max_shift,
         "shortened steps raise mu 1e-3 ... 1e4 (the cap), the ninth goes "
         "past it: Newton fails");
  TangentStrategy r(TangentType::adaptive, 1e3);
  r.accepted(true);
  expect(r.rejected() == Retry::larger_shift &&
           r.rejected() == Retry::shift_exhausted,
         "rejected steps past the cap: the shift is exhausted");
  return failures == 0 ? 0 : 1;
}
