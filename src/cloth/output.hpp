// Writers for the output files of MODEL.md: final.dat, energy.dat, frames.dat and run.txt.
#pragma once

#include "cloth/force_field.hpp"

#include <string>
#include <utility>
#include <vector>

namespace cloth {

/// One line of energy.dat.
struct EnergySample {
  double t;
  Energy energy;
};

/// The cloth at one instant: every particle's position in grid order (3 per particle).
struct Frame {
  double t;
  Vector positions;
};

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
