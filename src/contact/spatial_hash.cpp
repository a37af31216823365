// The spatial hash of Teschner et al. 2003, stored as a counting sort, and the momentum-conserving pair response.
#include "contact/spatial_hash.hpp"

#include <algorithm>
#include <cmath>

namespace cloth {

SpatialHash::SpatialHash(double cell, int buckets)
    : cell_(cell), buckets_(buckets), bucket_start_(static_cast<std::size_t>(buckets) + 1) {}

long long SpatialHash::cell_index(double coordinate) const {
  return static_cast<long long>(std::floor(coordinate / cell_));
}

int SpatialHash::bucket(long long i, long long j, long long k) const {
  // Unsigned arithmetic: the products wrap instead of overflowing, and negative cells hash like any other.
  const auto h = (static_cast<unsigned long long>(i) * 73856093ULL) ^
                 (static_cast<unsigned long long>(j) * 19349663ULL) ^
                 (static_cast<unsigned long long>(k) * 83492791ULL);
  // Into [0, buckets) without a division (a query hashes 14 cells per particle): the high half of h times
  // 2^64 / golden ratio is spread over [0, 2^32), then scaled by buckets / 2^32 (Lemire's range reduction).
  const unsigned long long spread = (h * 0x9E3779B97F4A7C15ULL) >> 32;
  return static_cast<int>((spread * static_cast<unsigned long long>(buckets_)) >> 32);
}

// [hash_build]
void SpatialHash::build(const Eigen::Ref<const Eigen::VectorXd>& x) {
  const auto n = static_cast<int>(x.size() / 3);
  sorted_.resize(static_cast<std::size_t>(n));
  cells_.resize(3 * static_cast<std::size_t>(n));
  for (std::size_t q = 0; q < cells_.size(); ++q) cells_[q] = cell_index(x[static_cast<Eigen::Index>(q)]);
  std::fill(bucket_start_.begin(), bucket_start_.end(), 0);
  const auto bucket_of = [&](int p) {
    const long long* const c = &cells_[3 * static_cast<std::size_t>(p)];
    return bucket(c[0], c[1], c[2]);
  };
  // Count each bucket's particles, turn the counts into ends, then place each particle by decrementing its end:
  // afterwards bucket_start_[b] is where bucket b starts.
  for (int p = 0; p < n; ++p) ++bucket_start_[static_cast<std::size_t>(bucket_of(p)) + 1];
  for (std::size_t b = 1; b < bucket_start_.size(); ++b) bucket_start_[b] += bucket_start_[b - 1];
  for (int p = n - 1; p >= 0; --p) {
    const auto b = static_cast<std::size_t>(bucket_of(p));
    sorted_[static_cast<std::size_t>(--bucket_start_[b + 1])] = p;
  }
  // Each end was decremented once per particle of its bucket, so bucket_start_[b + 1] now holds bucket b's start:
  // shift the array down by one and close it with the total.
  std::rotate(bucket_start_.begin(), bucket_start_.begin() + 1, bucket_start_.end());
  bucket_start_.back() = n;
  // Each bucket's particles with their cells and positions side by side: a query then reads a bucket from one
  // stretch of memory instead of jumping to each particle's entries.
  entries_.resize(static_cast<std::size_t>(n));
  for (std::size_t e = 0; e < entries_.size(); ++e) {
    const int p = sorted_[e];
    const long long* const c = &cells_[3 * static_cast<std::size_t>(p)];
    entries_[e] = {p, {c[0], c[1], c[2]}, x.segment<3>(3 * p)};
  }
}
// [hash_build]

// [hash_query]
void SpatialHash::pairs_within(const Eigen::Ref<const Eigen::VectorXd>& x, double r,
                               std::vector<std::pair<int, int>>& pairs) const {
  pairs.clear();
  const double r2 = r * r;
  const auto n = static_cast<int>(x.size() / 3);
  for (int a = 0; a < n; ++a) {
    const Eigen::Vector3d xa = x.segment<3>(3 * a);
    const long long* const ca = &cells_[3 * static_cast<std::size_t>(a)];
    // Half of the 26 neighbouring cells, those after a's own in the order (di, dj, dk): a pair in two different
    // cells is then found from one of its particles only, and a pair within one cell from its lower index.
    for (long long di = 0; di <= 1; ++di)
      for (long long dj = di == 0 ? 0 : -1; dj <= 1; ++dj)
        for (long long dk = di == 0 && dj == 0 ? 0 : -1; dk <= 1; ++dk) {
          const long long i = ca[0] + di, j = ca[1] + dj, k = ca[2] + dk;
          const bool own = di == 0 && dj == 0 && dk == 0;
          const auto b = static_cast<std::size_t>(bucket(i, j, k));
          const auto end = static_cast<std::size_t>(bucket_start_[b + 1]);
          for (auto e = static_cast<std::size_t>(bucket_start_[b]); e < end; ++e) {
            const Entry& entry = entries_[e];
            const int c = entry.particle;
            // A bucket may hold particles of other cells that hash alike: only those of cell (i, j, k) count
            // here, so each particle is read once per query and each pair found once.
            if ((c > a || !own) && entry.cell[0] == i && entry.cell[1] == j && entry.cell[2] == k &&
                (entry.x - xa).squaredNorm() < r2)
              pairs.emplace_back(std::min(a, c), std::max(a, c));
          }
        }
  }
}
// [hash_query]

std::vector<std::pair<int, int>> pairs_within_brute_force(const Eigen::Ref<const Eigen::VectorXd>& x, double r) {
  std::vector<std::pair<int, int>> pairs;
  const auto n = static_cast<int>(x.size() / 3);
  for (int a = 0; a < n; ++a)
    for (int c = a + 1; c < n; ++c)
      if ((x.segment<3>(3 * c) - x.segment<3>(3 * a)).squaredNorm() < r * r) pairs.emplace_back(a, c);
  return pairs;
}

// [self_contact]
int resolve_self_contacts(const std::vector<std::pair<int, int>>& pairs, double thickness,
                          Eigen::Ref<Eigen::VectorXd> x, Eigen::Ref<Eigen::VectorXd> v, double slack) {
  int corrected = 0;
  const double reach = (1 - slack) * thickness;
  for (const auto& [a, b] : pairs) {
    const Eigen::Vector3d ab = x.segment<3>(3 * b) - x.segment<3>(3 * a);
    const double distance = ab.norm();
    if (!(distance < reach) || distance == 0) continue;  // coincident particles have no direction to part in
    ++corrected;
    const Eigen::Vector3d n = ab / distance;
    // Equal masses: equal and opposite moves keep the centre of mass where it is.
    const Eigen::Vector3d half_gap = 0.5 * (thickness - distance) * n;
    x.segment<3>(3 * a) -= half_gap;
    x.segment<3>(3 * b) += half_gap;
    // Equal and opposite impulses remove the approaching normal relative velocity and keep the momentum.
    const double approach = (v.segment<3>(3 * b) - v.segment<3>(3 * a)).dot(n);
    if (approach < 0) {
      v.segment<3>(3 * a) += 0.5 * approach * n;
      v.segment<3>(3 * b) -= 0.5 * approach * n;
    }
  }
  return corrected;
}
// [self_contact]

}  // namespace cloth
