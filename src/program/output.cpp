// Plain-text output files, written with enough digits to reproduce every double (%.17g).
#include "program/output.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <utility>

namespace cloth {

namespace {

// One output file. stdio buffers what fprintf writes, so a write the system refuses (a full disk) usually fails
// only at a later flush or at fclose, and sets the stream's error flag rather than failing the fprintf that
// caused it: whether the file is whole is known at close(), which every writer calls last.
class OutputFile {
 public:
  explicit OutputFile(std::string path) : path_(std::move(path)), file_(std::fopen(path_.c_str(), "w")) {
    if (file_ == nullptr) fail(errno);
  }
  ~OutputFile() {
    if (file_ != nullptr) std::fclose(file_);  // reached only when an exception left a writer early
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  [[nodiscard]] std::FILE* get() const { return file_; }

  /// Flushes and closes the file; throws OutputError if any write to it failed.
  void close() {
    errno = 0;
    const bool flushed = std::fflush(file_) == 0 && std::ferror(file_) == 0;
    const int flush_error = errno;
    const bool closed = std::fclose(file_) == 0;
    file_ = nullptr;
    if (!flushed) fail(flush_error);
    if (!closed) fail(errno);
  }

 private:
  [[noreturn]] void fail(int error) const {
    throw OutputError("cannot write '" + path_ + "'" + (error != 0 ? std::string(": ") + std::strerror(error) : ""));
  }

  std::string path_;
  std::FILE* file_;
};

}  // namespace

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
  f.close();
}

void write_energy(const std::string& path, const std::vector<EnergySample>& samples) {
  OutputFile f(path);
  std::fprintf(f.get(), "# t kinetic gravity spring total\n");
  for (const EnergySample& s : samples)
    std::fprintf(f.get(), "%.10g %.17g %.17g %.17g %.17g\n", s.t, s.energy.kinetic, s.energy.gravity, s.energy.spring,
                 s.energy.total());
  f.close();
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
  f.close();
}

void write_key_values(const std::string& path, const std::vector<std::pair<std::string, std::string>>& entries) {
  OutputFile f(path);
  for (const auto& [key, value] : entries) std::fprintf(f.get(), "%s = %s\n", key.c_str(), value.c_str());
  f.close();
}

}  // namespace cloth
