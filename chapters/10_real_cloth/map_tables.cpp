// Chapter 10's map as tables (see map_sweep.hpp): from every measured part, for each accuracy level, the fastest
// run of the book's methods, of the peers, and of the implicit and position-based methods that reached it over
// every frame, each level beside the size of the motion; a level the rest state meets is said so, and a cell no
// run reached within the budget is predicted by the cost model and marked.
#include "map_sweep.hpp"

#include "study.hpp"

#include "analysis/trajectory_measures.hpp"
#include "program/fragment.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

using namespace cloth;

namespace ch10 {

namespace {

struct Row {
  std::string side, program, forces, setting, status;
  long long steps = 0;
  double seconds = 0, error_at_T = NAN, error = NAN;
};

struct Part {
  MapPart part;
  double motion = 0;  ///< over the frames [m]
  double T = 0;       ///< the horizon [s]
  std::vector<Row> rows;
};

Part read_part(const std::string& path) {
  std::ifstream in(path);
  Part p;
  std::string line, key, scene;
  std::getline(in, line);
  std::istringstream header(line.substr(2));
  std::map<std::string, std::string> values;
  while (header >> key && header >> scene) values[key] = scene;
  p.part = parse_map_part(values["part"]);
  p.motion = std::stod(values["motion_over_frames"]);
  p.T = std::stod(values["T"]);
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    Row r;
    std::string error_at_T, error;  // read as text: a failed run's "nan" is not a number to operator>>
    s >> r.side >> r.program >> r.forces >> std::quoted(r.setting) >> r.steps >> r.seconds >> error_at_T >> error >>
        r.status;
    if (!s) throw std::runtime_error(path + ": a row that is not a run: " + line);
    r.error_at_T = std::stod(error_at_T);
    r.error = std::stod(error);
    if (r.side == "book") {  // the one name of each method (integrators/configuration.hpp), however it was written
      r.program = label(r.program);
      const std::size_t comma = r.setting.find(',');
      if (comma != std::string::npos && r.setting.find('/') < comma)
        r.setting = label(r.setting.substr(0, comma)) + r.setting.substr(comma);
    }
    p.rows.push_back(r);
  }
  return p;
}

bool explicit_program(const std::string& program) {
  return program == "symplectic_euler" || program == "rk4" || program == "dopri5" || program == "odeint_rk4" ||
         program == "odeint_dopri5";
}

std::string who(const Row& r) {
  // A rung whose setting is the method's whole name (xpbd/10it/16sub, h = 1/60) is named by it alone.
  const std::string name = r.setting.rfind(r.program, 0) == 0 ? r.setting : r.program + ", " + r.setting;
  return r.side == "peer" ? name + " (" + r.forces + " forces)" : name;
}

bool in_column(const Row& r, const std::string& side) {
  return side == "implicit" ? !explicit_program(r.program) : r.side == side;
}

/// The fastest row of `side` (or of the implicit and position-based methods when `side` is "implicit") that
/// reached `level`, or null.
const Row* fastest(const Part& p, const std::string& side, double level) {
  const Row* best = nullptr;
  for (const Row& r : p.rows)
    if (in_column(r, side) && r.status == "ok" && r.error <= level && (best == nullptr || r.seconds < best->seconds))
      best = &r;
  return best;
}

// [map_cell]
/// The cell: the fastest run that reached `level`; else the cost model's prediction from each ladder's last two
/// rungs, error ~ seconds^-q, marked as predicted, when it lies within a hundred times the last rung's time.
std::string best(const Part& p, const std::string& side, double level) {
  if (const Row* r = fastest(p, side, level)) return format("%s: %.3g s", who(*r).c_str(), r->seconds);
  double predicted = INFINITY;
  std::string by;
  for (std::size_t k = 1; k < p.rows.size(); ++k) {
    const Row &a = p.rows[k - 1], &b = p.rows[k];
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

/// A part not measured (its reference alone is predicted over the budget): an explicit winner of the nearest
/// smaller measured grid, scaled by the explicit cost model, time ~ particles x steps ~ n^3 (the stable step
/// shrinks like the spacing), keeping the setting's steps per spacing.
std::string scaled(const Part& measured, int n, const std::string& side, double level) {
  const Row* r = fastest(measured, side, level);
  if (r == nullptr || !explicit_program(r->program)) return "not predicted";
  return format("*predicted* %s: %.2g s", r->program.c_str(),
                r->seconds * std::pow(static_cast<double>(n) / measured.part.n, 3));
}

}  // namespace

std::vector<std::string> write_map_tables(const std::string& dir, const std::string& command, bool predict_missing) {
  std::vector<Part> parts;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("map_", 0) == 0 && entry.path().extension() == ".dat") parts.push_back(read_part(entry.path()));
  }
  std::sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) {
    return std::tie(a.part.scene, a.part.n, a.part.K) < std::tie(b.part.scene, b.part.n, b.part.K);
  });
  std::vector<std::string> written;
  for (const char* scene : {"curtain", "swing"}) {
    std::vector<std::pair<std::pair<int, double>, std::vector<std::string>>> rows;  // by (n, K), then level
    const auto add = [&](const MapPart& part, std::vector<std::string> cells) {
      rows.push_back({{part.n, part.K}, std::move(cells)});
    };
    MarkdownTable t({"grid", "K [N/m]", "motion over the frames to T", "accuracy over the frames", "fastest of the book",
                     "fastest peer", "fastest implicit or position-based"},
                    "lrrllll");
    for (const Part& p : parts) {
      if (p.part.scene != scene) continue;
      const std::string grid = format("%d x %d", p.part.n, p.part.n), K = stiffness_text(p.part.K);
      const std::string motion = format("%.3g m to %.2g s", p.motion, p.T);
      for (const auto& [name, level] : std::vector<std::pair<std::string, double>>{
               {format("plausible: %.3g cm", 5 * p.motion), 0.05 * p.motion}, {"1 cm", 1e-2}, {"1 mm", 1e-3}}) {
        if (accuracy_verdict(0, p.motion, level) == AccuracyVerdict::met_by_rest) {
          add(p.part, {grid, K, motion, name, "met by standing still", "", ""});
          continue;
        }
        add(p.part, {grid, K, motion, name, best(p, "book", level), best(p, "peer", level), best(p, "implicit", level)});
      }
    }
    for (const MapPart& missing : full_map()) {
      if (!predict_missing || missing.scene != scene) continue;
      const Part* nearest = nullptr;
      bool present = false;
      for (const Part& p : parts) {
        present = present || p.part.name() == missing.name();
        if (p.part.scene == scene && p.part.K == missing.K && p.part.n < missing.n &&
            (nearest == nullptr || p.part.n > nearest->part.n))
          nearest = &p;
      }
      if (present) continue;
      if (nearest == nullptr) {
        add(missing, {format("%d x %d", missing.n, missing.n), stiffness_text(missing.K), "not measured", "-",
                      "not measured", "not measured", "not measured"});
        continue;
      }
      const std::string grid = format("%d x %d", missing.n, missing.n);
      const std::string motion = format("not measured (%.3g m at %d x %d)", nearest->motion, nearest->part.n,
                                        nearest->part.n);
      for (const auto& [name, level] : std::vector<std::pair<std::string, double>>{
               {"plausible", 0.05 * nearest->motion}, {"1 cm", 1e-2}, {"1 mm", 1e-3}})
        add(missing, {grid, stiffness_text(missing.K), motion, name, scaled(*nearest, missing.n, "book", level),
                      scaled(*nearest, missing.n, "peer", level), "not predicted"});
    }
    std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& row : rows) t.add_row(std::move(row.second));
    const std::string file = std::string("map_") + scene + ".md";
    write_table_fragment(dir + "/" + file, t, command);
    written.push_back(file);
  }
  return written;
}

}  // namespace ch10
