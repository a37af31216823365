// ch08_adaptive_step end to end: a run writes run.txt with its step statistics and steps.dat with every attempt;
// a tableau without an embedded row is refused; a run stopped by the floor on h exits 3 and keeps its outputs.
#ifdef CLOTH_HAVE_CH08_ADAPTIVE_STEP
#include "program_runner.hpp"

#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

using namespace cloth_test;

namespace {

std::string value_of(const fs::path& run_txt, const std::string& key) {
  std::ifstream in(run_txt);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key + " = ", 0) == 0) return line.substr(key.size() + 3);
  return "";
}

}  // namespace

TEST_CASE("ch08_adaptive_step: run.txt counts the steps of steps.dat, and the last accepted step ends at T") {
  const ProgramFolder folder;
  const ProgramRun run = folder.run("ch08_adaptive_step", {"--grid", "6x6", "--t-end", "0.3", "--tol", "1e-5",
                                                           "--tableau", "bs32", "--frames", "3", "--out", "out"});
  REQUIRE(run.status == 0);
  const fs::path out = folder.cwd() / "out";
  const std::vector<std::string> steps = data_lines(out / "steps.dat");
  long long accepted = 0, rejected = 0;
  double t_end = 0;
  for (const std::string& line : steps) {
    std::istringstream words(line);
    double t = 0, h = 0, err = 0;
    int ok = 0;
    words >> t >> h >> err >> ok;
    (ok ? accepted : rejected) += 1;
    CHECK((ok == 1) == (err <= 1.0));
    if (ok) t_end = t + h;
  }
  CHECK(std::to_string(accepted) == value_of(out / "run.txt", "accepted_steps"));
  CHECK(std::to_string(rejected) == value_of(out / "run.txt", "rejected_steps"));
  CHECK(t_end == doctest::Approx(0.3).epsilon(1e-12));
  CHECK(value_of(out / "run.txt", "first_same_as_last") == "yes");
  CHECK(value_of(out / "run.txt", "status") == "ok");
  CHECK(data_lines(out / "energy.dat").size() == static_cast<std::size_t>(accepted) + 1);
}

TEST_CASE("ch08_adaptive_step: a tolerance no step can meet stops at the floor on h, exit 3, outputs kept") {
  const ProgramFolder folder;
  const ProgramRun run =
      folder.run("ch08_adaptive_step", {"--grid", "5x5", "--t-end", "0.1", "--tol", "1e-300", "--out", "out"});
  CHECK(run.status == 3);
  CHECK(run.err.find("step size too small") != std::string::npos);
  const fs::path out = folder.cwd() / "out";
  CHECK(value_of(out / "run.txt", "failure") == "step_size_too_small");
  CHECK(value_of(out / "run.txt", "status") == "step_failed");
  CHECK(value_of(out / "run.txt", "reason").find("step size too small") != std::string::npos);
  CHECK(value_of(out / "run.txt", "failed_step") == "1");  // no step of the first can meet 1e-300
  CHECK(fs::exists(out / "final.dat"));
  CHECK(fs::exists(out / "steps.dat"));
  CHECK(data_lines(out / "steps.dat").size() > 10);  // every rejected attempt is listed
}

TEST_CASE("ch08_adaptive_step: no --dt among its flags, and a T shorter than the fixed steps' default is a run") {
  const ProgramFolder folder;
  const ProgramRun help = folder.run("ch08_adaptive_step", {"--help"});
  CHECK(help.status == 0);
  CHECK(help.out.find("--t-end") != std::string::npos);
  CHECK(help.out.find("--dt") == std::string::npos);
  CHECK(help.out.find(">= dt") == std::string::npos);
  const ProgramRun run = folder.run("ch08_adaptive_step", {"--grid", "5x5", "--t-end", "0.005", "--out", "out"});
  CHECK(run.status == 0);
  CHECK(value_of(folder.cwd() / "out" / "run.txt", "status") == "ok");
}

TEST_CASE("ch08_adaptive_step: a tableau file without an embedded row is refused, naming what is missing") {
  const ProgramFolder folder;
  const ProgramRun run = folder.run(
      "ch08_adaptive_step",
      {"--tableau", std::string(CLOTH_SOURCE_DIR) + "/chapters/03_runge_kutta/rk4_report.tableau", "--out", "out"});
  CHECK(run.status == 2);
  CHECK(run.err.find("--tableau") != std::string::npos);
  CHECK(run.err.find("no embedded row") != std::string::npos);
  CHECK_FALSE(fs::exists(folder.cwd() / "out"));
}
#endif
