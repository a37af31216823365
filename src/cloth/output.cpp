// Plain-text output files, written with enough digits to reproduce every double (%.17g).
#include "cloth/output.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>

namespace cloth {

namespace {

using File = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

File open(const std::string& path) {
  File f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) throw std::runtime_error("cannot write '" + path + "'");
  return f;
}

}  // namespace

void write_final(const std::string& path, const Scene& scene, const ConstVectorRef& x, const ConstVectorRef& v) {
  File f = open(path);
  const Grid& g = scene.grid();
  std::fprintf(f.get(), "# i j x y z vx vy vz\n");
  for (int i = 0; i < g.M; ++i)
    for (int j = 0; j < g.N; ++j) {
      const int s = scene.slot(g.particle(i, j));
      Eigen::Vector3d p = scene.rest_positions().segment<3>(3 * s), u = Eigen::Vector3d::Zero();
      if (s < scene.free_count()) p = x.segment<3>(3 * s), u = v.segment<3>(3 * s);
      std::fprintf(f.get(), "%d %d %.17g %.17g %.17g %.17g %.17g %.17g\n", i, j, p[0], p[1], p[2], u[0], u[1], u[2]);
    }
}

void write_energy(const std::string& path, const std::vector<EnergySample>& samples) {
  File f = open(path);
  std::fprintf(f.get(), "# t kinetic gravity spring total\n");
  for (const EnergySample& s : samples)
    std::fprintf(f.get(), "%.10g %.17g %.17g %.17g %.17g\n", s.t, s.energy.kinetic, s.energy.gravity, s.energy.spring,
                 s.energy.total());
}

void write_frames(const std::string& path, const Grid& grid, const std::vector<Frame>& frames) {
  File f = open(path);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (k > 0) std::fprintf(f.get(), "\n\n");
    std::fprintf(f.get(), "# frame %zu t = %.10g\n# i j x y z\n", k, frames[k].t);
    for (int i = 0; i < grid.M; ++i) {
      if (i > 0) std::fprintf(f.get(), "\n");
      for (int j = 0; j < grid.N; ++j) {
        const auto p = frames[k].positions.segment<3>(3 * grid.particle(i, j));
        std::fprintf(f.get(), "%d %d %.10g %.10g %.10g\n", i, j, p[0], p[1], p[2]);
      }
    }
  }
}

void write_key_values(const std::string& path, const std::vector<std::pair<std::string, std::string>>& entries) {
  File f = open(path);
  for (const auto& [key, value] : entries) std::fprintf(f.get(), "%s = %s\n", key.c_str(), value.c_str());
}

}  // namespace cloth
