// Chapter 4's study of the implicit step as a minimisation: the first frame step of the flat curtain with each
// line search, iteration by iteration, and implicit Euler on the curtain at frame-rate steps with each form.
#pragma once

#include "integrators/simulate.hpp"
#include "model/scene.hpp"

#include <string>

namespace ch04 {

/// The first frame step (h = 1/60 s) of the flat curtain with the residual and the potential line search:
/// writes flat_step.md into `dir`.
void flat_step_history(const cloth::SceneParams& base, const std::string& dir, const std::string& command);

/// Implicit Euler on the curtain at h = 1/30, 1/60, 1/120 s with each Newton form, and the frozen dampers'
/// effect: writes curtain_runs.md and frozen_dampers.md into `dir`.
void curtain_runs(const cloth::SceneParams& base, const cloth::RunSettings& base_run, const std::string& dir,
                  const std::string& command);

}  // namespace ch04
