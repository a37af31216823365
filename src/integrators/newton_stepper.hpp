// What every implicit stepper built on StageNewton shares (Chapters 4 and 9): its Newton iteration, with the
// settings it resolved, the residuals of its last stage equation and the time spent in its linear algebra. The
// method registry makes these steppers by name (make_newton_stepper) for the programs that inspect them.
#pragma once

#include "integrators/stage_newton.hpp"

#include <vector>

namespace cloth {

/// A Stepper whose implicit equations are stage equations solved by one StageNewton.
class NewtonStepper : public Stepper {
 public:
  /// The settings must pass validate(NewtonSettings); throws InputError otherwise.
  NewtonStepper(ForceField& field, NewtonSettings settings) : Stepper(field), newton_(field, settings, counters_) {}

  /// The settings with the automatic solver resolved.
  [[nodiscard]] const NewtonSettings& settings() const { return newton_.settings(); }
  /// |r|_inf of the last stage equation solved (each Newton iteration, then after its last update).
  [[nodiscard]] const std::vector<double>& residual_history() const { return newton_.residual_history(); }
  /// The Newton iteration of the last stage equation solved (its incremental potential and step fractions).
  [[nodiscard]] const StageNewton& newton() const { return newton_; }
  [[nodiscard]] const StageNewton::Timing& timing() const { return newton_.timing(); }
  void reset_timing() { newton_.reset_timing(); }

 protected:
  StageNewton newton_;
};

}  // namespace cloth
