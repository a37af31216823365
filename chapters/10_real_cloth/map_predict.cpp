// The cost model of Chapter 10's map (see map_parts.hpp): a part not measured predicted from the measured grids
// below it, program by program and level by level, and the check of that rule on the parts that were measured.
#include "map_parts.hpp"

#include "study.hpp"

#include "analysis/trajectory_measures.hpp"

#include <algorithm>

using namespace cloth;

namespace ch10 {

namespace {

/// The fastest finished rung of `ladder`'s program in `p` that reached the level, or null.
const MapRow* fastest_rung(const MeasuredPart& p, const MapRow& ladder, int level) {
  const MapRow* best = nullptr;
  for (const MapRow& r : p.rows)
    if (same_ladder(r, ladder) && r.status == "ok" && r.error <= level_value(level, p.motion) &&
        (best == nullptr || r.seconds < best->seconds))
      best = &r;
  return best;
}

/// A column's cell on a grid not measured: the fastest program predicted, and whether a program reached the
/// level on the coarser grid only.
struct ColumnPrediction {
  const MapRow* ladder = nullptr;
  GridPrediction cell;
  bool reached_on_coarser_only = false;
};

ColumnPrediction predict_column(const MeasuredPart* coarser, const MeasuredPart& finer, const std::string& column,
                                int level, int n) {
  ColumnPrediction best;
  for (const MeasuredPart* p : {coarser, &finer}) {
    if (p == nullptr) continue;
    for (const MapRow& ladder : p->rows) {
      if (!in_column(ladder, column)) continue;
      const GridPrediction g = predict_ladder(coarser, finer, ladder, level, n);
      best.reached_on_coarser_only |= g.status == GridPrediction::Status::not_reached_on_finer;
      if (g.status == GridPrediction::Status::predicted && (best.ladder == nullptr || g.seconds < best.cell.seconds))
        best = {&ladder, g, best.reached_on_coarser_only};
    }
  }
  return best;
}

/// A program as the predicted cells name it: a peer with its forces.
std::string program_text(const MapRow& r) {
  return r.side == "peer" ? r.program + " (" + r.forces + " forces)" : r.program;
}

std::string prediction_text(const ColumnPrediction& c, int finer_n, double seconds) {
  if (c.ladder == nullptr)
    return c.reached_on_coarser_only ? format("not predicted: not reached on %d x %d", finer_n, finer_n)
                                     : "not reached";
  return format("*predicted* %s: %.2g s (n^%.2g)", program_text(*c.ladder).c_str(), seconds, c.cell.exponent);
}

const char* column_title(const std::string& column) {
  return column == "book" ? "the book" : column == "peer" ? "peer" : "implicit or position-based";
}

}  // namespace

// [map_predict]
GridPrediction predict_ladder(const MeasuredPart* coarser, const MeasuredPart& finer, const MapRow& ladder,
                              int level, int n) {
  const MapRow* on_finer = fastest_rung(finer, ladder, level);
  const MapRow* on_coarser = coarser == nullptr ? nullptr : fastest_rung(*coarser, ladder, level);
  GridPrediction g;
  if (on_finer == nullptr) {  // not reached where it was last measured: no growth to extrapolate
    g.status = on_coarser != nullptr ? GridPrediction::Status::not_reached_on_finer
                                     : GridPrediction::Status::not_reached;
    return g;
  }
  // Time per simulated second (the horizons differ between grids) grows like n^p per the two grids; one grid
  // measured, or the level reached on the finer only, leaves the a-priori p = 3. No p below the floor: a step
  // touches all n^2 particles and a finer grid needs no longer step, and an explicit step shrinks like 1/n.
  const double rate = on_finer->seconds / finer.T, floor = explicit_program(ladder.program) ? 3 : 2;
  g.exponent = 3;
  if (on_coarser != nullptr)
    g.exponent = std::max(floor, std::log(rate / (on_coarser->seconds / coarser->T)) /
                                     std::log(static_cast<double>(finer.part.n) / coarser->part.n));
  g.seconds = on_finer->seconds * std::pow(static_cast<double>(n) / finer.part.n, g.exponent);
  g.status = GridPrediction::Status::predicted;
  return g;
}
// [map_predict]

std::pair<const MeasuredPart*, const MeasuredPart*> grids_below(const std::vector<MeasuredPart>& parts,
                                                                const MapPart& missing) {
  const MeasuredPart *coarser = nullptr, *finer = nullptr;
  for (const MeasuredPart& p : parts) {  // ordered by grid within a scene and stiffness
    if (p.part.scene != missing.scene || p.part.K != missing.K || p.part.n >= missing.n) continue;
    coarser = finer;
    finer = &p;
  }
  return {coarser, finer};
}

std::vector<std::vector<std::string>> predicted_rows(const MeasuredPart* coarser, const MeasuredPart& finer,
                                                     const MapPart& missing) {
  std::vector<std::vector<std::string>> rows;
  const std::string grid = format("%d x %d", missing.n, missing.n), K = stiffness_text(missing.K);
  const std::string motion = format("not measured (%.3g m to %.2g s at %d x %d)", finer.motion, finer.T,
                                    finer.part.n, finer.part.n);
  for (int level = 0; level < 3; ++level) {
    std::vector<std::string> row = {grid, K, motion, level_name(level, finer.motion)};
    if (accuracy_verdict(0, finer.motion, level_value(level, finer.motion)) == AccuracyVerdict::met_by_rest) {
      rows.push_back({grid, K, motion, row[3], "met by standing still", "", ""});
      continue;
    }
    for (const std::string& column : map_columns) {
      const ColumnPrediction c = predict_column(coarser, finer, column, level, missing.n);
      row.push_back(prediction_text(c, finer.part.n, c.cell.seconds));
    }
    rows.push_back(row);
  }
  return rows;
}

MarkdownTable validation_table(const std::vector<MeasuredPart>& parts) {
  MarkdownTable t({"scene", "grid", "K [N/m]", "accuracy over the frames", "column", "predicted from the grids below",
                   "measured", "measured / predicted"},
                  "lrrllllr");
  for (const MeasuredPart& p : parts) {
    const auto [coarser, finer] = grids_below(parts, p.part);
    if (finer == nullptr) continue;
    for (int level = 0; level < 3; ++level) {
      const double value = level_value(level, p.motion);
      if (accuracy_verdict(0, p.motion, value) == AccuracyVerdict::met_by_rest) continue;
      for (const std::string& column : map_columns) {
        const MapRow* measured = fastest(p, column, value);
        const ColumnPrediction c = predict_column(coarser, *finer, column, level, p.part.n);
        if (measured == nullptr || c.ladder == nullptr) continue;
        const double predicted = c.cell.seconds * p.T / finer->T;  // to this part's own horizon
        t.add_row({p.part.scene, format("%d x %d", p.part.n, p.part.n), stiffness_text(p.part.K),
                   level_name(level, p.motion), column_title(column),
                   prediction_text(c, finer->part.n, predicted).substr(12),  // without "*predicted* "
                   format("%s: %.3g s", program_text(*measured).c_str(), measured->seconds),
                   format("%#.3g", measured->seconds / predicted)});  // three figures: 0.0072 is not 0.01
      }
    }
  }
  return t;
}

}  // namespace ch10
