// How far a simulated motion of the cloth is from a reference motion (Chapter 10): the size of the motion itself,
// the position error at the end and over every frame, the energy lost beyond the reference, the largest stretch of
// a spring, and when the swing turns; with the rule that an accuracy level the rest state already meets measures
// nothing. Every measure takes frames as the driver records them: every particle's position, in grid order.
#pragma once

#include "integrators/simulate.hpp"
#include "model/scene.hpp"

#include <string>
#include <vector>

namespace cloth {

/// The largest distance between corresponding particles of two position vectors (3 per particle, same order) [m].
[[nodiscard]] double largest_distance(const Vector& a, const Vector& b);

/// The largest distance of a run from its reference: at the last frame, and over every frame of the run.
struct TrajectoryError {
  double at_end = 0;       ///< at the last frame [m]
  double over_frames = 0;  ///< the largest over every frame [m]
  double worst_time = 0;   ///< the time of the frame where it is largest [s]
};

/// The error of `run` against `reference`: each frame of the run is compared with the reference frame of the same
/// time (to 1e-9 s), so a run whose step is longer than the reference's frame interval is compared at its own
/// frames only. Throws std::invalid_argument when a frame of the run has no reference frame at its time, or when
/// the run ends before the reference (a run that stopped early has no error at T).
[[nodiscard]] TrajectoryError trajectory_error(const std::vector<Frame>& run, const std::vector<Frame>& reference);

/// The size of the motion: the error of a cloth that never moves from its first frame, against the reference.
/// An accuracy level at least this large is met by standing still.
[[nodiscard]] TrajectoryError motion_size(const std::vector<Frame>& reference);

/// The largest strain |l / L0 - 1| of a spring of `scene` in the state `positions` (every particle, grid order).
[[nodiscard]] double largest_strain(const Scene& scene, const Vector& positions);
/// The largest strain over every frame.
[[nodiscard]] double largest_strain(const Scene& scene, const std::vector<Frame>& frames);

/// The mean height z of the row j = 0, the edge opposite the pinned edge j = N-1 of `--pins edge`, frame by frame.
[[nodiscard]] std::vector<double> free_edge_height(const Grid& grid, const std::vector<Frame>& frames);

/// The time of the first local minimum of the samples y(t_k): the first k with y_{k-1} > y_k <= y_{k+1}, refined
/// to the vertex of the parabola through the three samples (exact for a quadratic, error O(dt^2) for a smooth
/// curve). NaN when no sample inside the horizon is a minimum: the horizon does not contain it. Throws
/// std::invalid_argument when t and y differ in length.
[[nodiscard]] double first_minimum_time(const std::vector<double>& t, const std::vector<double>& y);

/// Energy a run lost beyond what the reference lost, at the same time: E_reference - E_run [J] (positive when the
/// run dissipated more), and that as a fraction of `scale`, for example the reference's largest kinetic energy.
struct EnergyLoss {
  double joules = 0;
  double fraction = 0;
};
[[nodiscard]] EnergyLoss energy_lost(const Energy& run, const Energy& reference, double scale);

/// Whether a run reached an accuracy level. The rule of the book: a level that the rest state (a cloth that never
/// moves) already meets measures nothing, so it is never counted as reached, whatever the run's error.
enum class AccuracyVerdict {
  reached,       ///< error <= level < the size of the motion
  missed,        ///< error > level
  met_by_rest    ///< level >= the size of the motion: standing still meets it
};
/// `error` and `motion` must be the same measure (both at T, or both over the frames).
[[nodiscard]] AccuracyVerdict accuracy_verdict(double error, double motion, double level);
/// "reached", "missed", "met by standing still".
[[nodiscard]] const char* accuracy_verdict_name(AccuracyVerdict verdict);
/// What a table or sentence prints for a level the rest state meets, with the size of the motion:
/// "met by standing still (the rest state is 0.00669 m from the reference)".
[[nodiscard]] std::string met_by_standing_still(double motion);

/// A run as the choice of the fastest to a level sees it: its error (the same measure as the motion's; NaN or
/// infinity for a run that failed) and its cost.
struct RunCost {
  double error = 0;
  double seconds = 0;
};
/// The index in `runs` of the fastest run whose verdict at `level` is reached, or -1 when none is: in particular
/// at every level the rest state meets, where no run, however accurate, is a win.
[[nodiscard]] int fastest_reaching(const std::vector<RunCost>& runs, double motion, double level);

}  // namespace cloth
