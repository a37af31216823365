// The spatial hash of Teschner et al. 2003, stored as a counting sort, and the momentum-conserving pair response.
#include "contact/spatial_hash.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace cloth {

SpatialHash::SpatialHash(double cell, int buckets)
    : cell_(cell), buckets_(buckets), bucket_start_(static_cast<std::size_t>(buckets) + 1) {}

namespace {

// A cell (i, j, k) packed into one word, each index taken modulo 2^21. Cells 2^21 apart along an axis (31 km at
// the strip's 1.5 cm) share a key and are read together; the distance test then rejects their pairs, so the
// wrap costs time in such a cloud, never a pair, and a key is compared in one instruction.
constexpr int key_bits = 21;
constexpr std::uint64_t key_mask = (std::uint64_t{1} << key_bits) - 1;

std::uint64_t pack(std::uint64_t i, std::uint64_t j, std::uint64_t k) {
  return (i & key_mask) | (j & key_mask) << key_bits | (k & key_mask) << (2 * key_bits);
}

}  // namespace

std::uint64_t SpatialHash::key_of(const Eigen::Ref<const Eigen::Vector3d>& x) const {
  // Unsigned arithmetic: a negative index wraps like any other.
  const auto index = [&](double coordinate) { return static_cast<std::uint64_t>(static_cast<long long>(std::floor(coordinate / cell_))); };
  return pack(index(x[0]), index(x[1]), index(x[2]));
}

std::uint64_t SpatialHash::neighbour(std::uint64_t key, int di, int dj, int dk) {
  return pack((key & key_mask) + static_cast<std::uint64_t>(di), (key >> key_bits & key_mask) + static_cast<std::uint64_t>(dj),
              (key >> (2 * key_bits)) + static_cast<std::uint64_t>(dk));
}

int SpatialHash::bucket(std::uint64_t key) const {
  const std::uint64_t h = (key & key_mask) * 73856093ULL ^ (key >> key_bits & key_mask) * 19349663ULL ^
                          (key >> (2 * key_bits)) * 83492791ULL;
  // Into [0, buckets) without a division (a query hashes 14 cells per occupied cell): the high half of h times
  // 2^64 / golden ratio is spread over [0, 2^32), then scaled by buckets / 2^32 (Lemire's range reduction).
  const std::uint64_t spread = (h * 0x9E3779B97F4A7C15ULL) >> 32;
  return static_cast<int>((spread * static_cast<std::uint64_t>(buckets_)) >> 32);
}

// [hash_build]
void SpatialHash::build(const Eigen::Ref<const Eigen::VectorXd>& x) {
  const auto n = static_cast<int>(x.size() / 3);
  particle_keys_.resize(static_cast<std::size_t>(n));
  for (int p = 0; p < n; ++p) particle_keys_[static_cast<std::size_t>(p)] = key_of(x.segment<3>(3 * p));
  std::fill(bucket_start_.begin(), bucket_start_.end(), 0);
  // Count each bucket's particles, turn the counts into ends, then place each particle by decrementing its end:
  // afterwards bucket_start_[b + 1] is where bucket b starts.
  for (const std::uint64_t key : particle_keys_) ++bucket_start_[static_cast<std::size_t>(bucket(key)) + 1];
  for (std::size_t b = 1; b < bucket_start_.size(); ++b) bucket_start_[b] += bucket_start_[b - 1];
  entries_.resize(static_cast<std::size_t>(n));
  keys_.resize(static_cast<std::size_t>(n));
  for (int p = n - 1; p >= 0; --p) {
    const std::uint64_t key = particle_keys_[static_cast<std::size_t>(p)];
    const auto e = static_cast<std::size_t>(--bucket_start_[static_cast<std::size_t>(bucket(key)) + 1]);
    keys_[e] = key;
    entries_[e] = {x.segment<3>(3 * p), Eigen::Vector3d::Zero(), p};
  }
  // Shift the starts down by one and close the array with the total.
  std::rotate(bucket_start_.begin(), bucket_start_.begin() + 1, bucket_start_.end());
  bucket_start_.back() = n;
  sort_buckets_by_cell();
  has_rest_ = false;
}
// [hash_build]

void SpatialHash::build(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& rest) {
  build(x);
  for (Entry& e : entries_) e.rest = rest.segment<3>(3 * e.particle);
  has_rest_ = true;
}

// Distinct cells that share a bucket are rare with twice as many buckets as particles, so most buckets hold one
// cell and need no sorting; the few that hold two or three are put in order by insertion.
void SpatialHash::sort_buckets_by_cell() {
  for (std::size_t b = 0; b + 1 < bucket_start_.size(); ++b) {
    const auto first = static_cast<std::size_t>(bucket_start_[b]), last = static_cast<std::size_t>(bucket_start_[b + 1]);
    for (std::size_t e = first + 1; e < last; ++e)
      for (std::size_t f = e; f > first && keys_[f] < keys_[f - 1]; --f) {
        std::swap(keys_[f], keys_[f - 1]);
        std::swap(entries_[f], entries_[f - 1]);
      }
  }
}

std::pair<std::size_t, std::size_t> SpatialHash::run_of(std::uint64_t key) const {
  const auto b = static_cast<std::size_t>(bucket(key));
  auto first = static_cast<std::size_t>(bucket_start_[b]);
  const auto end = static_cast<std::size_t>(bucket_start_[b + 1]);
  while (first < end && keys_[first] != key) ++first;
  std::size_t last = first;
  while (last < end && keys_[last] == key) ++last;
  return {first, last};
}

// [hash_query]
void SpatialHash::pairs_within(double r, std::vector<std::pair<int, int>>& pairs, double apart_at_rest) {
  pairs.clear();
  distance_tests_ = 0;
  const double r2 = r * r, rest2 = apart_at_rest * apart_at_rest;
  const bool mesh_aware = has_rest_ && apart_at_rest > 0;
  // Each particle of the run [s, e) against those of [first, last), or only those after it within its own run.
  const auto test_runs = [&](std::size_t s, std::size_t e, std::size_t first, std::size_t last) {
    const bool own = first == s;
    for (std::size_t a = s; a < e; ++a)
      for (std::size_t b = own ? a + 1 : first; b < last; ++b) {
        const Entry& ea = entries_[a];
        const Entry& eb = entries_[b];
        if ((eb.x - ea.x).squaredNorm() < r2 && !(mesh_aware && (eb.rest - ea.rest).squaredNorm() <= rest2))
          pairs.emplace_back(std::min(ea.particle, eb.particle), std::max(ea.particle, eb.particle));
      }
  };
  const std::size_t n = entries_.size();
  for (std::size_t s = 0, e = 0; s < n; s = e) {
    // The run [s, e) of one occupied cell: its own pairs, then its pairs with the 13 neighbouring cells that come
    // after it in the order (di, dj, dk); a pair in two different cells is then found from one of them only.
    const std::uint64_t key = keys_[s];
    for (e = s + 1; e < n && keys_[e] == key; ++e) {}
    test_runs(s, e, s, e);
    distance_tests_ += static_cast<long long>((e - s) * (e - s - 1) / 2);
    for (int di = 0; di <= 1; ++di)
      for (int dj = di == 0 ? 0 : -1; dj <= 1; ++dj)
        for (int dk = di == 0 && dj == 0 ? 1 : -1; dk <= 1; ++dk) {
          const auto [first, last] = run_of(neighbour(key, di, dj, dk));
          test_runs(s, e, first, last);
          distance_tests_ += static_cast<long long>((e - s) * (last - first));
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
