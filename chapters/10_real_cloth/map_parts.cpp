// Chapter 10's map read back from its part files (see map_parts.hpp): each run of a part, and the fastest run of a
// column that reached a level.
#include "map_parts.hpp"

#include "study.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>

namespace ch10 {

namespace {

MeasuredPart read_part(const std::string& path) {
  std::ifstream in(path);
  MeasuredPart p;
  std::string line, key, value;
  std::getline(in, line);
  std::istringstream header(line.substr(2));
  std::map<std::string, std::string> values;
  while (header >> key && header >> value) values[key] = value;
  p.part = parse_map_part(values["part"]);
  p.motion = std::stod(values["motion_over_frames"]);
  p.T = std::stod(values["T"]);
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    MapRow r;
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

}  // namespace

std::vector<MeasuredPart> read_parts(const std::string& dir) {
  std::vector<MeasuredPart> parts;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("map_", 0) == 0 && entry.path().extension() == ".dat") parts.push_back(read_part(entry.path()));
  }
  std::sort(parts.begin(), parts.end(), [](const MeasuredPart& a, const MeasuredPart& b) {
    return std::tie(a.part.scene, a.part.n, a.part.K) < std::tie(b.part.scene, b.part.n, b.part.K);
  });
  return parts;
}

double level_value(int level, double motion) { return level == 0 ? 0.05 * motion : level == 1 ? 1e-2 : 1e-3; }

std::string level_name(int level, double motion) {
  return level == 0 ? format("plausible: %.3g cm", 100 * level_value(0, motion)) : level == 1 ? "1 cm" : "1 mm";
}

bool explicit_program(const std::string& program) {
  return program == "symplectic_euler" || program == "rk4" || program == "dopri5" || program == "odeint_rk4" ||
         program == "odeint_dopri5";
}

bool in_column(const MapRow& r, const std::string& column) {
  return column == "implicit" ? !explicit_program(r.program) : r.side == column;
}

std::string who(const MapRow& r) {
  // A rung whose setting is the method's whole name (xpbd/10it/16sub, h = 1/60) is named by it alone.
  const std::string name = r.setting.rfind(r.program, 0) == 0 ? r.setting : r.program + ", " + r.setting;
  return r.side == "peer" ? name + " (" + r.forces + " forces)" : name;
}

bool same_ladder(const MapRow& a, const MapRow& b) {
  return a.side == b.side && a.program == b.program && a.forces == b.forces;
}

const MapRow* fastest(const MeasuredPart& p, const std::string& column, double level) {
  const MapRow* best = nullptr;
  for (const MapRow& r : p.rows)
    if (in_column(r, column) && r.status == "ok" && r.error <= level && (best == nullptr || r.seconds < best->seconds))
      best = &r;
  return best;
}

}  // namespace ch10
