// Strict parsing of the common command-line flags of the model page.
#include "program/command_line.hpp"

#include "model/bending.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "base/text.hpp"
#include "program/interrupt.hpp"
#include "program/limits.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <new>
#include <sstream>
#include <stdexcept>

namespace cloth {

namespace {

std::string quoted(const std::string& text) { return "'" + escaped(text) + "'"; }

double positive(const std::string& text) {
  const double x = parse_number(text);
  if (!(x > 0)) throw InputError("expected a number > 0, got " + format_number(x));
  return x;
}

double non_negative(const std::string& text) {
  const double x = parse_number(text);
  if (!(x >= 0)) throw InputError("expected a number >= 0, got " + format_number(x));
  return x;
}

Grid parse_grid(const std::string& text, double spacing) {
  const auto x = text.find('x');
  if (x == std::string::npos) throw InputError("expected MxN (for example 20x20), got " + quoted(text));
  long long M = 0, N = 0;
  try {
    M = parse_integer(text.substr(0, x));
    N = parse_integer(text.substr(x + 1));
  } catch (const InputError&) {
    throw InputError("expected MxN with whole numbers M, N >= 2 (for example 20x20), got " + quoted(text));
  }
  if (M < 2 || N < 2)
    throw InputError("expected MxN with M, N >= 2: a cloth needs 2 particles in each direction, got " + quoted(text));
  // M and N first, so that M * N cannot overflow.
  if (M > max_particles || N > max_particles || M * N > max_particles)
    throw InputError(quoted(text) + " has more than " + std::to_string(max_particles) +
                     " particles, the largest grid accepted");
  return Grid{static_cast<int>(M), static_cast<int>(N), spacing};
}

/// The common flags of the model page, in the order `--help` lists them: the usage text and the "missing value"
/// message both come from this one table, so they cannot disagree.
struct CommonFlag {
  const char* name;
  const char* value_name;
  const char* accepted;  ///< what the value means and which values are accepted
  const char* fallback;  ///< the default, as `--help` prints it
};
constexpr CommonFlag common_flags[] = {
    {"--grid", "MxN", "particles, M, N >= 2", "20x20"},
    {"--spacing", "d", "rest spacing [m], > 0", "0.1"},
    {"--mass", "m", "mass of each particle [kg], > 0", "1"},
    {"--K", "k", "spring stiffness [N/m], > 0", "50"},
    {"--K-flexion", "k", "stiffness of the flexion springs alone [N/m], > 0 (fabric bends far more easily than it "
     "stretches, Chapter 10)",
     "--K"},
    {"--damping", "D", "damping coefficient [N s/m], >= 0", "0"},
    {"--damping-model", "projected|report", "damping law", "projected"},
    {"--springs", "LIST", "the spring families modelled, a comma list of structural,shear,flexion", "all three"},
    {"--pins", "corners|corner|edge|none",
     "pinned particles: the four corners, the one corner (0,0), the whole edge j = N-1, or none", "corners"},
    {"--v0", "vz", "initial z velocity of free particles [m/s]", "-20"},
    {"--bending", "flexion|hinge|quadratic",
     "bending: the flexion springs alone, or a hinge or quadratic energy on the triangles with rigidity "
     "--bending-rigidity, added to every force, energy and Newton matrix (Chapter 12)", "flexion"},
    {"--bending-rigidity", "B", "bending rigidity of the hinge and quadratic energies [N m], > 0", "5e-6"},
    {"--swing", "w",
     "initial turning rate about the edge j = N-1 [rad/s], on top of --v0: particle (i,j) starts with the z velocity "
     "w (N-1-j) d (> 0 lifts the far edge)", "0"},
    {"--dt", "h", "time step [s] of the fixed-step methods, > 0", "0.01"},
    {"--t-end", "T", "simulated time [s], >= dt", "2"},
    {"--frames", "n", "frames.dat holds n+1 frames (at most one per step), 1 <= n <= 100000", "20"},
    {"--out", "DIR", "the folder the outputs go to", ""},
};

const CommonFlag* find_common(const std::string& flag) {
  for (const CommonFlag& f : common_flags)
    if (flag == f.name) return &f;
  return nullptr;
}

// "--K" followed by "--dt" means the value was forgotten; "-20" or "-.5" is a value (a negative number).
bool looks_like_flag(const std::string& arg) {
  return arg.size() > 2 && arg[0] == '-' && arg[1] == '-' && std::isalpha(static_cast<unsigned char>(arg[2])) != 0;
}

FamilySet parse_families(const std::string& text) {
  FamilySet set{{false, false, false}};
  std::stringstream s(text);
  std::string item;
  int count = 0;
  while (std::getline(s, item, ',')) {
    bool known = false;
    for (SpringFamily f : all_spring_families)
      if (item == family_name(f)) set.on[static_cast<int>(f)] = known = true;
    if (!known)
      throw InputError("unknown spring family " + quoted(item) + ": expected a comma list of structural,shear,flexion");
    ++count;
  }
  if (count == 0) throw InputError("expected a comma list of structural,shear,flexion, got an empty value");
  return set;
}

void set_common(Options& opt, std::string& grid_text, const std::string& flag, const std::string& value) {
  if (flag == "--grid") grid_text = value;
  else if (flag == "--spacing") opt.scene.grid.d = positive(value);
  else if (flag == "--mass") opt.scene.mass = positive(value);
  else if (flag == "--K") opt.scene.stiffness = positive(value);
  else if (flag == "--K-flexion") opt.scene.flexion_stiffness = positive(value);
  else if (flag == "--damping") opt.scene.damping = non_negative(value);
  else if (flag == "--damping-model") {
    if (value == "projected") opt.scene.damping_model = DampingModel::projected;
    else if (value == "report") opt.scene.damping_model = DampingModel::report;
    else throw InputError("unknown damping model " + quoted(value) + ": expected projected or report");
  } else if (flag == "--springs") opt.scene.families = parse_families(value);
  else if (flag == "--pins") {
    if (value == "corners") opt.scene.pins = PinSet::corners;
    else if (value == "corner") opt.scene.pins = PinSet::corner;
    else if (value == "edge") opt.scene.pins = PinSet::edge;
    else if (value == "none") opt.scene.pins = PinSet::none;
    else throw InputError("unknown pin set " + quoted(value) + ": expected corners, corner, edge or none");
  } else if (flag == "--v0") opt.scene.initial_velocity_z = parse_number(value);
  else if (flag == "--swing") opt.scene.initial_swing = parse_number(value);
  else if (flag == "--bending") opt.scene.bending = bending_models().parse(value);
  else if (flag == "--bending-rigidity") opt.scene.bending_rigidity = positive(value);
  else if (flag == "--dt") opt.run.dt = positive(value);
  else if (flag == "--t-end") opt.run.t_end = positive(value);
  else if (flag == "--frames") {
    opt.run.frames = static_cast<int>(parse_count(value, 1, 100000));
  } else if (flag == "--out") {
    if (value.empty()) throw InputError("expected a folder name, got an empty value");
    opt.run.out_dir = value;
  }
}

}  // namespace

CommandLine::CommandLine(std::string program, std::string summary)
    : program_(std::move(program)), summary_(std::move(summary)) {
  for (const CommonFlag& f : common_flags) common_.emplace_back(f.name);
}

void CommandLine::use_common(std::initializer_list<const char*> flags) {
  common_.clear();
  for (const CommonFlag& f : common_flags)
    if (std::any_of(flags.begin(), flags.end(), [&](const char* name) { return std::string(name) == f.name; }))
      common_.emplace_back(f.name);
  for (const char* name : flags)
    if (find_common(name) == nullptr) throw std::logic_error(std::string("use_common: '") + name + "' is not a common flag");
}

void CommandLine::set_default(const std::string& flag, std::string value) {
  if (!uses(flag)) throw std::logic_error("set_default: " + program_ + " does not accept " + flag);
  for (auto& [name, fallback] : defaults_)
    if (name == flag) {
      fallback = std::move(value);
      return;
    }
  defaults_.emplace_back(flag, std::move(value));
}

bool CommandLine::uses(const std::string& flag) const {
  return std::find(common_.begin(), common_.end(), flag) != common_.end();
}

void CommandLine::add_value(std::string flag, std::string value_name, std::string help,
                            std::function<void(const std::string&)> set) {
  chapter_flags_.push_back({std::move(flag), std::move(value_name), std::move(help), std::move(set), {}});
}

void CommandLine::add_switch(std::string flag, std::string help, std::function<void()> set) {
  chapter_flags_.push_back({std::move(flag), "", std::move(help), {}, std::move(set)});
}

void CommandLine::declare_outputs(std::function<OutputList(const Options&)> outputs) { outputs_ = std::move(outputs); }

std::string CommandLine::usage() const {
  std::ostringstream u;
  const auto line = [&u](std::string head, const std::string& text, const std::string& fallback) {
    head = "  " + head;
    if (head.size() < 37) head.resize(37, ' ');
    u << head << " " << text << (fallback.empty() ? "" : " (default " + fallback + ")") << "\n";
  };
  u << "usage: " << program_ << " [flags]\n" << summary_ << "\n\nScene and run flags (the book's appendix on the programs, docs/back_matter/appendix_programs.md):\n";
  for (const CommonFlag& f : common_flags)
    if (uses(f.name)) {
      std::string accepted = f.accepted;
      // Without --dt (an adaptive program) T is not bounded below by a step.
      if (const auto at = accepted.find(", >= dt"); at != std::string::npos && !uses("--dt")) accepted.erase(at);
      // Nor are its frames one per step at most: it interpolates each at its time (the model page, frames.dat).
      if (const auto at = accepted.find("(at most one per step)"); at != std::string::npos && !uses("--dt"))
        accepted.replace(at, 22, "(interpolated at their times)");
      std::string fallback = std::string(f.name) == "--out" ? "./" + program_ : std::string(f.fallback);
      for (const auto& [name, value] : defaults_)
        if (name == f.name) fallback = value;
      line(std::string(f.name) + " " + f.value_name, accepted, fallback);
    }
  line("--help", "this text", "");
  if (outputs_)
    line("--list-outputs", "print the files the run the other flags describe writes into --out (name, kind: fragment, "
                           "figure_input or data, what it holds) instead of running", "");
  if (!chapter_flags_.empty()) {
    u << "\nChapter flags:\n";
    for (const Flag& f : chapter_flags_) line(f.name + (f.value_name.empty() ? "" : " " + f.value_name), f.help, "");
  }
  u << "\nEach flag at most once. Ctrl-C (SIGINT) or SIGTERM stops a run at its next step and keeps its outputs.\n"
       "Exit status: 0 finished, 1 internal error, 2 bad input (nothing written), 3 diverged or a step failed\n"
       "(outputs up to then kept), 4 an output could not be written, 130/143 interrupted (outputs up to then kept).\n";
  return u.str();
}

std::string CommandLine::markdown_reference() const {
  // A table cell holds no bare '|' (it would end the cell; Doxygen prints an escaped one, where it would print a
  // character entity literally) and shows flags and
  // values as code, each alternative of a value as code of its own.
  // A flag named in the text ("--dt") is code too: as plain text its "--" would print as a dash.
  const auto cell = [](const std::string& text) {
    std::string out;
    for (std::size_t k = 0; k < text.size(); ++k) {
      const bool flag_starts = text.compare(k, 2, "--") == 0 && (k == 0 || text[k - 1] == ' ' || text[k - 1] == '(') &&
                               k + 2 < text.size() && std::isalpha(static_cast<unsigned char>(text[k + 2])) != 0;
      if (flag_starts) {
        std::size_t end = k + 2;
        while (end < text.size() && (std::isalnum(static_cast<unsigned char>(text[end])) != 0 || text[end] == '-')) ++end;
        out += "`" + text.substr(k, end - k) + "`";
        k = end - 1;
      } else {
        out += text[k] == '|' ? std::string{'\\', '|'} : std::string(1, text[k]);
      }
    }
    return out;
  };
  const auto code = [](const std::string& text) {
    std::string out = "`";
    for (const char c : text) out += c == '|' ? std::string("` or `") : std::string(1, c);
    return out + "`";
  };
  std::ostringstream md;
  md << "| common flag | accepts | default here |\n|---|---|---|\n";
  for (const CommonFlag& f : common_flags)
    if (uses(f.name)) {
      std::string fallback = std::string(f.name) == "--out" ? "./" + program_ : std::string(f.fallback);
      for (const auto& [name, value] : defaults_)
        if (name == f.name) fallback = value;
      md << "| " << code(std::string(f.name) + " " + f.value_name) << " | " << cell(f.accepted) << " | "
         << (fallback.find(' ') != std::string::npos ? fallback : fallback.empty() ? "" : code(fallback)) << " |\n";
    }
  if (!chapter_flags_.empty()) {
    md << "\n| " << program_ << "'s own flag | meaning |\n|---|---|\n";
    for (const Flag& f : chapter_flags_)
      md << "| " << code(f.name + (f.value_name.empty() ? "" : " " + f.value_name)) << " | " << cell(f.help) << " |\n";
  }
  return md.str();
}

Options CommandLine::parse(int argc, const char* const* argv) const {
  Options opt;
  opt.run.out_dir = program_;
  opt.run.stop = &interrupt_flag();
  std::string grid_text;
  // The program's own defaults first, so that what the reader types overrides them.
  for (const auto& [flag, value] : defaults_) {
    try {
      set_common(opt, grid_text, flag, value);
    } catch (const InputError& e) {
      throw InputError(flag + " (" + program_ + "'s default): " + e.what());
    }
  }
  std::vector<std::pair<std::string, std::string>> given;  // flag and value, to refuse a flag given twice
  bool list_outputs = false;
  for (int k = 1; k < argc; ++k) {
    const std::string flag = argv[k];
    if (flag == "--help" || flag == "-h") {
      std::cout << usage();
      throw HelpRequested{};
    }
    if (flag == "--help-markdown") {  // the book's appendix on the programs reads it (cmake/ProgramReference.cmake)
      std::cout << markdown_reference();
      throw HelpRequested{};
    }
    if (flag == "--list-outputs" && outputs_) {
      list_outputs = true;
      continue;
    }
    const Flag* chapter = nullptr;
    for (const Flag& f : chapter_flags_)
      if (f.name == flag) chapter = &f;
    const CommonFlag* common = uses(flag) ? find_common(flag) : nullptr;
    if (chapter == nullptr && common == nullptr)
      throw InputError("unknown flag " + quoted(flag) + " (" + program_ + " --help lists the accepted flags)");
    const bool takes_value = chapter == nullptr || !chapter->set_switch;
    if (takes_value && (k + 1 >= argc || looks_like_flag(argv[k + 1]))) {
      std::string message = flag;
      message.append(": missing value: expected ").append(flag).append(" ");
      message.append(chapter != nullptr ? chapter->value_name : common->value_name).append(" (");
      message.append(chapter != nullptr ? chapter->help : common->accepted).append(")");
      throw InputError(message);
    }
    const std::string value = takes_value ? argv[++k] : "";
    for (const auto& [earlier, earlier_value] : given)
      if (earlier == flag)
        throw InputError(flag + ": given twice" +
                         (takes_value ? " (" + quoted(earlier_value) + ", then " + quoted(value) + ")" : "") +
                         ": expected each flag at most once");
    given.emplace_back(flag, value);
    opt.given.push_back(flag);
    try {
      if (chapter != nullptr && !takes_value) chapter->set_switch();
      else if (chapter != nullptr) chapter->set_value(value);
      else set_common(opt, grid_text, flag, value);
    } catch (const InputError& e) {
      throw InputError(flag + ": " + e.what());
    }
  }
  if (!grid_text.empty()) {
    try {
      opt.scene.grid = parse_grid(grid_text, opt.scene.grid.d);
    } catch (const InputError& e) {
      throw InputError(std::string("--grid: ") + e.what());
    }
  }
  try {
    validate(opt.scene);
  } catch (const InputError& e) {
    throw InputError(std::string("scene: ") + e.what());
  }
  // A program without --dt (an adaptive one chooses its own steps) is not held to the fixed step's limits.
  if (uses("--dt")) {
    if (opt.run.t_end < opt.run.dt)
      throw InputError("--t-end: " + format_number(opt.run.t_end) + " is smaller than --dt " +
                       format_number(opt.run.dt) + ": expected t-end >= dt");
    if (opt.run.t_end / opt.run.dt > 1e9)
      throw InputError("--t-end / --dt: more than 1e9 steps asked for; expected at most 1e9");
  }
  require_representable(opt.scene, opt.run);
  // What one recorded run by an explicit method holds: a fixed-step program's frames are at most one per step, an
  // adaptive program's (no --dt, but --frames) are interpolated, all of them; a program with a horizon that records
  // neither holds the scene and the method.
  if (uses("--dt")) {
    RunSettings recorded = opt.run;
    if (!uses("--frames")) recorded.frames = 0;  // a program without --frames records none
    require_run_memory(opt.scene, recorded, explicit_bytes_per_particle());
  }
  else if (uses("--frames"))
    require_interpolated_run_memory(opt.scene, opt.run, explicit_bytes_per_particle());
  else if (uses("--t-end"))
    require_memory(static_cast<double>(opt.scene.grid.M) * opt.scene.grid.N * explicit_bytes_per_particle(), "--grid",
                   "a run on a " + std::to_string(opt.scene.grid.M) + "x" + std::to_string(opt.scene.grid.N) + " grid",
                   ": expected a smaller grid");
  if (list_outputs) {
    std::cout << output_listing(outputs_(opt));
    throw HelpRequested{};
  }
  return opt;
}

bool Options::has(const std::string& flag) const { return std::find(given.begin(), given.end(), flag) != given.end(); }

void refuse_unused(const Options& opt, const std::string& mode, std::initializer_list<const char*> unused,
                   const std::string& why) {
  for (const char* flag : unused)
    if (opt.has(flag)) {
      std::string message = flag;
      message.append(": ").append(mode).append(" does not use it (").append(why).append("): expected ");
      message.append(mode).append(" without ").append(flag);
      throw InputError(message);
    }
}

namespace {

std::string terminating_program = "cloth";  // the program std::terminate names (run_program sets it)

}  // namespace

int run_program(const std::string& program, const std::function<int()>& body) {
  install_interrupt_handlers();
  // An exception nobody catches (one thrown in a worker thread, or through a noexcept function) ends in
  // std::terminate: one line and status 1 instead of an abort and a core dump.
  terminating_program = program;
  std::set_terminate([] {
    std::fprintf(stderr, "%s: internal error: an exception escaped where none can be handled (std::terminate)\n",
                 terminating_program.c_str());
    std::_Exit(1);
  });
  const auto say = [&program](const std::string& line) { std::cerr << program << ": " << line << "\n"; };
  const auto interrupted = [&](int signal) {
    say("interrupted by " + signal_name(signal) + "; the outputs written are complete, the rest were not written");
    return 128 + signal;
  };
  try {
    const int status = body();
    // A run that saw the stop request returned 128 + signal and said so; a signal that came after the last step
    // still ends the program as interrupted, its outputs whole.
    if (const int signal = interrupt_signal(); signal != 0 && status < 128) {
      say("interrupted by " + signal_name(signal) + " as the program finished; the outputs written are complete");
      return 128 + signal;
    }
    return status;
  } catch (const HelpRequested&) {
    return 0;
  } catch (const InputError& e) {
    say(e.what());
    return 2;
  } catch (const OutputError& e) {
    say(e.what());
    return 4;
  } catch (const Interrupted& e) {
    return interrupted(e.signal);
  } catch (const std::bad_alloc&) {
    say("internal error: out of memory (std::bad_alloc) although the run's size was checked against the "
        "machine's memory; the outputs written before are complete");
    return 1;
  } catch (const std::exception& e) {
    say(std::string("internal error: ") + e.what());
    return 1;
  } catch (...) {
    say("internal error: an unknown exception");
    return 1;
  }
}

}  // namespace cloth
