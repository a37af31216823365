// Writers for the output files of docs/model.md: final.dat, energy.dat, frames.dat and run.txt.
#pragma once

#include "integrators/simulate.hpp"
#include "model/force_field.hpp"

#include <cstdio>
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

/// One output file, written whole or not at all. It is written under a temporary name (`path` + ".partial") and
/// renamed to `path` by commit(), so a final name never holds a partial file; destroyed without commit() (an
/// exception, an interrupted run) it removes the temporary file. stdio buffers what fprintf writes, so a write the
/// system refuses (a full disk) usually fails only at a later flush or at fclose, and sets the stream's error flag
/// rather than failing the fprintf that caused it: whether the file is whole is known at commit(), which every
/// writer calls last.
class OutputFile {
 public:
  /// Opens the temporary file; throws OutputError naming `path` and the system's reason when it cannot.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  [[nodiscard]] std::FILE* get() const { return file_; }

  /// Flushes and closes the file and renames it into place; throws OutputError if any write to it failed.
  void commit();

 private:
  [[noreturn]] void fail(int error) const;

  std::string path_, temporary_;
  std::FILE* file_;
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
