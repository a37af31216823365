// Writers for the output files of MODEL.md: final.dat, energy.dat, frames.dat and run.txt.
#pragma once

#include "integrators/simulate.hpp"
#include "model/force_field.hpp"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace cloth {

/// A file that could not be written in full: it could not be opened, or the system refused a write (a full disk,
/// an I/O error). The message names the file and the system's reason. Chapter programs turn it into one line on
/// stderr and exit status 2, as for an --out folder that cannot be written (cloth::run_program).
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Each writer throws OutputError when its file is not written in full.

/// final.dat: `i j x y z vx vy vz` per particle, pinned ones included, 17 significant digits.
void write_final(const std::string& path, const Scene& scene, const ConstVectorRef& x, const ConstVectorRef& v);

/// energy.dat: `t kinetic gravity spring total`.
void write_energy(const std::string& path, const std::vector<EnergySample>& samples);

/// frames.dat: one gnuplot `index` block per frame; grid rows (fixed i) separated by one blank line, frames by two.
/// Columns `i j x y z`, preceded by a comment line with the frame's time.
void write_frames(const std::string& path, const Grid& grid, const std::vector<Frame>& frames);

/// run.txt: `key = value` lines, in the given order.
void write_key_values(const std::string& path, const std::vector<std::pair<std::string, std::string>>& entries);

}  // namespace cloth
