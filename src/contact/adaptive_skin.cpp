// The candidate list with a skin per particle: references binned in a hash of cells of the query's reach, moved
// between cells one particle at a time.
#include "contact/adaptive_skin.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace cloth {

AdaptiveSkinList::AdaptiveSkinList(Eigen::VectorXd rest, double thickness, double max_radius, double min_gap,
                                   bool follow_common_motion)
    : rest_(std::move(rest)), thickness_(thickness), max_radius_(max_radius), min_gap_(min_gap),
      reach_(thickness + 2 * max_radius), follow_(follow_common_motion) {
  const auto n = static_cast<std::size_t>(rest_.size() / 3);
  reference_.resize(n);
  radius_.assign(n, 0);
  queried_.assign(n, 0);
  partners_.resize(n);
  buckets_.resize(std::max<std::size_t>(16, 2 * n));
  bucket_.assign(n, 0);
}

bool AdaptiveSkinList::apart_at_rest(int a, int b) const {
  return (rest_.segment<3>(3 * b) - rest_.segment<3>(3 * a)).norm() > 2 * thickness_ * (1 + 1e-9);
}

// The cell of side reach_ that y lies in.
Eigen::Array3i AdaptiveSkinList::cell_of(const Eigen::Vector3d& y) const {
  // Clamped, so that a far or non-finite reference lands in some cell rather than overflowing an int.
  const auto index = [&](double c) {
    const double k = std::floor(c / reach_);
    return static_cast<int>(k >= -1e9 && k <= 1e9 ? k : 0);
  };
  return {index(y.x()), index(y.y()), index(y.z())};
}

// A cell hashed as in Teschner et al. 2003.
std::size_t AdaptiveSkinList::bucket_of(const Eigen::Array3i& c) const {
  const auto u = [](int k) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(k)); };
  const std::uint64_t h = u(c.x()) * 73856093ULL ^ u(c.y()) * 19349663ULL ^ u(c.z()) * 83492791ULL;
  return static_cast<std::size_t>(h % buckets_.size());
}

int AdaptiveSkinList::update(const Eigen::Ref<const Eigen::VectorXd>& x) {
  const auto n = static_cast<int>(reference_.size());
  if (follow_ && queries_ > 0) {
    Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), high = -low;
    for (int p = 0; p < n; ++p) {
      const Eigen::Vector3d drift = x.segment<3>(3 * p) - reference_[static_cast<std::size_t>(p)];
      low = low.cwiseMin(drift);
      high = high.cwiseMax(drift);
    }
    frame_ = 0.5 * (low + high);
  }
  int queried = 0;
  for (int p = 0; p < n; ++p) {
    const auto s = static_cast<std::size_t>(p);
    const Eigen::Vector3d y = x.segment<3>(3 * p) - frame_;
    if (queried_[s] != 0 && (y - reference_[s]).norm() <= radius_[s]) continue;
    query(p, y);
    ++queried;
  }
  return queried;
}

// [adaptive_query]
void AdaptiveSkinList::query(int p, const Eigen::Vector3d& y) {
  const auto s = static_cast<std::size_t>(p);
  for (const int b : partners_[s]) std::erase(partners_[static_cast<std::size_t>(b)], p);
  partners_[s].clear();
  if (queried_[s] != 0) std::erase(buckets_[bucket_[s]], p);
  reference_[s] = y;
  const Eigen::Array3i cell = cell_of(y);
  bucket_[s] = bucket_of(cell);
  buckets_[bucket_[s]].push_back(p);
  queried_[s] = 1;
  ++queries_;
  // The 27 cells around y's, each bucket visited once (two cells may share one).
  std::array<std::size_t, 27> visited{};
  std::size_t count = 0;
  double radius = max_radius_;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        const std::size_t bucket = bucket_of(cell + Eigen::Array3i(i, j, k));
        if (std::find(visited.begin(), visited.begin() + static_cast<std::ptrdiff_t>(count), bucket) !=
            visited.begin() + static_cast<std::ptrdiff_t>(count))
          continue;
        visited[count++] = bucket;
        for (const int b : buckets_[bucket]) {
          if (b == p) continue;
          ++distance_tests_;
          const auto t = static_cast<std::size_t>(b);
          const double distance = (reference_[t] - y).norm();
          if (!(distance < reach_) || !apart_at_rest(p, b)) continue;  // beyond the reach the gap is >= max_radius_
          // The gap between p's reference and b's ball, less the thickness: p may move that far and stay clear.
          const double gap = distance - radius_[t] - thickness_;
          if (gap < min_gap_) {
            partners_[s].push_back(b);
            partners_[t].push_back(p);
          } else {
            radius = std::min(radius, gap);
          }
        }
      }
  radius_[s] = radius;
  radii_ += radius;
}
// [adaptive_query]

bool AdaptiveSkinList::holds(int a, int b) const {
  const std::vector<int>& list = partners_[static_cast<std::size_t>(a)];
  return std::find(list.begin(), list.end(), b) != list.end();
}

long long AdaptiveSkinList::pairs() const {
  long long total = 0;
  for (const std::vector<int>& list : partners_) total += static_cast<long long>(list.size());
  return total / 2;
}

}  // namespace cloth
