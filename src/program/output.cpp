// Plain-text output files, written with enough digits to reproduce every double (%.17g).
#include "program/output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

namespace cloth {

OutputFile::OutputFile(std::string path)
    : path_(std::move(path)), temporary_(path_ + ".partial"), file_(std::fopen(temporary_.c_str(), "w")) {
  if (file_ == nullptr) fail(errno);
}

OutputFile::~OutputFile() {
  if (file_ != nullptr) {  // reached only when an exception or an interruption left a writer early
    std::fclose(file_);
    std::remove(temporary_.c_str());
  }
}

void OutputFile::commit() {
  errno = 0;
  const bool flushed = std::fflush(file_) == 0 && std::ferror(file_) == 0;
  const int flush_error = errno;
  const bool closed = std::fclose(file_) == 0;
  const int close_error = errno;
  file_ = nullptr;
  if (!flushed || !closed) {
    std::remove(temporary_.c_str());
    fail(!flushed ? flush_error : close_error);
  }
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    std::remove(temporary_.c_str());
    fail(error);
  }
}

void OutputFile::fail(int error) const {
  throw OutputError("cannot write '" + path_ + "'" + (error != 0 ? std::string(": ") + std::strerror(error) : ""));
}

void write_final(const std::string& path, const Scene& scene, const ConstVectorRef& x, const ConstVectorRef& v) {
  OutputFile f(path);
  const Grid& g = scene.grid();
  std::fprintf(f.get(), "# i j x y z vx vy vz\n");
  for (int i = 0; i < g.M; ++i)
    for (int j = 0; j < g.N; ++j) {
      const int s = scene.slot(g.particle(i, j));
      Eigen::Vector3d p = scene.rest_positions().segment<3>(3 * s), u = Eigen::Vector3d::Zero();
      if (s < scene.free_count()) p = x.segment<3>(3 * s), u = v.segment<3>(3 * s);
      std::fprintf(f.get(), "%d %d %.17g %.17g %.17g %.17g %.17g %.17g\n", i, j, p[0], p[1], p[2], u[0], u[1], u[2]);
    }
  f.commit();
}

void write_energy(const std::string& path, const std::vector<EnergySample>& samples) {
  OutputFile f(path);
  std::fprintf(f.get(), "# t kinetic gravity spring total\n");
  for (const EnergySample& s : samples)
    std::fprintf(f.get(), "%.10g %.17g %.17g %.17g %.17g\n", s.t, s.energy.kinetic, s.energy.gravity, s.energy.spring,
                 s.energy.total());
  f.commit();
}

void write_frames(const std::string& path, const Grid& grid, const std::vector<Frame>& frames) {
  OutputFile f(path);
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
  f.commit();
}

void write_key_values(const std::string& path, const std::vector<std::pair<std::string, std::string>>& entries) {
  OutputFile f(path);
  for (const auto& [key, value] : entries) std::fprintf(f.get(), "%s = %s\n", key.c_str(), value.c_str());
  f.commit();
}

}  // namespace cloth
