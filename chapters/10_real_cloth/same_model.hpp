// Chapter 10's check that the peers' plain loop and the book's force routine are the same model (same_model.cpp).
#pragma once

#include "peer_systems.hpp"

#include <string>

namespace ch10 {

/// Compares the right-hand sides and the Jacobians of `plain` and `core` at a perturbed, moving state of `scene`
/// (pinned rows excepted, which the core does not have); throws std::logic_error when they differ by more than
/// 1e-12 relative to their largest entries, else writes the agreement to DIR/peers_check.md.
void check_same_model(const cloth::Scene& scene, PlainSystem& plain, CoreSystem& core, const std::string& dir);

}  // namespace ch10
