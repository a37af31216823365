// The broad phase of self-collision (Chapter 11): a spatial hash (Teschner et al. 2003) that finds every pair of
// particles closer than a distance r in time proportional to the particles, where comparing all pairs costs n^2.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace cloth {

/// Particles binned by the cubic cell of side `cell` they lie in. Cells are grouped into columns (i, j), the cells
/// of one column one above the other, and each column is hashed to one of a fixed number of buckets by Teschner et
/// al.'s h = i p1 xor j p2 with p1 = 73856093, p2 = 19349663, reduced to [0, buckets) by a multiplication rather
/// than their mod (a division per column). The particles are stored as one array sorted by bucket (a counting sort)
/// and, within a bucket, by column and then by height k, so that each column is one contiguous run ordered upwards:
/// a query looks up each neighbouring column once per column and walks up it beside its own, where a hash of
/// cells would look up each of 13 neighbouring cells once per cell. Positions are stored coordinate by coordinate
/// in that order, so a query reads them as contiguous arrays. A build allocates nothing once the hash has seen its
/// largest cloud.
class SpatialHash {
 public:
  /// Cells of side `cell` (no smaller than the largest r queried, so that a query looks at a cell and its neighbours
  /// only) and `buckets` buckets (about twice the particles keeps collisions of distinct columns rare).
  SpatialHash(double cell, int buckets);

  /// Bins the particles of x (3 coordinates per particle).
  void build(const Eigen::Ref<const Eigen::VectorXd>& x);
  /// Bins the particles of x with their rest positions (3 per particle), so that a query can leave out the pairs
  /// that were near each other at rest: the mesh's own neighbours.
  void build(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::VectorXd>& rest);

  /// Every pair (a, b), a < b, of the particles last built whose distance is below r (r <= cell), in no
  /// particular order, each once. With `apart_at_rest` > 0 (and rest positions built) only the pairs whose rest
  /// positions are farther apart than it: the neighbours at rest are tested and dropped inside the loop, never
  /// stored.
  void pairs_within(double r, std::vector<std::pair<int, int>>& pairs, double apart_at_rest = 0);

  [[nodiscard]] double cell() const { return cell_; }
  /// The distances the last query computed: its candidates, every pair of particles in neighbouring cells.
  [[nodiscard]] long long distance_tests() const { return distance_tests_; }

 private:
  struct Keyed {
    std::uint64_t key;  // column (i, j) in the high bits, height k in the low ones
    int particle;
  };

  [[nodiscard]] std::uint64_t key_of(double x, double y, double z) const;
  [[nodiscard]] int bucket(std::uint64_t column) const;
  /// The run [first, last) of the entries that lie in the column `column`; empty when none do.
  [[nodiscard]] std::pair<std::size_t, std::size_t> run_of(std::uint64_t column) const;
  void sort_buckets();
  template <bool mesh_aware>
  void test_window(std::size_t a, std::size_t first, std::size_t last, double r2, double rest2,
                   std::vector<std::pair<int, int>>& pairs);
  void gather(const Eigen::Ref<const Eigen::VectorXd>& x);

  double cell_;
  int buckets_;
  bool has_rest_ = false;
  long long distance_tests_ = 0;
  std::vector<int> bucket_start_;  // entries of bucket b: [bucket_start_[b], bucket_start_[b + 1])
  std::vector<Keyed> particle_keys_;  // each particle's cell, in particle order
  std::vector<Keyed> sorted_;         // the same, in bucket order, then column, then height
  std::vector<std::uint64_t> keys_;   // the cell of each entry, in the sorted order
  std::vector<int> particle_;         // the particle of each entry
  std::vector<int> close_;            // scratch: the entries of a window that a query keeps
  std::vector<double> px_, py_, pz_, rx_, ry_, rz_;  // positions and rest positions of the entries
};

/// The pairs a brute-force comparison of every pair finds: the independent check of the hash.
[[nodiscard]] std::vector<std::pair<int, int>> pairs_within_brute_force(const Eigen::Ref<const Eigen::VectorXd>& x,
                                                                        double r);

}  // namespace cloth
