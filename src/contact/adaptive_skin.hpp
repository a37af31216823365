// A list of self-contact candidates refreshed particle by particle, each particle with a skin of its own (Chapter
// 11 measures what it would save against rebuilding the spatial hash): only the particles that drift out of their
// own ball are binned and queried again.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace cloth {

/// Each particle p carries a reference y_p and a free radius r_p, and the list keeps, for every pair (a, b) of
/// particles farther than 2 delta apart at rest that it does not hold, the separation of their balls:
/// |y_a - y_b| >= r_a + r_b + delta. References live in a frame that moves by U with the cloth as a whole; while
/// every particle lies within its radius of its reference, |x_p - U - y_p| <= r_p, a pair left out is then at
/// least |y_a - y_b| - r_a - r_b >= delta apart, so the list holds every contact. A particle that leaves its ball
/// is queried again: its reference moves to x_p - U, and each particle b whose reference lies within the reach
/// R = delta + 2 r_max either joins its list (its gap |y_p - y_b| - r_b - delta below min_gap) or bounds its new
/// radius, r_p = min(r_max, smallest gap); particles beyond R have gaps of at least R - r_max - delta = r_max.
/// Measuring the gap against b's ball rather than against where b is now is what keeps the bound when b was
/// queried earlier and has moved since. Every radius is at least min_gap.
class AdaptiveSkinList {
 public:
  /// `rest` the rest positions (3 per particle), `thickness` delta, `max_radius` r_max and `min_gap` as above
  /// (min_gap <= max_radius); `follow_common_motion` moves U to the centre of the drifts' bounding box each update,
  /// otherwise U stays 0.
  AdaptiveSkinList(Eigen::VectorXd rest, double thickness, double max_radius, double min_gap, bool follow_common_motion);

  /// Brings the list up to date with x: queries every particle (the first time) or those outside their balls.
  /// Returns the particles queried.
  int update(const Eigen::Ref<const Eigen::VectorXd>& x);

  /// Whether the list holds the pair (a, b).
  [[nodiscard]] bool holds(int a, int b) const;
  [[nodiscard]] double radius(int p) const { return radius_[static_cast<std::size_t>(p)]; }
  [[nodiscard]] const Eigen::Vector3d& reference(int p) const { return reference_[static_cast<std::size_t>(p)]; }
  /// The frame's displacement U at the last update.
  [[nodiscard]] const Eigen::Vector3d& frame() const { return frame_; }
  /// Over all updates: particles queried, and the distances their queries computed.
  [[nodiscard]] long long queries() const { return queries_; }
  [[nodiscard]] long long distance_tests() const { return distance_tests_; }
  /// The mean radius the queries gave.
  [[nodiscard]] double mean_radius() const { return queries_ > 0 ? radii_ / static_cast<double>(queries_) : 0; }
  /// The pairs the list holds now.
  [[nodiscard]] long long pairs() const;

 private:
  [[nodiscard]] bool apart_at_rest(int a, int b) const;
  [[nodiscard]] Eigen::Array3i cell_of(const Eigen::Vector3d& y) const;
  [[nodiscard]] std::size_t bucket_of(const Eigen::Array3i& cell) const;
  void query(int p, const Eigen::Vector3d& y);

  Eigen::VectorXd rest_;
  double thickness_, max_radius_, min_gap_, reach_;
  bool follow_;
  std::vector<Eigen::Vector3d> reference_;
  std::vector<double> radius_;
  std::vector<unsigned char> queried_;
  std::vector<std::vector<int>> partners_;  // each particle's pairs in the list
  std::vector<std::vector<int>> buckets_;   // the references binned by cell of side reach_, hashed
  std::vector<std::size_t> bucket_;         // each queried particle's bucket
  Eigen::Vector3d frame_ = Eigen::Vector3d::Zero();
  long long queries_ = 0, distance_tests_ = 0;
  double radii_ = 0;
};

}  // namespace cloth
