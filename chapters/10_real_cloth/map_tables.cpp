// Chapter 10's map as tables (see map_sweep.hpp): from every measured part, for each accuracy level, the fastest
// run of the book's methods, of the peers, and of the implicit and position-based methods that reached it over
// every frame, each level beside the size of the motion; a level the rest state meets is said so, a cell no run
// reached within the budget is predicted from its ladder and marked, and so is every cell of a part not measured
// (map_predict.cpp).
#include "map_parts.hpp"

#include "study.hpp"

#include "analysis/trajectory_measures.hpp"

#include <algorithm>
#include <cmath>

using namespace cloth;

namespace ch10 {

namespace {

// [map_cell]
/// The cell: the fastest run that reached `level`; else the cost model's prediction from each ladder's last two
/// rungs, error ~ seconds^-q, marked as predicted, when it lies within a hundred times the last rung's time.
std::string best(const MeasuredPart& p, const std::string& side, double level) {
  if (const MapRow* r = fastest(p, side, level)) return format("%s: %.3g s", who(*r).c_str(), r->seconds);
  double predicted = INFINITY;
  std::string by;
  for (std::size_t k = 1; k < p.rows.size(); ++k) {
    const MapRow &a = p.rows[k - 1], &b = p.rows[k];
    const bool last = k + 1 == p.rows.size() || p.rows[k + 1].program != b.program || p.rows[k + 1].forces != b.forces;
    if (!last || !in_column(b, side) || a.program != b.program || a.forces != b.forces || a.status != "ok" ||
        b.status != "ok")
      continue;  // only a ladder's last two rungs, both finished: an earlier pair can hide a stall that followed
    const double q = std::log(a.error / b.error) / std::log(b.seconds / a.seconds);
    if (!(q > 0.2) || !(b.seconds > a.seconds)) continue;  // no convergence to extrapolate
    const double t = b.seconds * std::pow(b.error / level, 1 / q);
    if (t > 100 * b.seconds) continue;  // two rungs say nothing of a time a hundred times beyond the last
    if (t < predicted) predicted = t, by = b.program + (b.side == "peer" ? " (" + b.forces + " forces)" : "");
  }
  if (std::isfinite(predicted)) return format("*predicted* %s: %.2g s", by.c_str(), predicted);
  return "none";
}
// [map_cell]

/// The rows of a measured part, one per level.
std::vector<std::vector<std::string>> measured_rows(const MeasuredPart& p) {
  std::vector<std::vector<std::string>> rows;
  const std::string grid = format("%d x %d", p.part.n, p.part.n), K = stiffness_text(p.part.K);
  const std::string motion = format("%.3g m to %.2g s", p.motion, p.T);
  for (int level = 0; level < 3; ++level) {
    const double value = level_value(level, p.motion);
    const std::string name = level_name(level, p.motion);
    if (accuracy_verdict(0, p.motion, value) == AccuracyVerdict::met_by_rest)
      rows.push_back({grid, K, motion, name, "met by standing still", "", ""});
    else
      rows.push_back({grid, K, motion, name, best(p, "book", value), best(p, "peer", value), best(p, "implicit", value)});
  }
  return rows;
}

}  // namespace

std::vector<std::string> write_map_tables(const std::string& dir, const std::string& command, bool predict_missing) {
  const std::vector<MeasuredPart> parts = read_parts(dir);
  std::vector<std::string> written;
  for (const char* scene : {"curtain", "swing"}) {
    std::vector<std::pair<std::pair<int, double>, std::vector<std::string>>> rows;  // by (n, K), then level
    const auto add = [&](const MapPart& part, std::vector<std::vector<std::string>> cells) {
      for (auto& row : cells) rows.push_back({{part.n, part.K}, std::move(row)});
    };
    for (const MeasuredPart& p : parts)
      if (p.part.scene == scene) add(p.part, measured_rows(p));
    for (const MapPart& missing : full_map()) {
      const bool present = std::any_of(parts.begin(), parts.end(),
                                       [&](const MeasuredPart& p) { return p.part.name() == missing.name(); });
      if (!predict_missing || missing.scene != scene || present) continue;
      const auto [coarser, finer] = grids_below(parts, missing);
      if (finer != nullptr) {
        add(missing, predicted_rows(coarser, *finer, missing));
        continue;
      }
      add(missing, {{format("%d x %d", missing.n, missing.n), stiffness_text(missing.K), "not measured", "-",
                     "not measured", "not measured", "not measured"}});
    }
    std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    MarkdownTable t({"grid", "K [N/m]", "motion over the frames to T", "accuracy over the frames", "fastest of the book",
                     "fastest peer", "fastest implicit or position-based"},
                    "lrrllll");
    for (auto& row : rows) t.add_row(std::move(row.second));
    const std::string file = std::string("map_") + scene + ".md";
    write_table_fragment(dir + "/" + file, t, command);
    written.push_back(file);
  }
  write_table_fragment(dir + "/map_validation.md", validation_table(parts), command);
  written.emplace_back("map_validation.md");
  return written;
}

}  // namespace ch10
