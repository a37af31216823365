// Self-collision in a run (Chapter 11): each step, the spatial hash finds the particles closer than the cloth's
// thickness, the pairs that were not already that close at rest are parted by the momentum-conserving response,
// and a clamp on each particle's displacement per step stops two particles from passing through each other.
#pragma once

#include "contact/spatial_hash.hpp"

#include "contact/obstacles.hpp"

#include <Eigen/Core>
#include <cstdint>
#include <utility>
#include <vector>

namespace cloth {

/// The response to one pair (a, b) of equal-mass particles of x and v (3 coordinates each) closer than `reach`:
/// parted along the line between them to `thickness`, its approaching normal velocity removed. Returns whether it
/// moved them.
bool part_pair(int a, int b, double thickness, double reach, double* x, double* v);

/// The response to self-contact of equal-mass particles: each pair (a, b) closer than `thickness` is pushed apart
/// along n = (x_b - x_a) / |x_b - x_a|, each by half of what is missing, and its approaching normal relative
/// velocity is removed by equal and opposite impulses (perfectly inelastic). Both corrections are internal, so
/// the centre of mass and the linear momentum do not change. Pairs closer than thickness but no closer than
/// (1 - slack) thickness are left as they are. Returns the pairs it corrected.
int resolve_self_contacts(const std::vector<std::pair<int, int>>& pairs, double thickness,
                          Eigen::Ref<Eigen::VectorXd> x, Eigen::Ref<Eigen::VectorXd> v, double slack = 0);

/// What self-collision did in one call, and the wall time it took (the chapter weighs it against the forces).
struct SelfCollisionWork {
  long long pairs_found = 0;      ///< close pairs the hash returned, over all passes
  long long pairs_corrected = 0;  ///< of them, pairs the response moved
  long long clamped = 0;          ///< particles whose displacement the clamp shortened
  long long builds = 0;           ///< hash builds and queries
  long long reuses = 0;           ///< steps that kept the last build's candidates (no particle moved a margin)
  long long distance_tests = 0;   ///< distances the hash's queries computed
  long long passes = 0;           ///< response passes over the candidates
  long long full_passes = 0;      ///< of them, passes that read every candidate in order (the others, marked ones)
  double seconds = 0;             ///< processor seconds of the clamp, hash builds, queries and responses
  /// Of them, the sweep's (clamp_and_correct): the clamp and the obstacle correction of every particle, which a
  /// step without self-collision makes too.
  double sweep_seconds = 0;
  /// Of them, the response's passes with the obstacle corrections between them (resolve, resolve_again and
  /// correct_moved); the rest is the hash's builds and queries and the margin's checks.
  double pass_seconds = 0;
};

/// The particles of one cloth, their rest positions (3 per particle, the flat sheet the scene starts from) and the
/// thickness delta. A pair is a self-contact when it is closer than delta now and was farther than 2 delta apart
/// at rest: nearer pairs are grid neighbours (at spacing delta, the ends of a spring), held apart by their springs.
class SelfCollision {
 public:
  /// `skin` is the kept list's skin as a fraction s of delta (the comments below are written for the default,
  /// 1/4): the hash's reach is (1 + 2 s) delta, and a list is kept while every particle lies within s delta of the
  /// common motion. Chapter 11 measures the choice (`--skin`).
  SelfCollision(Eigen::VectorXd rest_positions, double thickness, double skin = 0.25);

  /// Shortens the displacement x1 - x0 of each particle to at most delta / 2, and its velocity v1 to at most
  /// delta / (2 h), keeping their directions. Two particles then move at most delta relative to each other in a
  /// step, so neither can jump over the other's centre without ending the step inside its delta-ball, where
  /// the hash sees it. Returns the particles clamped.
  int clamp(const Eigen::Ref<const Eigen::VectorXd>& x0, double h, Eigen::Ref<Eigen::VectorXd> x1,
            Eigen::Ref<Eigen::VectorXd> v1) const;

  /// What a step does to every particle before the self-contacts, in one sweep over the particles rather than
  /// three: the clamp, the obstacle correction (resolve_obstacle_contacts) and, for the margin check of
  /// update_candidates, the bounding box of the displacements since the last build. Each particle's clamp and
  /// correction depend on it alone, so the result is that of clamp followed by resolve_obstacle_contacts.
  /// Returns the particle-obstacle contacts; the particles clamped are counted in work().
  int clamp_and_correct(const ContactModel& model, const Eigen::Ref<const Eigen::VectorXd>& x0, double h,
                        Eigen::Ref<Eigen::VectorXd> x1, Eigen::Ref<Eigen::VectorXd> v1);

  /// The obstacle correction after a pass, of the particles it moved (moved()) that may have come within an
  /// obstacle's shell: those no closer to where clamp_and_correct left them than their clearance then
  /// (obstacles.hpp, clearance) are left alone. The result is that of resolve_obstacle_contacts on moved().
  int correct_moved(const ContactModel& model, const Eigen::Ref<const Eigen::VectorXd>& x0,
                    Eigen::Ref<Eigen::VectorXd> x1, Eigen::Ref<Eigen::VectorXd> v1) const;

  /// Builds the hash on x and keeps the candidate pairs: closer than 1.5 delta, and farther than 2 delta apart at
  /// rest (the hash leaves the mesh's neighbours out as it finds them). Particles move little while their contacts
  /// are resolved, so the passes that follow read this list rather than query the hash again.
  void find_candidates(const Eigen::Ref<const Eigen::VectorXd>& x);

  /// The candidates for x: those of the last build while every particle's displacement since then lies within
  /// delta / 4 of one displacement u common to all, else find_candidates(x). A pair left out was at least 1.5 delta
  /// apart at the build and u does not bring it closer, so it is still at least 1.5 delta - 2 (delta / 4) = delta
  /// apart: the kept list holds every contact (a Verlet list with a skin, measured from the common motion).
  void update_candidates(const Eigen::Ref<const Eigen::VectorXd>& x);

  /// Whether some particle of x lies more than delta / 4 from its position at the last build moved by u, the centre
  /// of the displacements' bounding box (or nothing was built): then the candidates may miss a contact.
  [[nodiscard]] bool moved_beyond_margin(const Eigen::Ref<const Eigen::VectorXd>& x) const;

  /// The response leaves a pair alone once it is no closer than (1 - response_slack) delta: a pair parted to
  /// delta exactly is not reopened for rounding, and a pile whose pairs all lie within 0.6 % of delta, inside the
  /// 1 % the chapter promises with 0.4 % to spare, needs no more passes (on the fold, 0.3 % took 6.0 passes per
  /// step and 0.6 % takes 4.6; 0.9 % saves no more).
  static constexpr double response_slack = 6e-3;

  /// One pass over the candidates: the pairs closer than delta (1 - response_slack) parted to delta (part_pair).
  /// Returns the pairs corrected; a caller repeats it (resolve_again) until none is (a correction may bring another
  /// pair too close), and the passes end once every pair is within response_slack of the thickness.
  int resolve(Eigen::VectorXd& x, Eigen::VectorXd& v);

  /// The next pass, over the candidates that may have changed since the last: those with a particle that the last
  /// pass moved (listed by moved(), which is all the obstacles' correction between passes may move) or that this
  /// pass moved before reaching them. Every other pair is where the last pass found it, or left it, apart, so the
  /// result is that of a full pass, in the same order. The pairs to visit are marked in a bit per candidate,
  /// reached from the moved particles through each particle's list of candidates, and read in order: a pass costs
  /// the moved particles' pairs, not a sweep over every candidate. When those are more than a quarter of all the
  /// candidates, the pass reads every candidate in order instead, as resolve does, which then costs less.
  int resolve_again(Eigen::VectorXd& x, Eigen::VectorXd& v);

  /// The particles the last pass moved, each once.
  [[nodiscard]] const std::vector<int>& moved() const { return moved_list_; }

  /// The candidates of the last find_candidates.
  [[nodiscard]] const std::vector<std::pair<int, int>>& candidates() const { return pairs_; }
  /// The candidates of x by brute force: the check of the hash in a run.
  [[nodiscard]] std::vector<std::pair<int, int>> candidates_brute_force(const Eigen::Ref<const Eigen::VectorXd>& x) const;

  /// The smallest distance between particles farther apart than `rest_factor` delta at rest (the chapter's check:
  /// rest_factor = 2; pairs exactly that far apart at rest, up to rounding, are not), found by the hash; delta when
  /// no such pair is closer than delta.
  [[nodiscard]] double closest_distance(const Eigen::Ref<const Eigen::VectorXd>& x, double rest_factor);

  [[nodiscard]] double thickness() const { return thickness_; }
  [[nodiscard]] const SelfCollisionWork& work() const { return work_; }
  void add_seconds(double s) { work_.seconds += s; }
  void add_sweep_seconds(double s) { work_.sweep_seconds += s; }
  void add_pass_seconds(double s) { work_.pass_seconds += s; }
  void count_clamped(int n) { work_.clamped += n; }

 private:
  [[nodiscard]] bool apart_at_rest(int a, int b) const;
  int pass_over_all(Eigen::VectorXd& x, Eigen::VectorXd& v);
  void mark_moved(int p);  // flags p in moved_now_ and lists it, once
  void index_candidates();  // each particle's candidates (pair_start_, pair_index_), once per build
  void mark_pairs_of(int p, std::size_t from);  // marks p's candidates numbered from `from` on in todo_
  [[nodiscard]] bool box_beyond_margin(const Eigen::Vector3d& low, const Eigen::Vector3d& high,
                                       const Eigen::Ref<const Eigen::VectorXd>& x) const;

  Eigen::VectorXd rest_;
  Eigen::VectorXd built_at_;  // the positions of the last find_candidates
  bool candidates_current_ = false;
  double thickness_;
  double margin_;  // the skin s delta
  double reach_;   // the candidates' distance (1 + 2 s) delta
  SpatialHash hash_;
  std::vector<std::pair<int, int>> pairs_;  // reused: a step allocates nothing once it has seen its most pairs
  std::vector<std::pair<int, int>> checked_;  // the pairs closest_distance looked at
  std::vector<unsigned char> moved_now_;     // per particle: moved by this pass
  std::vector<int> moved_list_;              // the particles moved_now_ flags
  std::vector<int> moved_before_;            // the particles the last pass moved
  std::vector<int> pair_start_, pair_index_;  // particle p's candidates: pair_index_[pair_start_[p] ...]
  std::vector<std::uint64_t> todo_;           // one bit per candidate: to be visited by this pass
  bool indexed_ = false;                      // pair_start_, pair_index_ and todo_ describe the candidates
  bool box_current_ = false;                  // low_, high_ measured on the positions update_candidates gets
  Eigen::Vector3d low_, high_;                // the bounding box of the displacements since the last build
  std::vector<double> clearance_;  // each particle's clearance from the obstacles after clamp_and_correct, 0 in contact
  Eigen::VectorXd swept_;          // the positions clamp_and_correct left
  SelfCollisionWork work_;
};

}  // namespace cloth
