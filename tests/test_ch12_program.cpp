// ch12_bending end to end: one strip's run.txt holds what a reader needs to check it against an elastica of their
// own, and its numbers agree with cloth::heavy_elastica computed here; --grid and --pins are refused for the
// cantilever with status 2 and nothing written; a strip that is not a whole number of spacings is refused.
#include <doctest/doctest.h>

#ifdef CLOTH_HAVE_CH12_BENDING

#include "analysis/elastica.hpp"
#include "program_runner.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <string>

using namespace cloth_test;

namespace {

std::map<std::string, std::string> key_values(const std::string& text) {
  std::map<std::string, std::string> kv;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find(" = ");
    if (eq != std::string::npos) kv[line.substr(0, eq)] = line.substr(eq + 3);
  }
  return kv;
}

}  // namespace

TEST_CASE("ch12_bending: one strip's run.txt gives overhang, areal density, B and a tip deflection on the elastica") {
  const ProgramFolder folder;
  const ProgramRun run = folder.run("ch12_bending", {"--overhang", "0.05", "--spacing", "0.0025", "--mass", "1.25e-6",
                                                     "--bending-rigidity", "2.5e-5", "--out", "run"});
  REQUIRE(run.status == 0);
  auto kv = key_values(read_text(folder.cwd() / "run" / "run.txt"));
  CHECK(kv["status"] == "ok");
  CHECK(std::stod(kv["overhang"]) == doctest::Approx(0.05).epsilon(1e-12));
  CHECK(std::stod(kv["areal_density"]) == doctest::Approx(0.2).epsilon(1e-9));
  CHECK(std::stod(kv["bending_rigidity"]) == doctest::Approx(2.5e-5).epsilon(1e-12));
  // lambda = rho_A g L^3 / B, and the elastica's tip at that lambda, computed here.
  const double lambda = 0.2 * 9.81 * std::pow(0.05, 3) / 2.5e-5;
  const double exact = cloth::heavy_elastica(lambda).tip_deflection * 0.05;
  CHECK(std::stod(kv["tip_deflection"]) == doctest::Approx(exact).epsilon(0.01));
  CHECK(std::stod(kv["residual_per_weight"]) < 1e-6);
  CHECK(data_lines(folder.cwd() / "run" / "final.dat").size() == 22u * 11u);
}

TEST_CASE("ch12_bending: --grid and --pins are refused for the cantilever, and an overhang between spacings") {
  for (const auto& args : {std::vector<std::string>{"--grid", "5x5"}, std::vector<std::string>{"--pins", "none"},
                           std::vector<std::string>{"--overhang", "0.051"}}) {
    const ProgramFolder folder;
    std::vector<std::string> with_out = args;
    with_out.insert(with_out.end(), {"--out", "run"});
    const ProgramRun run = folder.run("ch12_bending", with_out);
    CHECK(run.status == 2);
    CHECK(run.err.find(args[0]) != std::string::npos);
    CHECK(!fs::exists(folder.cwd() / "run"));
  }
}

#endif
