// Chapter 10's map: which program is fastest at each accuracy, for the curtain and the swinging curtain at 20 x 20
// to 160 x 160 particles on the same square metre and tensile stiffness over three decades. A part of the map is
// one scene at one resolution and one stiffness ("curtain_40_1e4"); measuring a part writes map_<part>.dat, and
// the tables are built from whichever parts' files exist, so that the full sweep can run for hours part by part.
#pragma once

#include <string>
#include <vector>

namespace ch10 {

/// A part of the map: a scene, a resolution and a stiffness.
struct MapPart {
  std::string scene;  ///< "curtain" (released flat) or "swing" (thrown down at 4 rad/s)
  int n = 20;         ///< particles per side
  double K = 1e5;     ///< tensile stiffness of every spring [N/m]
  [[nodiscard]] std::string name() const;
};

/// The part named `SCENE_N_1eE` (K = 10^E). Throws cloth::InputError naming what is accepted.
MapPart parse_map_part(const std::string& name);
/// Every part of the full map, cheapest first.
std::vector<MapPart> full_map();

/// How a part is measured: the horizon is the longest over which the reference is verified (the scene's own,
/// 0.6 s for the curtain and 0.8 s for the swing, or less on a finer grid), no single run longer than `run_budget` seconds is started (a ladder of finer settings
/// stops when the next run's predicted time would exceed it), and the reference is Dormand-Prince at
/// `reference_tolerance`.
struct SweepPlan {
  double run_budget = 600;
  double reference_tolerance = 1e-9;
  /// The horizon ends where the reference and a second one at a tenth of its tolerance first differ by more than
  /// this [m]: a hundredth of the finest level, 1 mm.
  double reference_agreement = 1e-5;
  int max_runs_per_series = 12;
  /// A rung predicted slower than this many times the fastest run that already reached 1 mm is not started: it
  /// could win no cell of the book's or the peers' columns, only the implicit column, where it is then predicted.
  double prune_factor = 20;
  /// A SUNDIALS run is stopped after this many times the fastest run that reached 1 mm (at least 10 s, at most
  /// the budget): its time is not predictable from the rung before it, and slower than that it wins no cell.
  double sundials_cap_factor = 20;
};

/// Measures `part` and writes `DIR/map_PART.dat`; `command` is the line that measures it again. Returns the
/// reference's processor seconds (for the cost model of the next parts).
double measure_part(const MapPart& part, const SweepPlan& plan, const std::string& dir, const std::string& command);

/// Reads every `map_PART.dat` in `dir` and writes the map's fragments there (map_curtain.md, map_swing.md, and
/// map_validation.md, the cost model's check); returns their names. With `predict_missing`, each part of the full
/// map without a file gets every column predicted by the cost model from the two largest measured grids below it
/// (map_parts.hpp), marked as predicted.
std::vector<std::string> write_map_tables(const std::string& dir, const std::string& command, bool predict_missing);

}  // namespace ch10
