// Strict parsing of the shared command-line flags of docs/model.md.
#include "program/command_line.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "program/output.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace cloth {

namespace {

// strtod and strtoll skip leading blanks; a value with blanks around it is a quoting slip, so it is refused whole.
bool has_blank(const std::string& text) { return text.find_first_of(" \t\n\r\f\v") != std::string::npos; }

}  // namespace

double parse_number(const std::string& text) {
  if (text.empty()) throw InputError("expected a number, got an empty value");
  if (has_blank(text)) throw InputError("expected a number, got '" + text + "'");
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE)
    throw InputError("expected a number, got '" + text + "'");
  if (!std::isfinite(value)) throw InputError("expected a finite number, got '" + text + "'");
  return value;
}

long long parse_integer(const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || has_blank(text) || end != text.c_str() + text.size() || errno == ERANGE)
    throw InputError("expected a whole number, got '" + text + "'");
  return value;
}

namespace {

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
  if (x == std::string::npos) throw InputError("expected MxN (for example 20x20), got '" + text + "'");
  long long M = 0, N = 0;
  try {
    M = parse_integer(text.substr(0, x));
    N = parse_integer(text.substr(x + 1));
  } catch (const InputError&) {
    throw InputError("expected MxN with whole numbers M, N >= 2 (for example 20x20), got '" + text + "'");
  }
  if (M < 2 || N < 2)
    throw InputError("expected MxN with M, N >= 2: a cloth needs 2 particles in each direction, got '" + text + "'");
  if (M * N > max_particles || M > max_particles || N > max_particles)
    throw InputError("'" + text + "' has more than " + std::to_string(max_particles) +
                     " particles, the largest grid accepted");
  return Grid{static_cast<int>(M), static_cast<int>(N), spacing};
}

/// The shared flags of docs/model.md, in the order --help lists them: the usage text and the "missing value" message
/// both come from this one table, so they cannot disagree.
struct SharedFlag {
  const char* name;
  const char* value_name;
  const char* accepted;  ///< what the value means and which values are accepted
  const char* fallback;  ///< the default, as --help prints it
};
constexpr SharedFlag shared_flags[] = {
    {"--grid", "MxN", "particles, M, N >= 2", "20x20"},
    {"--spacing", "d", "rest spacing [m], > 0", "0.1"},
    {"--K", "k", "spring stiffness [N/m], > 0", "50"},
    {"--damping", "D", "damping coefficient, >= 0", "0"},
    {"--damping-model", "projected|report", "damping law", "projected"},
    {"--springs", "LIST", "comma list of structural,shear,flexion", "all three"},
    {"--pins", "corners|corner|edge|none", "pinned particles", "corners"},
    {"--v0", "vz", "initial z velocity of free particles [m/s]", "-20"},
    {"--dt", "h", "time step [s], > 0", "0.01"},
    {"--t-end", "T", "simulated time [s], >= dt", "2"},
    {"--frames", "n", "frames.dat holds n+1 frames, 1 <= n <= 100000", "20"},
    {"--out", "DIR", "output folder", ""},
};

const SharedFlag* find_shared(const std::string& flag) {
  for (const SharedFlag& f : shared_flags)
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
    if (!known) throw InputError("unknown spring family '" + item + "': expected a comma list of structural,shear,flexion");
    ++count;
  }
  if (count == 0) throw InputError("expected a comma list of structural,shear,flexion, got an empty value");
  return set;
}

}  // namespace

CommandLine::CommandLine(std::string program, std::string summary)
    : program_(std::move(program)), summary_(std::move(summary)) {}

void CommandLine::add_value(std::string flag, std::string value_name, std::string help,
                            std::function<void(const std::string&)> set) {
  chapter_flags_.push_back({std::move(flag), std::move(value_name), std::move(help), std::move(set), {}});
}

void CommandLine::add_switch(std::string flag, std::string help, std::function<void()> set) {
  chapter_flags_.push_back({std::move(flag), "", std::move(help), {}, std::move(set)});
}

std::string CommandLine::usage() const {
  std::ostringstream u;
  const auto line = [&u](std::string head, const std::string& text, const std::string& fallback) {
    head = "  " + head;
    if (head.size() < 37) head.resize(37, ' ');
    u << head << " " << text << (fallback.empty() ? "" : " (default " + fallback + ")") << "\n";
  };
  u << "usage: " << program_ << " [flags]\n"
    << summary_ << "\n\nScene and run flags (the book's model page, docs/model.md):\n";
  for (const SharedFlag& f : shared_flags)
    line(std::string(f.name) + " " + f.value_name, f.accepted,
         std::string(f.name) == "--out" ? "./" + program_ : std::string(f.fallback));
  line("--help", "this text", "");
  if (!chapter_flags_.empty()) {
    u << "\nChapter flags:\n";
    for (const Flag& f : chapter_flags_) line(f.name + (f.value_name.empty() ? "" : " " + f.value_name), f.help, "");
  }
  u << "\nExit status: 0 finished, 2 bad input (nothing written), 3 diverged (outputs up to then kept).\n";
  return u.str();
}

Options CommandLine::parse(int argc, const char* const* argv) const {
  Options opt;
  opt.run.out_dir = program_;
  std::string grid_text;
  for (int k = 1; k < argc; ++k) {
    const std::string flag = argv[k];
    if (flag == "--help" || flag == "-h") {
      std::cout << usage();
      throw HelpRequested{};
    }
    const Flag* chapter = nullptr;
    for (const Flag& f : chapter_flags_)
      if (f.name == flag) chapter = &f;
    if (chapter != nullptr && chapter->set_switch) {
      chapter->set_switch();
      continue;
    }
    const SharedFlag* shared = find_shared(flag);
    if (chapter == nullptr && shared == nullptr)
      throw InputError("unknown flag '" + flag + "' (" + program_ + " --help lists the accepted flags)");
    if (k + 1 >= argc || looks_like_flag(argv[k + 1])) {
      std::string message = flag;
      message.append(": missing value: expected ").append(flag).append(" ");
      message.append(chapter != nullptr ? chapter->value_name : shared->value_name).append(" (");
      message.append(chapter != nullptr ? chapter->help : shared->accepted).append(")");
      throw InputError(message);
    }
    const std::string value = argv[++k];
    try {
      if (chapter != nullptr) chapter->set_value(value);
      else if (flag == "--grid") grid_text = value;
      else if (flag == "--spacing") opt.scene.grid.d = positive(value);
      else if (flag == "--K") opt.scene.stiffness = positive(value);
      else if (flag == "--damping") opt.scene.damping = non_negative(value);
      else if (flag == "--damping-model") {
        if (value == "projected") opt.scene.damping_model = DampingModel::projected;
        else if (value == "report") opt.scene.damping_model = DampingModel::report;
        else throw InputError("unknown damping model '" + value + "': expected projected or report");
      } else if (flag == "--springs") opt.scene.families = parse_families(value);
      else if (flag == "--pins") {
        if (value == "corners") opt.scene.pins = PinSet::corners;
        else if (value == "corner") opt.scene.pins = PinSet::corner;
        else if (value == "edge") opt.scene.pins = PinSet::edge;
        else if (value == "none") opt.scene.pins = PinSet::none;
        else throw InputError("unknown pin set '" + value + "': expected corners, corner, edge or none");
      } else if (flag == "--v0") opt.scene.initial_velocity_z = parse_number(value);
      else if (flag == "--dt") opt.run.dt = positive(value);
      else if (flag == "--t-end") opt.run.t_end = positive(value);
      else if (flag == "--frames") {
        const long long n = parse_integer(value);
        if (n < 1 || n > 100000) throw InputError("expected a whole number from 1 to 100000, got " + value);
        opt.run.frames = static_cast<int>(n);
      } else if (flag == "--out") {
        if (value.empty()) throw InputError("expected a folder name, got an empty value");
        opt.run.out_dir = value;
      }
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
  if (opt.run.t_end < opt.run.dt)
    throw InputError("--t-end: " + format_number(opt.run.t_end) + " is smaller than --dt " + format_number(opt.run.dt) +
                     ": expected t-end >= dt");
  if (opt.run.t_end / opt.run.dt > 1e9)
    throw InputError("--t-end / --dt: more than 1e9 steps asked for; expected at most 1e9");
  try {
    validate(opt.scene);
  } catch (const InputError& e) {
    throw InputError(std::string("scene: ") + e.what());
  }
  return opt;
}

void prepare_output_dir(const std::string& dir, const std::string& flag) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError(flag + ": cannot create folder '" + dir + "'" + (ec ? " (" + ec.message() + ")" : "") +
                     ": expected a writable folder path");
  const fs::path probe = fs::path(dir) / ".write_test";
  {
    std::ofstream test(probe);
    if (!test) throw InputError(flag + ": folder '" + dir + "' is not writable: expected a writable folder path");
  }
  fs::remove(probe, ec);
}

int run_program(const std::string& program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const HelpRequested&) {
    return 0;
  } catch (const InputError& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 2;
  } catch (const OutputError& e) {
    // The folder --out names cannot take the outputs: the contract's status for an unwritable --out, although
    // here some files may already be written.
    std::cerr << program << ": --out: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace cloth
