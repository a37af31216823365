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
#include <map>
#include <sstream>

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
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    Row r;
    s >> r.side >> r.program >> r.forces >> std::quoted(r.setting) >> r.steps >> r.seconds >> r.error_at_T >> r.error >>
        r.status;
    if (s) p.rows.push_back(r);
  }
  return p;
}

bool explicit_program(const std::string& program) {
  return program == "symplectic_euler" || program == "rk4" || program == "odeint_rk4" || program == "odeint_dopri5";
}

std::string who(const Row& r) {
  return r.program + (r.side == "peer" ? " (" + r.forces + " forces)" : "") + ", " + r.setting;
}

// [map_cell]
/// The fastest row of `side` (or of the implicit and position-based methods when `side` is "implicit") that
/// reached `level`; else the cost model's prediction from each ladder's last two rungs, error ~ seconds^-q.
std::string best(const Part& p, const std::string& side, double level) {
  const Row* fastest = nullptr;
  for (const Row& r : p.rows) {
    const bool mine = side == "implicit" ? !explicit_program(r.program) : r.side == side;
    if (mine && r.status == "ok" && r.error <= level && (fastest == nullptr || r.seconds < fastest->seconds)) fastest = &r;
  }
  if (fastest != nullptr) return format("%s: %.3g s", who(*fastest).c_str(), fastest->seconds);
  double predicted = INFINITY;
  std::string by;
  for (std::size_t k = 1; k < p.rows.size(); ++k) {
    const Row &a = p.rows[k - 1], &b = p.rows[k];
    const bool mine = side == "implicit" ? !explicit_program(b.program) : b.side == side;
    if (!mine || a.program != b.program || a.forces != b.forces || a.status != "ok" || b.status != "ok") continue;
    const double q = std::log(a.error / b.error) / std::log(b.seconds / a.seconds);
    if (!(q > 0.2) || !(b.seconds > a.seconds)) continue;  // no convergence to extrapolate
    const double t = b.seconds * std::pow(b.error / level, 1 / q);
    if (t < predicted) predicted = t, by = b.program + (b.side == "peer" ? " (" + b.forces + " forces)" : "");
  }
  if (std::isfinite(predicted)) return format("*predicted* %s: %.2g s", by.c_str(), predicted);
  return "none";
}
// [map_cell]

}  // namespace

std::vector<std::string> write_map_tables(const std::string& dir, const std::string& command) {
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
    MarkdownTable t({"grid", "K [N/m]", "motion over the frames", "accuracy over the frames", "fastest of the book",
                     "fastest peer", "fastest implicit or position-based"},
                    "lrrllll");
    for (const Part& p : parts) {
      if (p.part.scene != scene) continue;
      const std::string grid = format("%d x %d", p.part.n, p.part.n), K = format("%g", p.part.K);
      const std::string motion = format("%.3g m", p.motion);
      for (const auto& [name, level] : std::vector<std::pair<std::string, double>>{
               {format("plausible: %.3g cm", 5 * p.motion), 0.05 * p.motion}, {"1 cm", 1e-2}, {"1 mm", 1e-3}}) {
        if (accuracy_verdict(0, p.motion, level) == AccuracyVerdict::met_by_rest) {
          t.add_row({grid, K, motion, name, "met by standing still", "", ""});
          continue;
        }
        t.add_row({grid, K, motion, name, best(p, "book", level), best(p, "peer", level), best(p, "implicit", level)});
      }
    }
    const std::string file = std::string("map_") + scene + ".md";
    write_table_fragment(dir + "/" + file, t, command);
    written.push_back(file);
  }
  return written;
}

}  // namespace ch10
