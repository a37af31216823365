// Checked output files: declared outputs, temporary names renamed when whole, and the model page's writers.
// Numbers are written with std::to_chars, which prints exactly what printf's %.17g (or %.10g) would, without
// printf's format parsing and locale: energy.dat has a line per step and frames.dat a line per particle and frame.
#include "program/output.hpp"

#include "base/input_error.hpp"
#include "base/text.hpp"
#include "program/command_line.hpp"
#include "program/output_spec.hpp"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace cloth {

namespace {

namespace fs = std::filesystem;

std::string quoted(const std::string& path) { return "'" + escaped(path) + "'"; }

// A relative path that stays inside its folder: no empty, "." or ".." part, not absolute.
bool stays_inside(const std::string& name) {
  if (name.empty() || name.front() == '/') return false;
  std::size_t start = 0;
  while (start <= name.size()) {
    const std::size_t slash = std::min(name.find('/', start), name.size());
    const std::string part = name.substr(start, slash - start);
    if (part.empty() || part == "." || part == "..") return false;
    start = slash + 1;
  }
  return true;
}

bool is_directory(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode);
}

bool exists(const std::string& path) {
  struct stat info {};
  return ::lstat(path.c_str(), &info) == 0;
}

void remove_if_regular(const std::string& path) {
  struct stat info {};
  if (::lstat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode)) ::unlink(path.c_str());
}

}  // namespace

void prepare_outputs(const std::string& dir, const std::vector<std::string>& outputs,
                     const std::vector<std::string>& others, const std::string& flag) {
  for (const std::vector<std::string>* list : {&outputs, &others})
    for (const std::string& name : *list)
      if (!stays_inside(name)) throw std::logic_error("output name '" + escaped(name) + "' leaves its folder");
  const auto in_dir = [&dir](const std::string& name) {
    std::string path = dir;
    path.append("/").append(name);
    return path;
  };
  // Everything in the way is found before anything is created.
  if (exists(dir) && !is_directory(dir))
    throw InputError(flag + ": " + quoted(dir) + " exists and is not a folder: expected a writable folder path");
  for (const std::string& name : outputs) {
    for (std::size_t slash = name.find('/'); slash != std::string::npos; slash = name.find('/', slash + 1)) {
      const std::string folder = in_dir(name.substr(0, slash));
      if (exists(folder) && !is_directory(folder))
        throw InputError(flag + ": " + quoted(folder) + " is a file where the run puts a folder of outputs: expected "
                         "an --out without it (remove it or choose another folder)");
    }
    const std::string file_path = in_dir(name);
    for (const std::string& file : {file_path, file_path + ".partial"})
      if (is_directory(file))
        throw InputError(flag + ": " + quoted(file) + " is a folder where the run writes a file: expected an --out "
                         "without it (remove it or choose another folder)");
  }
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !is_directory(dir))
    throw InputError(flag + ": cannot create folder " + quoted(dir) + (ec ? " (" + ec.message() + ")" : "") +
                     ": expected a writable folder path");
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw InputError(flag + ": folder " + quoted(dir) + " is not writable (" + std::strerror(errno) +
                     "): expected a writable folder path");
  for (const std::string& name : outputs)
    if (const auto slash = name.rfind('/'); slash != std::string::npos) {
      const std::string folder = in_dir(name.substr(0, slash));
      fs::create_directories(folder, ec);
      if (ec) throw InputError(flag + ": cannot create folder " + quoted(folder) + " (" + ec.message() + ")");
    }
  for (const std::string& name : others)
    if (std::find(outputs.begin(), outputs.end(), name) == outputs.end()) remove_if_regular(in_dir(name));
  for (const std::vector<std::string>* list : {&outputs, &others})
    for (const std::string& name : *list) remove_if_regular(in_dir(name + ".partial"));
  // The subfolders of the stale files, when that left them empty, deepest first; never one this run writes into.
  // rmdir(2) removes only an empty folder, so a folder holding anything else (a reader's file) stays.
  std::vector<std::string> folders;
  for (const std::string& name : others)
    for (std::size_t slash = name.rfind('/'); slash != std::string::npos && slash > 0;
         slash = name.rfind('/', slash - 1)) {
      const std::string folder = name.substr(0, slash);
      const bool used = std::any_of(outputs.begin(), outputs.end(), [&](const std::string& output) {
        return output.compare(0, folder.size() + 1, folder + "/") == 0;
      });
      if (!used) folders.push_back(folder);
    }
  std::sort(folders.begin(), folders.end(), [](const std::string& a, const std::string& b) {
    return a.size() != b.size() ? a.size() > b.size() : a < b;
  });
  folders.erase(std::unique(folders.begin(), folders.end()), folders.end());
  for (const std::string& folder : folders) ::rmdir(in_dir(folder).c_str());
}

void prepare_output_dir(const std::string& dir, const std::string& flag) { prepare_outputs(dir, {}, {}, flag); }

struct OutputSink {
  int fd = -1;
  int error = 0;  // errno of the first write or close the system refused
};

namespace {

// The stream's write function (fopencookie): write(2) until every byte is taken, keeping the first refusal's
// errno. It returns the bytes taken, 0 on an error, as fopencookie asks.
ssize_t write_to_sink(void* cookie, const char* data, std::size_t size) {
  auto& sink = *static_cast<OutputSink*>(cookie);
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(sink.fd, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (sink.error == 0) sink.error = n < 0 ? errno : EIO;
      return static_cast<ssize_t>(done);
    }
    done += static_cast<std::size_t>(n);
  }
  return static_cast<ssize_t>(done);
}

int close_sink(void* cookie) {
  auto& sink = *static_cast<OutputSink*>(cookie);
  // close(2) can report a write the system deferred (NFS, quotas): it counts as a refused write.
  if (::close(sink.fd) != 0 && sink.error == 0) sink.error = errno;
  sink.fd = -1;
  return sink.error == 0 ? 0 : -1;
}

}  // namespace

OutputFile::OutputFile(std::string path)
    : path_(std::move(path)), temporary_(path_ + ".partial"), sink_(std::make_unique<OutputSink>()) {
  sink_->fd = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (sink_->fd < 0) fail(errno);
  file_ = ::fopencookie(sink_.get(), "w", cookie_io_functions_t{nullptr, write_to_sink, nullptr, close_sink});
  if (file_ == nullptr) {
    const int error = errno;
    ::close(sink_->fd);
    std::remove(temporary_.c_str());
    fail(error);
  }
  std::setvbuf(file_, nullptr, _IOFBF, 1 << 16);
}

OutputFile::~OutputFile() {
  if (file_ != nullptr) {  // reached only when an exception or an interruption left a writer early
    std::fclose(file_);
    std::remove(temporary_.c_str());
  }
}

void OutputFile::commit() {
  const bool flushed = std::fflush(file_) == 0 && std::ferror(file_) == 0;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) {
    std::remove(temporary_.c_str());
    fail(sink_->error);
  }
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    std::remove(temporary_.c_str());
    fail(error);
  }
}

void OutputFile::fail(int error) const {
  throw OutputError("cannot write " + quoted(path_) + (error != 0 ? std::string(": ") + std::strerror(error) : ""));
}

namespace {

/// One line of numbers built in a buffer and written with one fwrite.
class Line {
 public:
  Line& number(double x, int significant_digits) {
    end_ = std::to_chars(end_, buffer_ + capacity, x, std::chars_format::general, significant_digits).ptr;
    return *this;
  }
  Line& integer(long long n) {
    end_ = std::to_chars(end_, buffer_ + capacity, n).ptr;
    return *this;
  }
  Line& space() {
    *end_++ = ' ';
    return *this;
  }
  void write(std::FILE* file) {
    *end_++ = '\n';
    std::fwrite(buffer_, 1, static_cast<std::size_t>(end_ - buffer_), file);
    end_ = buffer_;
  }

 private:
  static constexpr std::size_t capacity = 256;  // 8 numbers of at most 24 characters and their separators
  char buffer_[capacity];
  char* end_ = buffer_;
};

}  // namespace

void write_text(const std::string& path, const std::string& text) {
  OutputFile f(path);
  std::fwrite(text.data(), 1, text.size(), f.get());
  f.commit();
}

void write_final(const std::string& path, const Scene& scene, const ConstVectorRef& x, const ConstVectorRef& v) {
  OutputFile f(path);
  const Grid& g = scene.grid();
  std::fputs("# i j x y z vx vy vz\n", f.get());
  Line line;
  for (int i = 0; i < g.M; ++i)
    for (int j = 0; j < g.N; ++j) {
      const int s = scene.slot(g.particle(i, j));
      Eigen::Vector3d p = scene.rest_positions().segment<3>(3 * s), u = Eigen::Vector3d::Zero();
      if (s < scene.free_count()) p = x.segment<3>(3 * s), u = v.segment<3>(3 * s);
      line.integer(i).space().integer(j);
      for (const double value : {p[0], p[1], p[2], u[0], u[1], u[2]}) line.space().number(value, 17);
      line.write(f.get());
    }
  f.commit();
}

void write_energy(const std::string& path, const std::vector<EnergySample>& samples) {
  OutputFile f(path);
  std::fputs("# t kinetic gravity spring total\n", f.get());
  Line line;
  for (const EnergySample& s : samples) {
    line.number(s.t, 10);
    for (const double value : {s.energy.kinetic, s.energy.gravity, s.energy.spring, s.energy.total()})
      line.space().number(value, 17);
    line.write(f.get());
  }
  f.commit();
}

void write_frames(const std::string& path, const Grid& grid, const std::vector<Frame>& frames) {
  OutputFile f(path);
  Line line;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (k > 0) std::fputs("\n\n", f.get());
    std::fprintf(f.get(), "# frame %zu t = %.10g\n# i j x y z\n", k, frames[k].t);
    for (int i = 0; i < grid.M; ++i) {
      if (i > 0) std::fputc('\n', f.get());
      for (int j = 0; j < grid.N; ++j) {
        const auto p = frames[k].positions.segment<3>(3 * grid.particle(i, j));
        line.integer(i).space().integer(j).space().number(p[0], 10).space().number(p[1], 10).space().number(p[2], 10);
        line.write(f.get());
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

// Declared in program/output_spec.hpp; defined here, beside prepare_outputs, so that the declarations themselves
// (listed by `--list-outputs`, also in the WebAssembly build, which writes no files) need no file system.
void prepare_declared_outputs(const std::string& dir, const OutputList& written, const OutputList& others) {
  prepare_outputs(dir, output_names(written), output_names(others));
}

}  // namespace cloth
