// Each program's declared outputs (see output_spec.hpp).
#include "program/output_spec.hpp"

#include <algorithm>
#include <utility>

namespace cloth {

const char* output_kind_name(OutputKind kind) {
  switch (kind) {
    case OutputKind::fragment: return "fragment";
    case OutputKind::figure_input: return "figure_input";
    case OutputKind::data: break;
  }
  return "data";
}

OutputList run_output_specs(const std::string& folder, std::initializer_list<const char*> drawn) {
  OutputList files = {{"final.dat", OutputKind::data, "every particle's position and velocity at the end of the run"},
                      {"energy.dat", OutputKind::data, "kinetic, gravity, spring and total energy at every step"},
                      {"frames.dat", OutputKind::data, "the cloth's positions at the frames asked for"},
                      {"run.txt", OutputKind::data, "the scene, the method, the work counters and how the run ended"}};
  for (OutputSpec& file : files) {
    if (std::find_if(drawn.begin(), drawn.end(), [&](const char* name) { return file.name == name; }) != drawn.end())
      file.kind = OutputKind::figure_input;
    if (!folder.empty()) file.name = folder + "/" + file.name;
  }
  return files;
}

OutputList operator+(OutputList list, const OutputList& more) {
  list.insert(list.end(), more.begin(), more.end());
  return list;
}

std::vector<std::string> output_names(const OutputList& list) {
  std::vector<std::string> names;
  names.reserve(list.size());
  for (const OutputSpec& file : list) names.push_back(file.name);
  return names;
}

std::string output_listing(const OutputList& list) {
  std::string text;
  for (const OutputSpec& file : list) text += file.name + "\t" + output_kind_name(file.kind) + "\t" + file.holds + "\n";
  return text;
}

}  // namespace cloth
