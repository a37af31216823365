// A made-up part file of Chapter 10's map (the format map_sweep.cpp writes), for the tests that read tables from
// parts whose numbers they know.
#pragma once

#include "program_runner.hpp"

#include <fstream>
#include <string>

namespace cloth_test {

/// Writes `rows` (side program forces "setting" steps seconds error_at_T error_over_frames status) under the header
/// of part `part` with horizon T and motion over the frames `motion`.
inline void write_map_part(const fs::path& file, const std::string& part, double T, double motion,
                           const std::string& rows) {
  std::ofstream out(file);
  out << "# part " << part << " T " << T << " motion_over_frames " << motion
      << "\n# side program forces setting steps seconds error_at_T error_over_frames status\n"
      << rows;
}

}  // namespace cloth_test
