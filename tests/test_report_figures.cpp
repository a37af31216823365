// End-to-end checks of Chapter 5's program on a small cloth: bad input is refused, the summary covers the whole
// method x configuration grid, the strain meshes start unstretched, and the energy verdicts the page quotes
// (implicit Euler never gains energy; explicit Euler gains far more than RK4) come out of the run.
#include "program_runner.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>

using namespace cloth_test;

#ifdef CLOTH_HAVE_CH05_REPORT_FIGURES
TEST_CASE("ch05_report_figures --threads 0: status 2, the flag named, nothing written") {
  const ProgramFolder folder;
  const ProgramRun run = folder.run("ch05_report_figures", {"--threads", "0", "--out", "out"});
  CHECK(run.status == 2);
  CHECK(run.err.find("--threads") != std::string::npos);
  CHECK(entry_count(folder.cwd()) == 0);
}

TEST_CASE("ch05_report_figures on an 8x8 cloth: full grid, unstretched start, energy verdicts") {
  const ProgramFolder folder;
  const fs::path& cwd = folder.cwd();
  const ProgramRun run = folder.run("ch05_report_figures", {"--grid", "8x8", "--t-end", "0.5", "--no-sweep", "--out", "out"});
  CAPTURE(run.err);
  REQUIRE(run.status == 0);

  // summary.dat: method K D status t_diverged gain final_change ...; one row per method and configuration.
  const std::vector<std::string> rows = data_lines(cwd / "out" / "summary.dat");
  REQUIRE(rows.size() == 12);
  std::map<std::string, double> gain;
  for (const std::string& row : rows) {
    std::istringstream in(row);
    std::string method, status, t_div;
    double K = 0, D = 0, g = 0;
    in >> method >> K >> D >> status >> t_div >> g;
    gain[method + " " + std::to_string(static_cast<int>(K)) + " " + std::to_string(static_cast<int>(D))] = g;
  }
  REQUIRE(gain.size() == 12);
  // Backward Euler contracts every linear mode (|1/(1 - z)| < 1 for Re z <= 0), so the energy never rises above E(0).
  CHECK(gain["implicit_euler 50 0"] == 0.0);
  CHECK(gain["implicit_euler 200 0"] == 0.0);
  CHECK(gain["implicit_euler 200 20"] == 0.0);
  // Explicit Euler's energy factor 1 + (h omega)^2 a step against RK4's 1 + O((h omega)^6): orders apart.
  CHECK(gain["explicit_euler 50 0"] > 100 * gain["rk4 50 0"]);
  CHECK(gain["explicit_euler 50 0"] > 0.0);

  // The first block of a mesh file is the rest state: every spring at its rest length, strain 0 to print precision.
  std::ifstream mesh(cwd / "out" / "mesh_rk4_K50_D0.dat");
  std::string line;
  int segments = 0;
  double worst = 0;
  while (std::getline(mesh, line)) {
    if (line.rfind("# t = ", 0) == 0 && segments > 0) break;  // the second block starts
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    double x = 0, y = 0, z = 0, strain = 1;
    in >> x >> y >> z >> strain;
    worst = std::max(worst, std::abs(strain));
    ++segments;
  }
  CHECK(segments == 2 * (7 * 8 + 8 * 7));  // two endpoints per structural spring of an 8x8 grid
  CHECK(worst < 1e-12);
  CHECK(fs::exists(cwd / "out" / "runs" / "implicit_euler_K50_D0" / "run.txt"));
}

namespace {

/// The first word of `text` (a run of letters) that is how printf spells a non-finite number: "inf", "infinity"
/// or "nan", in any case; empty when there is none.
std::string not_finite_word(const std::string& text) {
  std::string word;
  for (std::size_t k = 0; k <= text.size(); ++k) {
    const char c = k < text.size() ? text[k] : ' ';
    if (std::isalpha(static_cast<unsigned char>(c)) != 0) {
      word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      continue;
    }
    if (word == "inf" || word == "infinity" || word == "nan") return word;
    word.clear();
  }
  return "";
}

}  // namespace

TEST_CASE("ch05_report_figures --v0 0: a cloth dropped from rest (E(0) = 0) has finite energy ratios, to W L") {
  const ProgramFolder folder;
  const fs::path out = folder.cwd() / "out";
  const ProgramRun run =
      folder.run("ch05_report_figures", {"--grid", "6x6", "--t-end", "0.2", "--v0", "0", "--out", "out"});
  CAPTURE(run.err);
  REQUIRE(run.status == 0);
  // What the reader reads, the console and the page's fragments, and the ratios the energy plot draws: no
  // infinity or NaN, as a ratio to E(0) = 0 would give.
  std::vector<std::pair<std::string, std::string>> texts = {{"stdout", run.out}};
  for (const char* fragment : {"summary.md", "theory.md", "deformed_damping.md", "growth.md", "sweep.md",
                               "sweep_implicit.md", "series_rk4_K200_D20.dat", "series_explicit_euler_K50_D0.dat"})
    texts.emplace_back(fragment, read_text(out / fragment));
  for (const auto& [name, text] : texts) {
    INFO(name);
    CHECK(!text.empty());
    CHECK(not_finite_word(text).empty());
  }
  // The reference is W L: 32 free particles of 1 kg at g = 9.81 m/s^2, side 5 x 0.1 m (a 6x6 grid, four corners
  // pinned), 156.96 J; the page's table names it.
  CHECK(read_text(out / "summary.md").find("W L = 0.157 kJ") != std::string::npos);
  std::istringstream parameters(data_lines(out / "parameters.dat").at(0));
  double h = 0, t_end = 0, t_implicit = 0, e_ref = 0;
  int nmethods = 0, ncases = 0, ninstants = 0, launch = 1;
  parameters >> h >> t_end >> t_implicit >> nmethods >> ncases >> ninstants >> e_ref >> launch;
  CHECK(e_ref == doctest::Approx(32 * 9.81 * 0.5).epsilon(1e-5));
  CHECK(launch == 0);
}
#endif
