// Runs a chapter program the way a reader does, from a shell in a scratch folder, and captures its exit status,
// stdout and stderr: the end-to-end tests of bad input, divergence and determinism are built on it.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace cloth_test {

namespace fs = std::filesystem;

/// A fresh, empty folder under the system's temporary folder, removed with everything in it at scope exit.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (fs::temp_directory_path() / "cloth_test_XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  [[nodiscard]] const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

/// What a finished program left behind.
struct ProgramRun {
  int status = -1;  ///< the exit status; 124 when the time guard stopped it, 128 + n when signal n killed it
  std::string out, err;
};

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The number of entries in a folder (0 for a folder that does not exist).
inline int entry_count(const fs::path& dir) {
  if (!fs::exists(dir)) return 0;
  int n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++n;
  return n;
}

inline std::string shell_quote(const std::string& word) {
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

inline fs::path program_path(const std::string& program) { return fs::path(CLOTH_BIN_DIR) / program; }

/// Runs build/bin/<program> with `args` in folder `cwd`, stdout and stderr captured into files beside `cwd`.
/// `timeout` (coreutils) guards against a hang: a program that should stop at once but does not is a failure
/// with status 124, not a test suite that never ends.
inline ProgramRun run_chapter(const std::string& program, const std::vector<std::string>& args, const fs::path& cwd,
                              int time_guard_seconds = 120) {
  const fs::path out = cwd.parent_path() / (cwd.filename().string() + ".stdout");
  const fs::path err = cwd.parent_path() / (cwd.filename().string() + ".stderr");
  // Joined word by word: GCC 12 gives a false -Wrestrict on "literal" + std::string&& (GCC bug 105329).
  std::vector<std::string> words = {"cd", shell_quote(cwd.string()), "&&", "timeout", std::to_string(time_guard_seconds),
                                    shell_quote(program_path(program).string())};
  for (const std::string& a : args) words.push_back(shell_quote(a));
  words.insert(words.end(), {">", shell_quote(out.string()), "2>", shell_quote(err.string())});
  std::string command;
  for (const std::string& w : words) (command += w) += ' ';
  const int raw = std::system(command.c_str());
  ProgramRun run;
  if (raw != -1 && WIFEXITED(raw)) run.status = WEXITSTATUS(raw);
  run.out = read_text(out);
  run.err = read_text(err);
  std::error_code ec;
  fs::remove(out, ec);
  fs::remove(err, ec);
  return run;
}

/// A scratch folder holding an empty working folder `cwd()`, from which chapter programs are run as a reader runs
/// them: what a program writes relative to where it runs lands in `cwd()`, and stays apart from the scratch
/// folder's other files (test inputs, captured stdout and stderr).
class ProgramFolder {
 public:
  ProgramFolder() : cwd_(scratch_.path() / "cwd") { fs::create_directory(cwd_); }
  [[nodiscard]] const fs::path& scratch() const { return scratch_.path(); }
  [[nodiscard]] const fs::path& cwd() const { return cwd_; }
  /// run_chapter(program, args) in cwd().
  [[nodiscard]] ProgramRun run(const std::string& program, const std::vector<std::string>& args,
                               int time_guard_seconds = 120) const {
    return run_chapter(program, args, cwd_, time_guard_seconds);
  }

 private:
  ScratchDir scratch_;
  fs::path cwd_;
};

/// Every line of a text file that is not a '#' comment and not blank.
inline std::vector<std::string> data_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  return lines;
}

}  // namespace cloth_test
