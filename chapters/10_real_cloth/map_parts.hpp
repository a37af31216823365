// Chapter 10's map as its tables read it back (see map_sweep.hpp): the runs of each measured part, the fastest run
// of a column that reached a level, and the cost model that predicts the cells of a part not measured from the
// measured grids below it (map_predict.cpp).
#pragma once

#include "map_sweep.hpp"

#include "program/fragment.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace ch10 {

/// One run of a part's file: a rung of a program's ladder.
struct MapRow {
  std::string side, program, forces, setting, status;
  long long steps = 0;
  double seconds = 0, error_at_T = NAN, error = NAN;
};

/// A measured part: its runs, the size of its motion and its horizon.
struct MeasuredPart {
  MapPart part;
  double motion = 0;  ///< the rest state's largest distance from the reference over the frames [m]
  double T = 0;       ///< the horizon [s]
  std::vector<MapRow> rows;
};

/// Every `map_PART.dat` in `dir`, ordered by scene, grid and stiffness.
std::vector<MeasuredPart> read_parts(const std::string& dir);

/// The levels of the tables, 0 to 2: plausible (5 % of the motion), 1 cm and 1 mm [m].
double level_value(int level, double motion);
/// "plausible: 8.6 cm", "1 cm", "1 mm".
std::string level_name(int level, double motion);

/// The three columns of a table: the book's methods, the peers, the implicit and position-based methods.
inline const std::vector<std::string> map_columns = {"book", "peer", "implicit"};

bool explicit_program(const std::string& program);
/// Whether `r` belongs to `column`.
bool in_column(const MapRow& r, const std::string& column);
/// The run as a cell names it: program and setting, and a peer's forces.
std::string who(const MapRow& r);
/// Whether two rows are rungs of the same ladder (side, program and forces).
bool same_ladder(const MapRow& a, const MapRow& b);
/// The fastest finished run of `column` that reached `level` over the frames, or null.
const MapRow* fastest(const MeasuredPart& p, const std::string& column, double level);

/// One program's cell at a grid not measured, as the cost model predicts it.
struct GridPrediction {
  enum class Status { predicted, not_reached, not_reached_on_finer };
  Status status = Status::not_reached;
  double seconds = NAN;   ///< processor seconds to the finer measured grid's horizon
  double exponent = NAN;  ///< the time per simulated second grows like n^exponent
};

/// The cost model: the cell of `ladder`'s program at `level` on the n x n grid, from its fastest runs to that level
/// on the measured grids `coarser` (null when only one grid is measured) and `finer` of the same scene and
/// stiffness. Two grids give the measured growth, time per simulated second ~ n^p with p fitted to them; one grid
/// the a-priori p = 3. A cell reached on the coarser grid but not on the finer is not predicted.
GridPrediction predict_ladder(const MeasuredPart* coarser, const MeasuredPart& finer, const MapRow& ladder,
                              int level, int n);

/// The table rows of a part not measured, one per level, each column's fastest predicted program and marked
/// "*predicted*", from the two largest measured grids below it (or the one).
std::vector<std::vector<std::string>> predicted_rows(const MeasuredPart* coarser, const MeasuredPart& finer,
                                                     const MapPart& missing);

/// The model's check: every cell of a measured part whose smaller grids are measured, predicted from them as
/// the tables predict a part not measured, against the cell measured; "-" where either is missing.
cloth::MarkdownTable validation_table(const std::vector<MeasuredPart>& parts);

/// The two largest measured grids of `missing`'s scene and stiffness below its grid: {coarser or null, finer or
/// null}.
std::pair<const MeasuredPart*, const MeasuredPart*> grids_below(const std::vector<MeasuredPart>& parts,
                                                                const MapPart& missing);

}  // namespace ch10
