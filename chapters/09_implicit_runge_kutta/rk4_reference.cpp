// RK4 at a small step: the reference of Chapter 9's accuracy studies (rk4_reference.hpp).
#include "rk4_reference.hpp"

#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "program/interrupt.hpp"

#include <stdexcept>

using namespace cloth;

namespace ch09 {

Vector rk4_positions(ForceField& field, double T, double h_ref) {
  const auto rk4 = make_stepper("rk4", field);
  RunSettings run;
  run.dt = h_ref;
  run.t_end = T;
  run.stop = &interrupt_flag();
  const RunResult r = simulate(*rk4, run, false);
  throw_if_interrupted();
  if (r.status != RunStatus::ok) throw std::runtime_error("the RK4 reference failed: " + r.message);
  return r.x;
}

}  // namespace ch09
