// Self-collision in a run: the hash's close pairs less the pairs that are neighbours at rest, parted in place.
#include "contact/self_collision.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>

namespace cloth {

// The pair response lives beside the passes, which call it thousands of times a step, so that the compiler can
// write it into them rather than call it.
// [self_contact]
bool part_pair(int a, int b, double thickness, double reach, double* x, double* v) {
  Eigen::Map<Eigen::Vector3d> xa(x + 3 * a), xb(x + 3 * b), va(v + 3 * a), vb(v + 3 * b);
  const Eigen::Vector3d ab = xb - xa;
  // The squared distance first: most candidates are apart, and need no square root.
  const double distance2 = ab.squaredNorm();
  if (!(distance2 < reach * reach) || distance2 == 0) return false;  // coincident particles have no direction to part in
  const double distance = std::sqrt(distance2);
  const Eigen::Vector3d n = ab / distance;
  // Equal masses: equal and opposite moves keep the centre of mass where it is.
  const Eigen::Vector3d half_gap = 0.5 * (thickness - distance) * n;
  xa -= half_gap;
  xb += half_gap;
  // Equal and opposite impulses remove the approaching normal relative velocity and keep the momentum.
  const double approach = (vb - va).dot(n);
  if (approach < 0) {
    va += 0.5 * approach * n;
    vb -= 0.5 * approach * n;
  }
  return true;
}

int resolve_self_contacts(const std::vector<std::pair<int, int>>& pairs, double thickness,
                          Eigen::Ref<Eigen::VectorXd> x, Eigen::Ref<Eigen::VectorXd> v, double slack) {
  int corrected = 0;
  for (const auto& [a, b] : pairs) corrected += part_pair(a, b, thickness, (1 - slack) * thickness, x.data(), v.data()) ? 1 : 0;
  return corrected;
}
// [self_contact]

// Cells of side the reach delta + 2 s (1.5 delta at the default skin), the largest distance queried: a close pair lies in one cell or in neighbouring ones. About
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

namespace {

// [clamp]
// The clamp of one particle s: its displacement x1 - x0 shortened to at most `reach`, and its velocity to reach / h.
// Returns whether the displacement was shortened.
bool clamp_particle(Eigen::Index s, const Eigen::Ref<const Eigen::VectorXd>& x0, double h, double reach,
                    Eigen::Ref<Eigen::VectorXd>& x1, Eigen::Ref<Eigen::VectorXd>& v1) {
  // Square roots only near the limits: a squared length below 0.98 reach^2 is below it after rounding too.
  const double near2 = 0.98 * reach * reach;
  const Eigen::Vector3d dx = x1.segment<3>(3 * s) - x0.segment<3>(3 * s);
  bool clamped = false;
  if (!(dx.squaredNorm() < near2)) {
    const double length = dx.norm();
    clamped = length > reach;
    if (clamped) x1.segment<3>(3 * s) = x0.segment<3>(3 * s) + (reach / length) * dx;
  }
  if (!(v1.segment<3>(3 * s).squaredNorm() * (h * h) < near2)) {
    const double speed = v1.segment<3>(3 * s).norm();
    if (speed * h > reach) v1.segment<3>(3 * s) *= reach / (speed * h);
  }
  return clamped;
}
// [clamp]

}  // namespace

int SelfCollision::clamp(const Eigen::Ref<const Eigen::VectorXd>& x0, double h, Eigen::Ref<Eigen::VectorXd> x1,
                         Eigen::Ref<Eigen::VectorXd> v1) const {
  const double reach = thickness_ / 2;  // per particle and step: two approaching particles close at most delta
  int clamped = 0;
  for (Eigen::Index s = 0; s < x1.size() / 3; ++s) clamped += clamp_particle(s, x0, h, reach, x1, v1) ? 1 : 0;
  return clamped;
}


int SelfCollision::correct_moved(const ContactModel& model, const Eigen::Ref<const Eigen::VectorXd>& x0,
                                 Eigen::Ref<Eigen::VectorXd> x1, Eigen::Ref<Eigen::VectorXd> v1) const {
  int contacts = 0;
  for (const int p : moved_list_) {
    const auto s = static_cast<Eigen::Index>(p);
    const double c = clearance_[static_cast<std::size_t>(p)];
    // Closer to where the sweep left it than its clearance then: still clear of every obstacle.
    if ((x1.segment<3>(3 * s) - swept_.segment<3>(3 * s)).squaredNorm() < c * c) continue;
    contacts += resolve_obstacle_contacts(model, s, x0, x1, v1);
  }
  return contacts;
}
// [clamp_sweep]
int SelfCollision::clamp_and_correct(const ContactModel& model, const Eigen::Ref<const Eigen::VectorXd>& x0, double h,
                                     Eigen::Ref<Eigen::VectorXd> x1, Eigen::Ref<Eigen::VectorXd> v1) {
  const double reach = thickness_ / 2;
  box_current_ = candidates_current_ && built_at_.size() == x1.size();
  clearance_.resize(static_cast<std::size_t>(x1.size() / 3));
  swept_.resize(x1.size());
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
  int contacts = 0;
  for (Eigen::Index s = 0; s < x1.size() / 3; ++s) {
    work_.clamped += clamp_particle(s, x0, h, reach, x1, v1) ? 1 : 0;
    // Most particles are clear of every obstacle: a signed distance each, and nothing more.
    double& c = clearance_[static_cast<std::size_t>(s)];
    c = clearance(model, x1.segment<3>(3 * s));
    if (!(c > 0)) {
      contacts += resolve_obstacle_contacts(model, s, x0, x1, v1);
      c = 0;
    }
    swept_.segment<3>(3 * s) = x1.segment<3>(3 * s);
    if (!box_current_) continue;
    const Eigen::Vector3d moved = x1.segment<3>(3 * s) - built_at_.segment<3>(3 * s);
    low = low.cwiseMin(moved);
    high = high.cwiseMax(moved);
  }
  low_ = low;
  high_ = high;
  return contacts;
}
// [clamp_sweep]

// [self_collision_pass]
void SelfCollision::find_candidates(const Eigen::Ref<const Eigen::VectorXd>& x) {
  hash_.build(x, rest_);
  hash_.pairs_within(reach_, pairs_, 2 * thickness_ * (1 + 1e-9));
  built_at_ = x;
  candidates_current_ = true;
  indexed_ = false;
  ++work_.builds;
  work_.distance_tests += hash_.distance_tests();
  work_.pairs_found += static_cast<long long>(pairs_.size());
}

// [margin]
// A pair left out of the list was at least the reach r = delta + 2 s apart at the build (s the skin, delta / 4 by
// default). Its particles' displacements since then are u + e_a and u + e_b for any common u, and a common motion
// does not bring them closer: they are now at least r - |e_a| - |e_b| apart. So the list holds while every
// |x - x_built - u| <= s for one u, and
// the u that needs this least is near the centre of the displacements' bounding box: a strip toppling over as a
// whole, or falling, keeps its list longer than the largest displacement alone would allow.
bool SelfCollision::moved_beyond_margin(const Eigen::Ref<const Eigen::VectorXd>& x) const {
  if (!candidates_current_ || built_at_.size() != x.size()) return true;
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
  for (Eigen::Index s = 0; s < x.size(); s += 3) {
    const Eigen::Vector3d moved = x.segment<3>(s) - built_at_.segment<3>(s);
    low = low.cwiseMin(moved);
    high = high.cwiseMax(moved);
  }
  return box_beyond_margin(low, high, x);
}

bool SelfCollision::box_beyond_margin(const Eigen::Vector3d& low, const Eigen::Vector3d& high,
                                      const Eigen::Ref<const Eigen::VectorXd>& x) const {
  const double margin2 = margin_ * margin_;
  const Eigen::Vector3d u = 0.5 * (low + high);
  if (!((high - u).squaredNorm() > margin2)) return false;  // the box's half-diagonal bounds every |e|
  for (Eigen::Index s = 0; s < x.size(); s += 3)
    if (!((x.segment<3>(s) - built_at_.segment<3>(s) - u).squaredNorm() <= margin2)) return true;  // a NaN too
  return false;
}
// [margin]

void SelfCollision::update_candidates(const Eigen::Ref<const Eigen::VectorXd>& x) {
  // The box of the sweep that just measured x, when there was one; else measured here.
  const bool beyond = box_current_ ? box_beyond_margin(low_, high_, x) : moved_beyond_margin(x);
  box_current_ = false;
  if (beyond) {
    find_candidates(x);
  } else {
    ++work_.reuses;
    work_.pairs_found += static_cast<long long>(pairs_.size());
  }
}

// Each particle's candidates as one list of pair numbers, by counting: afterwards the candidates of p are
// pair_index_[pair_start_[p] ... pair_start_[p + 1]), in increasing order.
void SelfCollision::index_candidates() {
  const std::size_t n = static_cast<std::size_t>(rest_.size() / 3), count = pairs_.size();
  pair_start_.assign(n + 1, 0);
  for (const auto& [a, b] : pairs_) {
    ++pair_start_[static_cast<std::size_t>(a) + 1];
    ++pair_start_[static_cast<std::size_t>(b) + 1];
  }
  for (std::size_t p = 1; p <= n; ++p) pair_start_[p] += pair_start_[p - 1];
  pair_index_.resize(2 * count);
  for (std::size_t i = count; i-- > 0;) {
    pair_index_[static_cast<std::size_t>(--pair_start_[static_cast<std::size_t>(pairs_[i].first) + 1])] = static_cast<int>(i);
    pair_index_[static_cast<std::size_t>(--pair_start_[static_cast<std::size_t>(pairs_[i].second) + 1])] = static_cast<int>(i);
  }
  std::rotate(pair_start_.begin(), pair_start_.begin() + 1, pair_start_.end());
  pair_start_.back() = static_cast<int>(2 * count);
  todo_.assign((count + 63) / 64, 0);
  indexed_ = true;
}

// Every candidate in order, without a mark: the first pass, and a later one when marking would cost more.
int SelfCollision::pass_over_all(Eigen::VectorXd& x, Eigen::VectorXd& v) {
  ++work_.full_passes;
  const double reach = (1 - response_slack) * thickness_;
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

int SelfCollision::resolve(Eigen::VectorXd& x, Eigen::VectorXd& v) {
  ++work_.passes;
  moved_now_.assign(static_cast<std::size_t>(x.size() / 3), 0);
  moved_list_.clear();
  return pass_over_all(x, v);
}

void SelfCollision::mark_moved(int p) {
  if (moved_now_[static_cast<std::size_t>(p)] != 0) return;
  moved_now_[static_cast<std::size_t>(p)] = 1;
  moved_list_.push_back(p);
}

void SelfCollision::mark_pairs_of(int p, std::size_t from) {
  const auto first = static_cast<std::size_t>(pair_start_[static_cast<std::size_t>(p)]);
  const auto last = static_cast<std::size_t>(pair_start_[static_cast<std::size_t>(p) + 1]);
  for (std::size_t k = first; k < last; ++k) {
    const auto i = static_cast<std::size_t>(pair_index_[k]);
    if (i >= from) todo_[i / 64] |= std::uint64_t{1} << (i % 64);
  }
}

int SelfCollision::resolve_again(Eigen::VectorXd& x, Eigen::VectorXd& v) {
  ++work_.passes;
  if (!indexed_) index_candidates();  // once per build, and only for a step that needs a second pass
  std::swap(moved_before_, moved_list_);
  moved_list_.clear();
  // The moved particles' candidates; when they are more than a quarter of all, reading every candidate in order
  // costs less than marking theirs and visiting the marks (on the fold, most second passes).
  std::size_t marks = 0;
  for (const int p : moved_before_) {
    const auto s = static_cast<std::size_t>(p);
    moved_now_[s] = 0;
    marks += static_cast<std::size_t>(pair_start_[s + 1] - pair_start_[s]);
  }
  if (4 * marks > pairs_.size()) return pass_over_all(x, v);
  for (const int p : moved_before_) mark_pairs_of(p, 0);
  const double reach = (1 - response_slack) * thickness_;
  int corrected = 0;
  // The marked pairs in order; a pair that moves a particle for the first time in this pass marks that
  // particle's later pairs, which this pass then reaches.
  for (std::size_t w = 0; w < todo_.size(); ++w)
    while (todo_[w] != 0) {
      const std::size_t i = 64 * w + static_cast<std::size_t>(std::countr_zero(todo_[w]));
      todo_[w] &= todo_[w] - 1;
      const auto [a, b] = pairs_[i];
      if (!part_pair(a, b, thickness_, reach, x.data(), v.data())) continue;
      ++corrected;
      for (const int p : {a, b})
        if (moved_now_[static_cast<std::size_t>(p)] == 0) {
          mark_moved(p);
          mark_pairs_of(p, i + 1);
        }
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
  hash_.pairs_within(thickness_, checked_, rest_factor * thickness_ * (1 + 1e-9));
  double closest = thickness_;
  for (const auto& [a, b] : checked_) closest = std::min(closest, (x.segment<3>(3 * b) - x.segment<3>(3 * a)).norm());
  return closest;
}

}  // namespace cloth
