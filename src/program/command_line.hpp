// The one command-line contract of the programs (the book's appendix on the programs), shared by every chapter
// program: the common flags (scene and run), chapter-specific flags on top, and strict validation (one clear line
// and exit status 2 on bad input).
#pragma once

#include "base/parse_number.hpp"  // parse_number, parse_integer, parse_count: the flags' one rule
#include "integrators/simulate.hpp"
#include "model/scene.hpp"
#include "program/output_spec.hpp"

#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace cloth {

/// Everything the common flags set.
struct Options {
  SceneParams scene;
  RunSettings run;  ///< run.stop points at the program's interrupt flag (program/interrupt.hpp)
  std::vector<std::string> given;  ///< every flag on the command line (common and the chapter's), in order

  /// Whether `flag` was on the command line.
  [[nodiscard]] bool has(const std::string& flag) const;
};

/// A mode of a program (`--experiments`, `--report-runs`) that sets what some flags would set refuses them rather
/// than ignoring them: throws InputError "<flag>: <mode> does not use it (<why>): expected <mode> without <flag>"
/// for the first of `unused` that `opt` was given.
void refuse_unused(const Options& opt, const std::string& mode, std::initializer_list<const char*> unused,
                   const std::string& why);

/// Parses the common flags and a chapter's own. Usage:
///   CommandLine cli("ch03_runge_kutta", "Runge-Kutta methods from their Butcher tableau.");
///   cli.add_value("--tableau", "NAME|FILE", "...", [&](const std::string& s) { tableau = s; });
///   Options opt = cli.parse(argc, argv);   // throws InputError, or HelpRequested after printing usage
/// A single-run program accepts every common flag. An experiment program, which runs its own set of runs, names
/// the common flags it uses, and accepts and lists only those:
///   cli.use_common({"--grid", "--spacing", "--mass", "--K", "--out"});
class CommandLine {
 public:
  CommandLine(std::string program, std::string summary);

  /// Restricts the common flags to `flags` (each a common flag's name, "--out" included when wanted); the
  /// others are refused as unknown and left out of `--help`. Throws std::logic_error on a name that is not one.
  void use_common(std::initializer_list<const char*> flags);

  /// Gives the common flag `flag` this program's own default `value` (the text a reader would type), which
  /// `--help` then prints: `cli.set_default("--t-end", "1")`. Throws std::logic_error when the program does not
  /// accept `flag` (call use_common first), and InputError from parse when `value` is not one it accepts.
  void set_default(const std::string& flag, std::string value);

  /// A chapter flag taking a value; `set` throws InputError (message without the flag name) when it is bad.
  void add_value(std::string flag, std::string value_name, std::string help, std::function<void(const std::string&)> set);
  /// A chapter flag without a value.
  void add_switch(std::string flag, std::string help, std::function<void()> set);

  /// Declares the files a run writes into `--out` (program/output_spec.hpp), as a function of the parsed flags, and
  /// adds `--list-outputs`: parse then prints them (output_listing) instead of running, and ends as for `--help`.
  /// The program prepares `--out` from the same function, so the list the build checks is the one the run uses.
  void declare_outputs(std::function<OutputList(const Options&)> outputs);

  /// Parses argv. Throws InputError naming the flag on any bad input (a flag given twice included),
  /// HelpRequested after printing `--help`. When the program uses the run flags, also checks the run they describe
  /// before anything runs: the number of steps, the numbers of the model at t = 0 (limits.hpp), and the memory of
  /// one recorded run by an explicit method.
  Options parse(int argc, const char* const* argv) const;

  [[nodiscard]] std::string usage() const;
  /// The flags the program accepts as Markdown tables for the book's appendix on the programs (`--help-markdown`
  /// prints it): the common flags it uses with what each accepts and its default here, then the chapter's own.
  [[nodiscard]] std::string markdown_reference() const;
  [[nodiscard]] const std::string& program() const { return program_; }
  /// Whether the program accepts the common flag `flag`.
  [[nodiscard]] bool uses(const std::string& flag) const;

 private:
  struct Flag {
    std::string name, value_name, help;
    std::function<void(const std::string&)> set_value;
    std::function<void()> set_switch;
  };
  std::string program_, summary_;
  std::vector<std::string> common_;  ///< the common flags accepted, in the order `--help` lists them
  std::vector<std::pair<std::string, std::string>> defaults_;  ///< the program's own defaults: flag, value
  std::vector<Flag> chapter_flags_;
  std::function<OutputList(const Options&)> outputs_;  ///< the declared outputs, when the program declared them
};

/// Thrown by CommandLine::parse after it printed the usage for `--help`.
struct HelpRequested {};

/// Creates the output folder (and its parents) and checks that it can be written. Throws InputError when it
/// cannot be created or written. (program/output.hpp declares the form that also checks the outputs' names.)
void prepare_output_dir(const std::string& dir, const std::string& flag = "--out");

/// Runs a chapter's main body and turns what escapes it into the model page's exit statuses, each with one line
/// "program: ..." on stderr: InputError 2, OutputError 4, Interrupted 128 + signal (130 SIGINT, 143 SIGTERM),
/// std::bad_alloc and every other exception 1; `--help` 0. The body returns 0 (finished) or 3 (diverged or a step
/// failed). It also installs the SIGINT and SIGTERM handlers first, turns a signal that arrived while the body
/// finished into 128 + signal, and makes std::terminate print one line and exit with status 1 (no core dump).
int run_program(const std::string& program, const std::function<int()>& body);

}  // namespace cloth
