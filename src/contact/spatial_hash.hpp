// The broad phase of self-collision (Chapter 11): a spatial hash (Teschner et al. 2003) that finds every pair of
// particles closer than a distance r in time proportional to the particles, where comparing all pairs costs n^2.
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace cloth {

/// Particles binned by the cubic cell of side `cell` they lie in, each cell (i, j, k) hashed to one of a fixed
/// number of buckets by Teschner et al.'s h = i p1 xor j p2 xor k p3 with p1 = 73856093, p2 = 19349663,
/// p3 = 83492791, reduced to [0, buckets) by a multiplication rather than their mod (a division per cell). The buckets are stored as one array sorted by bucket (a counting sort), so a
/// build allocates nothing once the hash has seen its largest cloud.
class SpatialHash {
 public:
  /// Cells of side `cell` (no smaller than the largest r queried, so that a query looks at a particle's cell and its neighbours only) and
  /// `buckets` buckets (about twice the particles keeps collisions of distinct cells rare).
  SpatialHash(double cell, int buckets);

  /// Bins the particles of x (3 coordinates per particle).
  void build(const Eigen::Ref<const Eigen::VectorXd>& x);

  /// Every pair (a, b), a < b, of the particles last built whose distance is below r (r <= cell), in no
  /// particular order. Each pair once: a particle counts only for the cell it lies in, though its bucket may be
  /// read for another cell that hashes alike.
  void pairs_within(const Eigen::Ref<const Eigen::VectorXd>& x, double r, std::vector<std::pair<int, int>>& pairs) const;

  [[nodiscard]] double cell() const { return cell_; }

 private:
  [[nodiscard]] int bucket(long long i, long long j, long long k) const;
  [[nodiscard]] long long cell_index(double coordinate) const;

  double cell_;
  int buckets_;
  std::vector<int> bucket_start_;  // particles of bucket b: sorted_[bucket_start_[b] .. bucket_start_[b + 1])
  std::vector<int> sorted_;
  std::vector<long long> cells_;  // the cell (i, j, k) of each particle, 3 per particle
  struct Entry {
    int particle;
    long long cell[3];  // NOLINT(*-avoid-c-arrays): three indices read side by side
    Eigen::Vector3d x;
  };
  std::vector<Entry> entries_;  // sorted_ with each particle's cell and position, in bucket order
};

/// The pairs a brute-force comparison of every pair finds: the independent check of the hash.
[[nodiscard]] std::vector<std::pair<int, int>> pairs_within_brute_force(const Eigen::Ref<const Eigen::VectorXd>& x,
                                                                        double r);

/// The response to self-contact of equal-mass particles: each pair (a, b) closer than `thickness` is pushed apart
/// along n = (x_b - x_a) / |x_b - x_a|, each by half of what is missing, and its approaching normal relative
/// velocity is removed by equal and opposite impulses (perfectly inelastic). Both corrections are internal, so
/// the centre of mass and the linear momentum do not change. Pairs closer than thickness but no closer than
/// (1 - slack) thickness are left as they are. Returns the pairs it corrected.
int resolve_self_contacts(const std::vector<std::pair<int, int>>& pairs, double thickness,
                          Eigen::Ref<Eigen::VectorXd> x, Eigen::Ref<Eigen::VectorXd> v, double slack = 0);

}  // namespace cloth
