// The stretch a method lets through: the largest relative elongation (l - L0) / L0 of any spring, the measure a
// practitioner reads beside an error (a fabric this stiff should stretch by a fraction of a percent).
#pragma once

#include "model/scene.hpp"

#include <Eigen/Core>

namespace cloth {

/// max over the scene's springs of (l - L0) / L0 (negative when every spring is compressed), from the positions
/// of every particle in grid order (3 per particle, pinned ones included: a Frame's positions).
double largest_spring_strain(const Scene& scene, const Eigen::Ref<const Eigen::VectorXd>& grid_positions);

}  // namespace cloth
