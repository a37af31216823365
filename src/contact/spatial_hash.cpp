// The spatial hash of Teschner et al. 2003, stored as a counting sort, and the brute-force search that checks it.
#include "contact/spatial_hash.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace cloth {

SpatialHash::SpatialHash(double cell, int buckets)
    : cell_(cell), buckets_(buckets), bucket_start_(static_cast<std::size_t>(buckets) + 1) {}

namespace {

// A cell index along an axis, offset by 2^20 and clamped to [0, 2^21): monotone, and cells next to each other stay
// next to each other or merge. A cell 2^20 cells from the origin (4 km at the strip's 1.5 cm / 4 in height) is
// merged with all beyond it: such a cloud costs time in the merged cell, never a pair, and a key is compared in one
// instruction.
constexpr int key_bits = 21;
// Heights are binned 4 times finer than the cell: a pair closer than the cell is at most 4 such slices apart, so
// beside each particle a query reads a window 9/4 cells tall rather than the 3 cells of a cubic grid's neighbours.
constexpr std::uint64_t slices = 4;
constexpr std::uint64_t key_mask = (std::uint64_t{1} << key_bits) - 1;
constexpr double index_offset = 1 << (key_bits - 1);

std::uint64_t index_of(double coordinate, double cell) {
  const double k = std::floor(coordinate / cell) + index_offset;
  constexpr auto top = static_cast<double>(key_mask);
  return static_cast<std::uint64_t>(k >= 0 ? (k <= top ? k : top) : 0);  // a NaN lands in cell 0
}

// The height k of a key, and the column (i, j) it lies in.
std::uint64_t height(std::uint64_t key) { return key & key_mask; }
std::uint64_t column(std::uint64_t key) { return key >> key_bits; }

}  // namespace

std::uint64_t SpatialHash::key_of(double x, double y, double z) const {
  return index_of(x, cell_) << (2 * key_bits) | index_of(y, cell_) << key_bits | index_of(z, cell_ / slices);
}

int SpatialHash::bucket(std::uint64_t column) const {
  const std::uint64_t h = (column >> key_bits) * 73856093ULL ^ (column & key_mask) * 19349663ULL;
  // Into [0, buckets) without a division: h times 2^64 / golden ratio spreads its bits into the high half, whose
  // top 32 bits are scaled by buckets / 2^32 (Lemire's range reduction).
  const std::uint64_t spread = (h * 0x9E3779B97F4A7C15ULL) >> 32;
  return static_cast<int>((spread * static_cast<std::uint64_t>(buckets_)) >> 32);
}

// [hash_build]
void SpatialHash::build(const Eigen::Ref<const Eigen::VectorXd>& x) {
  const auto n = static_cast<int>(x.size() / 3);
  particle_keys_.resize(static_cast<std::size_t>(n));
  sorted_.resize(static_cast<std::size_t>(n));
  for (int p = 0; p < n; ++p) particle_keys_[static_cast<std::size_t>(p)] = {key_of(x[3 * p], x[3 * p + 1], x[3 * p + 2]), p};
  // Count each bucket's particles, turn the counts into ends, then place each particle by decrementing its end:
  // afterwards bucket_start_[b + 1] is where bucket b starts.
  std::fill(bucket_start_.begin(), bucket_start_.end(), 0);
  for (const Keyed& k : particle_keys_) ++bucket_start_[static_cast<std::size_t>(bucket(column(k.key))) + 1];
  for (std::size_t b = 1; b < bucket_start_.size(); ++b) bucket_start_[b] += bucket_start_[b - 1];
  for (int p = n - 1; p >= 0; --p) {
    const Keyed& k = particle_keys_[static_cast<std::size_t>(p)];
    sorted_[static_cast<std::size_t>(--bucket_start_[static_cast<std::size_t>(bucket(column(k.key))) + 1])] = k;
  }
  // Shift the starts down by one and close the array with the total.
  std::rotate(bucket_start_.begin(), bucket_start_.begin() + 1, bucket_start_.end());
  bucket_start_.back() = n;
  sort_buckets();
  gather(x);
  has_rest_ = false;
}
// [hash_build]

void SpatialHash::build(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& rest) {
  build(x);
  const std::size_t n = particle_.size();
  rx_.resize(n);
  ry_.resize(n);
  rz_.resize(n);
  for (std::size_t e = 0; e < n; ++e) {
    const Eigen::Index p = 3 * static_cast<Eigen::Index>(particle_[e]);
    rx_[e] = rest[p];
    ry_[e] = rest[p + 1];
    rz_[e] = rest[p + 2];
  }
  has_rest_ = true;
}

// Within a bucket, by column and then upwards. Most buckets hold one short column and are put in order by
// insertion; the rare long one (a pile, or many columns sharing a bucket) by std::sort, which allocates nothing.
void SpatialHash::sort_buckets() {
  const auto by_key = [](const Keyed& a, const Keyed& b) { return a.key < b.key; };
  for (std::size_t b = 0; b + 1 < bucket_start_.size(); ++b) {
    const auto first = static_cast<std::size_t>(bucket_start_[b]), last = static_cast<std::size_t>(bucket_start_[b + 1]);
    if (last - first > 16) {
      std::sort(sorted_.begin() + static_cast<std::ptrdiff_t>(first), sorted_.begin() + static_cast<std::ptrdiff_t>(last), by_key);
      continue;
    }
    for (std::size_t e = first + 1; e < last; ++e)
      for (std::size_t f = e; f > first && sorted_[f].key < sorted_[f - 1].key; --f) std::swap(sorted_[f], sorted_[f - 1]);
  }
}

// The sorted entries' keys, particles and positions as separate arrays, read contiguously by a query.
void SpatialHash::gather(const Eigen::Ref<const Eigen::VectorXd>& x) {
  const std::size_t n = sorted_.size();
  keys_.resize(n);
  particle_.resize(n);
  close_.resize(n);
  px_.resize(n);
  py_.resize(n);
  pz_.resize(n);
  for (std::size_t e = 0; e < n; ++e) {
    keys_[e] = sorted_[e].key;
    particle_[e] = sorted_[e].particle;
    const Eigen::Index p = 3 * static_cast<Eigen::Index>(sorted_[e].particle);
    px_[e] = x[p];
    py_[e] = x[p + 1];
    pz_[e] = x[p + 2];
  }
}

std::pair<std::size_t, std::size_t> SpatialHash::run_of(std::uint64_t col) const {
  const auto b = static_cast<std::size_t>(bucket(col));
  auto first = static_cast<std::size_t>(bucket_start_[b]);
  const auto end = static_cast<std::size_t>(bucket_start_[b + 1]);
  while (first < end && column(keys_[first]) != col) ++first;
  std::size_t last = first;
  while (last < end && column(keys_[last]) == col) ++last;
  return {first, last};
}

// [hash_window]
// Entry a against the entries [first, last), without a branch on the outcome: in a crumpled cloth a large part of
// the distances tested are close pairs, in an irregular order that defeats a processor's branch prediction, so
// each entry is written to the end of a scratch list whose end moves past it only when it is kept (both tests,
// the distance now and the distance at rest, computed for every entry from contiguous arrays).
template <bool mesh_aware>
void SpatialHash::test_window(std::size_t a, std::size_t first, std::size_t last, double r2, double rest2,
                              std::vector<std::pair<int, int>>& pairs) {
  const double xa = px_[a], ya = py_[a], za = pz_[a];
  const double* px = px_.data();
  const double* py = py_.data();
  const double* pz = pz_.data();
  const double* rx = rx_.data();
  const double* ry = ry_.data();
  const double* rz = rz_.data();
  int* close = close_.data();
  std::size_t kept = 0;
  if constexpr (mesh_aware) {
    const double rxa = rx[a], rya = ry[a], rza = rz[a];
    for (std::size_t b = first; b < last; ++b) {
      const double dx = px[b] - xa, dy = py[b] - ya, dz = pz[b] - za;
      const double ex = rx[b] - rxa, ey = ry[b] - rya, ez = rz[b] - rza;
      const unsigned keep = static_cast<unsigned>(dx * dx + dy * dy + dz * dz < r2) &
                            static_cast<unsigned>(ex * ex + ey * ey + ez * ez > rest2);
      close[kept] = static_cast<int>(b);
      kept += keep;
    }
  } else {
    for (std::size_t b = first; b < last; ++b) {
      const double dx = px[b] - xa, dy = py[b] - ya, dz = pz[b] - za;
      close[kept] = static_cast<int>(b);
      kept += static_cast<unsigned>(dx * dx + dy * dy + dz * dz < r2);
    }
  }
  const int pa = particle_[a];
  for (std::size_t c = 0; c < kept; ++c) {
    const int pb = particle_[static_cast<std::size_t>(close[c])];
    pairs.emplace_back(std::min(pa, pb), std::max(pa, pb));
  }
}
// [hash_window]

// [hash_query]
void SpatialHash::pairs_within(double r, std::vector<std::pair<int, int>>& pairs, double apart_at_rest) {
  pairs.clear();
  distance_tests_ = 0;
  const double r2 = r * r, rest2 = apart_at_rest * apart_at_rest;
  const bool mesh_aware = has_rest_ && apart_at_rest > 0;
  const auto test = [&](std::size_t a, std::size_t first, std::size_t last) {
    distance_tests_ += static_cast<long long>(last - first);
    if (mesh_aware) test_window<true>(a, first, last, r2, rest2, pairs);
    else test_window<false>(a, first, last, r2, rest2, pairs);
  };
  const std::size_t n = keys_.size();
  for (std::size_t s = 0, e = 0; s < n; s = e) {
    // The run [s, e) of one occupied column, ordered upwards. Its own pairs: each entry with those after it at
    // most 4 slices higher.
    const std::uint64_t col = column(keys_[s]);
    for (e = s + 1; e < n && column(keys_[e]) == col; ++e) {}
    for (std::size_t a = s, last = s; a < e; ++a) {
      last = std::max(last, a + 1);
      while (last < e && height(keys_[last]) <= height(keys_[a]) + slices) ++last;
      test(a, a + 1, last);
    }
    // Its pairs with the four neighbouring columns that come after it in the order (di, dj), (0, 1), (1, -1),
    // (1, 0), (1, 1): the other four find the same pairs from the other column. Both columns go upwards, so
    // the window of slices k - 4 .. k + 4 beside entry a only moves up as a does.
    const std::uint64_t i = col >> key_bits, j = col & key_mask;
    for (const auto& [di, dj] : {std::pair{0, 1}, std::pair{1, -1}, std::pair{1, 0}, std::pair{1, 1}}) {
      const std::uint64_t ni = i + static_cast<std::uint64_t>(di), nj = j + static_cast<std::uint64_t>(dj);
      if (ni > key_mask || nj > key_mask) continue;  // beyond the clamped range (j - 1 of j = 0 wraps to 2^64 - 1)
      const auto [first, last] = run_of(ni << key_bits | nj);
      for (std::size_t a = s, lo = first, hi = first; a < e; ++a) {
        const std::uint64_t k = height(keys_[a]);
        while (lo < last && height(keys_[lo]) + slices < k) ++lo;
        hi = std::max(hi, lo);
        while (hi < last && height(keys_[hi]) <= k + slices) ++hi;
        test(a, lo, hi);
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

}  // namespace cloth
