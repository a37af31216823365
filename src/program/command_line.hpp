// The one command-line contract of docs/model.md, shared by every chapter program: the scene flags, the run flags,
// chapter-specific flags on top, and strict validation (one clear line and exit status 2 on bad input).
#pragma once

#include "integrators/simulate.hpp"
#include "model/scene.hpp"

#include <functional>
#include <string>
#include <vector>

namespace cloth {

/// Everything the shared flags set.
struct Options {
  SceneParams scene;
  RunSettings run;
};

/// Parses the shared flags and a chapter's own. Usage:
///   CommandLine cli("ch03_runge_kutta", "Runge-Kutta methods from their Butcher tableau.");
///   cli.add_value("--tableau", "NAME|FILE", "...", [&](const std::string& s) { tableau = s; });
///   Options opt = cli.parse(argc, argv);   // throws InputError, or HelpRequested after printing usage
class CommandLine {
 public:
  CommandLine(std::string program, std::string summary);

  /// A chapter flag taking a value; `set` throws InputError (message without the flag name) when it is bad.
  void add_value(std::string flag, std::string value_name, std::string help, std::function<void(const std::string&)> set);
  /// A chapter flag without a value.
  void add_switch(std::string flag, std::string help, std::function<void()> set);

  /// Parses argv. Throws InputError naming the flag on any bad input, HelpRequested after printing --help.
  Options parse(int argc, const char* const* argv) const;

  [[nodiscard]] std::string usage() const;
  [[nodiscard]] const std::string& program() const { return program_; }

 private:
  struct Flag {
    std::string name, value_name, help;
    std::function<void(const std::string&)> set_value;
    std::function<void()> set_switch;
  };
  std::string program_, summary_;
  std::vector<Flag> chapter_flags_;
};

/// Thrown by CommandLine::parse after it printed the usage for --help.
struct HelpRequested {};

/// Strict number parsing for flags: the whole text must be a finite number. Throw InputError otherwise.
double parse_number(const std::string& text);
long long parse_integer(const std::string& text);

/// Creates the output folder (and its parents). Throws InputError when it cannot be created or written.
void prepare_output_dir(const std::string& dir, const std::string& flag = "--out");

/// Runs a chapter's main body: InputError gives one line "program: message" on stderr and exit status 2, and so
/// does OutputError (an output file not written in full), --help gives exit status 0. The body returns the exit
/// status (0 finished, 3 diverged).
int run_program(const std::string& program, const std::function<int()>& body);

}  // namespace cloth
