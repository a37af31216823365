// Self-collision in a run: the hash's close pairs less the pairs that are neighbours at rest, parted in place.
#include "contact/self_collision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace cloth {

// Cells of side 1.5 delta, the largest distance queried: a close pair lies in one cell or in neighbouring ones. About
// two buckets per particle keep collisions of distinct cells rare (Teschner et al. 2003).
SelfCollision::SelfCollision(Eigen::VectorXd rest_positions, double thickness, double skin)
    : rest_(std::move(rest_positions)), thickness_(thickness), margin_(skin * thickness),
      reach_((1 + 2 * skin) * thickness), hash_(reach_, std::max(16, static_cast<int>(2 * (rest_.size() / 3)))) {}

// Pairs nearer than 2 delta at rest are neighbours: at the grid spacing d = delta they are the ends of a
// structural, shear or flexion spring, which already keeps them apart; parting them too would fight the springs.
// The rounding allowance keeps the flexion pairs, exactly 2 d apart, out.
bool SelfCollision::apart_at_rest(int a, int b) const {
  return (rest_.segment<3>(3 * b) - rest_.segment<3>(3 * a)).norm() > 2 * thickness_ * (1 + 1e-9);
}

// [clamp]
int SelfCollision::clamp(const Eigen::Ref<const Eigen::VectorXd>& x0, double h, Eigen::Ref<Eigen::VectorXd> x1,
                         Eigen::Ref<Eigen::VectorXd> v1) const {
  const double reach = thickness_ / 2;  // per particle and step: two approaching particles close at most delta
  int clamped = 0;
  for (Eigen::Index s = 0; s < x1.size() / 3; ++s) {
    const Eigen::Vector3d dx = x1.segment<3>(3 * s) - x0.segment<3>(3 * s);
    const double length = dx.norm();
    if (length > reach) {
      x1.segment<3>(3 * s) = x0.segment<3>(3 * s) + (reach / length) * dx;
      ++clamped;
    }
    const double speed = v1.segment<3>(3 * s).norm();
    if (speed * h > reach) v1.segment<3>(3 * s) *= reach / (speed * h);
  }
  return clamped;
}
// [clamp]

// [self_collision_pass]
void SelfCollision::find_candidates(const Eigen::Ref<const Eigen::VectorXd>& x) {
  hash_.build(x, rest_);
  hash_.pairs_within(reach_, pairs_, 2 * thickness_ * (1 + 1e-9));
  built_at_ = x;
  candidates_current_ = true;
  ++work_.builds;
  work_.distance_tests += hash_.distance_tests();
  work_.pairs_found += static_cast<long long>(pairs_.size());
}

// [margin]
// A pair left out of the list was at least 1.5 delta apart at the build. Its particles' displacements since then
// are u + e_a and u + e_b for any common u, and a common motion does not bring them closer: they are now at least
// 1.5 delta - |e_a| - |e_b| apart. So the list holds while every |x - x_built - u| <= delta / 4 for one u, and
// the u that needs this least is near the centre of the displacements' bounding box: a strip toppling over as a
// whole, or falling, keeps its list longer than the largest displacement alone would allow.
bool SelfCollision::moved_beyond_margin(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  if (!candidates_current_ || built_at_.size() != x.size()) return true;
  const double margin2 = margin_ * margin_;
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (Eigen::Index s = 0; s < x.size(); s += 3) {
    const Eigen::Vector3d moved = x.segment<3>(s) - built_at_.segment<3>(s);
    low = low.cwiseMin(moved);
    high = high.cwiseMax(moved);
  }
  const Eigen::Vector3d u = 0.5 * (low + high);
  if (!((high - u).squaredNorm() > margin2)) return false;  // the box's half-diagonal bounds every |e|
  for (Eigen::Index s = 0; s < x.size(); s += 3)
    if (!((x.segment<3>(s) - built_at_.segment<3>(s) - u).squaredNorm() <= margin2)) return true;  // a NaN too
  return false;
}
// [margin]

void SelfCollision::update_candidates(const Eigen::Ref<const Eigen::VectorXd>& x) {
  if (moved_beyond_margin(x)) {
    find_candidates(x);
  } else {
    ++work_.reuses;
    work_.pairs_found += static_cast<long long>(pairs_.size());
  }
}

int SelfCollision::resolve(Eigen::VectorXd& x, Eigen::VectorXd& v) {
  const auto n = static_cast<std::size_t>(x.size() / 3);
  ++work_.passes;
  moved_before_.resize(n);
  moved_now_.assign(n, 0);
  moved_list_.clear();
  const double reach = (1 - 1e-3) * thickness_;
  int corrected = 0;
  for (const auto& [a, b] : pairs_)
    if (part_pair(a, b, thickness_, reach, x.data(), v.data())) {
      ++corrected;
      mark_moved(a);
      mark_moved(b);
    }
  work_.pairs_corrected += corrected;
  return corrected;
}

void SelfCollision::mark_moved(int p) {
  if (moved_now_[static_cast<std::size_t>(p)] != 0) return;
  moved_now_[static_cast<std::size_t>(p)] = 1;
  moved_list_.push_back(p);
}

int SelfCollision::resolve_again(Eigen::VectorXd& x, Eigen::VectorXd& v) {
  ++work_.passes;
  std::swap(moved_before_, moved_now_);
  std::fill(moved_now_.begin(), moved_now_.end(), 0);
  moved_list_.clear();
  const double reach = (1 - 1e-3) * thickness_;
  int corrected = 0;
  for (const auto& [a, b] : pairs_) {
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    if ((moved_before_[ua] | moved_before_[ub] | moved_now_[ua] | moved_now_[ub]) == 0) continue;
    if (!part_pair(a, b, thickness_, reach, x.data(), v.data())) continue;
    ++corrected;
    mark_moved(a);
    mark_moved(b);
  }
  work_.pairs_corrected += corrected;
  return corrected;
}
// [self_collision_pass]

std::vector<std::pair<int, int>> SelfCollision::candidates_brute_force(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  std::vector<std::pair<int, int>> pairs = pairs_within_brute_force(x, reach_);
  std::erase_if(pairs, [&](const std::pair<int, int>& p) { return !apart_at_rest(p.first, p.second); });
  return pairs;
}

double SelfCollision::closest_distance(const Eigen::Ref<const Eigen::VectorXd>& x, double rest_factor) {
  hash_.build(x, rest_);
  hash_.pairs_within(thickness_, pairs_, rest_factor * thickness_ * (1 + 1e-9));
  candidates_current_ = false;  // pairs_ now holds this check's pairs, not the step's candidates
  double closest = thickness_;
  for (const auto& [a, b] : pairs_) closest = std::min(closest, (x.segment<3>(3 * b) - x.segment<3>(3 * a)).norm());
  return closest;
}

}  // namespace cloth
