// Every file a chapter program writes goes through this one checked path: the outputs are declared and checked
// before the run (prepare_outputs), each is written under a temporary name and renamed when whole (OutputFile),
// and a write the system refuses becomes an OutputError naming the file and the reason (exit status 4).
// The writers of the model page's files (final.dat, energy.dat, frames.dat, run.txt) are here too.
#pragma once

#include "integrators/simulate.hpp"
#include "model/force_field.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace cloth {

/// A file that could not be written in full: it could not be opened, the system refused a write (a full disk,
/// an I/O error), or it could not be renamed into place (a folder of its name appeared). The message names the
/// file and the system's reason. run_program turns it into one line on stderr and exit status 4.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Checks and prepares the output folder `dir` for the files a run will write, before anything runs.
/// `outputs` are those files, relative to `dir` ("final.dat", "rk4_K50_D0/run.txt"); `others` are the files the
/// program writes in its other modes, which an earlier run may have left. In order:
///  - every name must be a plain relative path (no "..", "." or empty part, not absolute): std::logic_error if not,
///    since names are the program's own (a name read from a file goes through safe_file_name first);
///  - nothing may be in the way: a folder where an output file (or its `.partial`) goes, or a file where a
///    subfolder goes, is bad input (InputError naming it, so exit status 2 with nothing written);
///  - `dir` and the subfolders are created, and `dir` must be writable (access(2): no probe file is made);
///  - the stale files of an earlier run are removed: each of `others` that is a regular file and not an output
///    of this run, and leftover `.partial` files of both lists. Nothing else in `dir` is touched.
/// Throws InputError (with `flag` first) when the folder cannot be created or written.
void prepare_outputs(const std::string& dir, const std::vector<std::string>& outputs,
                     const std::vector<std::string>& others = {}, const std::string& flag = "--out");

/// Where an OutputFile's stream writes: its file descriptor and the first error the system gave for it.
struct OutputSink;

/// One output file, written whole or not at all. It is written under a temporary name (`path` + ".partial") and
/// renamed to `path` by commit(), so a final name never holds a partial file; destroyed without commit() (an
/// exception, an interrupted run) it removes the temporary file. stdio buffers what fprintf writes, so a write the
/// system refuses (a full disk) usually fails only at a later flush or at fclose, and sets the stream's error flag
/// rather than failing the fprintf that caused it: whether the file is whole is known at commit(), which every
/// writer calls last. The stream hands its buffers to the system through OutputFile's own write function, which
/// keeps the system's reason (errno) of the first refused write for commit()'s message. Usage:
///   OutputFile f(dir + "/order.dat");
///   std::fprintf(f.get(), "# h error\n");
///   f.commit();  // throws OutputError if anything failed
class OutputFile {
 public:
  /// Opens the temporary file; throws OutputError naming `path` and the system's reason when it cannot.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  [[nodiscard]] std::FILE* get() const { return file_; }
  [[nodiscard]] const std::string& path() const { return path_; }

  /// Flushes and closes the file and renames it into place; throws OutputError if any write to it failed.
  void commit();

 private:
  [[noreturn]] void fail(int error) const;

  std::string path_, temporary_;
  std::unique_ptr<OutputSink> sink_;
  std::FILE* file_ = nullptr;
};

// Each writer throws OutputError when its file is not written in full.

/// A small text file, whole: `text` as it is.
void write_text(const std::string& path, const std::string& text);

/// final.dat: `i j x y z vx vy vz` per particle, pinned ones included, 17 significant digits.
void write_final(const std::string& path, const Scene& scene, const ConstVectorRef& x, const ConstVectorRef& v);

/// energy.dat: `t kinetic gravity spring total`, t with 10 significant digits and the energies with 17.
void write_energy(const std::string& path, const std::vector<EnergySample>& samples);

/// frames.dat: one gnuplot `index` block per frame; grid rows (fixed i) separated by one blank line, frames by two.
/// Columns `i j x y z` (10 significant digits), preceded by a comment line with the frame's time.
void write_frames(const std::string& path, const Grid& grid, const std::vector<Frame>& frames);

/// run.txt: `key = value` lines, in the given order.
void write_key_values(const std::string& path, const std::vector<std::pair<std::string, std::string>>& entries);

}  // namespace cloth
