// ch12_bending end to end: one strip's run.txt holds what a reader needs to check it against an elastica of their
// own, and its numbers agree with cloth::heavy_elastica computed here; --grid and --pins are refused for the
// cantilever with status 2 and nothing written; a strip that is not a whole number of spacings is refused; SIGINT
// during the rest-shape search stops it within a second, keeps the shape reached, and exits 130.
#include <doctest/doctest.h>

#ifdef CLOTH_HAVE_CH12_BENDING

#include "analysis/elastica.hpp"
#include "process.hpp"
#include "program_runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <thread>
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

TEST_CASE("ch12_bending: SIGINT during the rest-shape search ends it within a second, keeps the shape, exits 130") {
  // The flexion strip at L/80: Newton's method takes some sixty iterations on it (the page says why), about 2 s of
  // processor time in Release and many more under the sanitizers, so a signal half a second after the program
  // starts lands inside the search. On a loaded machine the program may get a small share
  // of a processor, and the signal may then come before the search's first iteration (its set-up takes a
  // sixtieth of the search's processor time, but may take more than half a second on the wall clock): that run is
  // interrupted correctly but does not test the search, so the signal is sent again later, in a new run. For the
  // same reason "within a second" is the processor time the program spends after the signal, which is all a
  // program controls: the wall-clock time adds the time it waits for a processor.
  for (const double delay : {0.5, 1.0, 2.0, 4.0}) {
    CAPTURE(delay);
    const ProgramFolder folder;
    const Child child = spawn_chapter("ch12_bending", {"--bending", "flexion", "--overhang", "0.1", "--spacing",
                                                       "0.00125", "--mass", "3.125e-7", "--out", "out"},
                                      folder.cwd());
    REQUIRE(wait_until_exists(child, folder.cwd() / "out"));
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    const double cpu_at_signal = cpu_seconds_so_far(child.pid);
    const auto signalled = std::chrono::steady_clock::now();
    ::kill(child.pid, SIGINT);
    double cpu_at_end = 0;
    const int status = wait_for(child, 60, &cpu_at_end);
    const std::chrono::duration<double> wall_after_signal = std::chrono::steady_clock::now() - signalled;
    const std::string err = read_text(child.err);
    CAPTURE(err);
    CHECK(status == 130);
    REQUIRE(cpu_at_signal >= 0);
    CHECK(cpu_at_end - cpu_at_signal < 1.0);
    // A program that stopped computing but not running (blocked, or sleeping) uses no processor time: the wall
    // clock bounds that, with ten times the second for the waits of a loaded machine.
    CHECK(wall_after_signal.count() < 10.0);
    CHECK(std::count(err.begin(), err.end(), '\n') == 1);
    CHECK(err.find("SIGINT") != std::string::npos);
    auto kv = key_values(read_text(folder.cwd() / "out" / "run.txt"));
    CHECK(kv["status"] == "interrupted");
    CHECK(data_lines(folder.cwd() / "out" / "final.dat").size() == 82u * 21u);
    if (std::stoi(kv["iterations"]) >= 1 || delay == 4.0) {
      CHECK(std::stoi(kv["iterations"]) >= 1);  // the signal came during the search
      break;
    }
  }
}

#endif
