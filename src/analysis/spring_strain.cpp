// The largest spring strain of a state.
#include "analysis/spring_strain.hpp"

#include <algorithm>
#include <limits>

namespace cloth {

double largest_spring_strain(const Scene& scene, const Eigen::Ref<const Eigen::VectorXd>& grid_positions) {
  double largest = -std::numeric_limits<double>::infinity();
  for (const Spring& s : scene.springs().springs) {
    const int p = scene.particle_of_slot(s.p), q = scene.particle_of_slot(s.q);
    const double l = (grid_positions.segment<3>(3 * p) - grid_positions.segment<3>(3 * q)).norm();
    largest = std::max(largest, (l - s.rest_length) / s.rest_length);
  }
  return largest;
}

}  // namespace cloth
