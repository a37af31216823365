// Chapter 10's map: the cost model that predicts a part not measured from the two largest measured grids below it
// (chapters/10_real_cloth/map_predict.cpp), read from the tables `ch10_map --tables` writes for a made-up pair of
// parts whose growth per doubling is known.
#include "map_part_file.hpp"
#include "program_runner.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

#ifdef CLOTH_HAVE_CH10_MAP
namespace {

std::string printed(const char* fmt, double x) {
  char text[64];
  std::snprintf(text, sizeof text, fmt, x);
  return text;
}

}  // namespace

TEST_CASE("the map's cost model: a measured growth per doubling predicts the next grid, a floor bounds it, and a "
          "cell not reached on the finer grid is not predicted") {
  cloth_test::ScratchDir dir;
  // The curtain at K = 1e5 on 20 x 20 (to 0.6 s) and 40 x 40 (to 0.4 s). Per simulated second rk4 grows from
  // 1/0.6 to 12/0.4 s/s, 18 times per doubling (p = log2 18), so 80 x 80 takes 12 x 18 = 216 s to the 0.4 s of
  // 40 x 40. Implicit Euler grows 0.8/0.4 over 0.5/0.6, 2.4 times (p = 1.26), below the floor p = 2 of a method
  // whose every step touches all n^2 particles: 0.8 x 4 = 3.2 s. XPBD reaches 1 mm on 20 x 20 only; the peer
  // reaches 1 cm on both (p = log2 12) and 1 mm on neither.
  cloth_test::write_map_part(dir.path() / "map_curtain_20_1e5.dat", "curtain_20_1e5", 0.6, 1.5,
             "book rk4 book \"h = 1/2760\" 1656 1 5e-4 5e-04 ok\n"
             "book implicit_euler book \"h = 1/60\" 36 0.5 5e-3 5e-03 ok\n"
             "book xpbd book \"xpbd/16sub, h = 1/60\" 36 1 5e-4 5e-04 ok\n"
             "peer odeint_rk4 plain \"h = 1/2760\" 1656 2 5e-3 5e-03 ok\n");
  cloth_test::write_map_part(dir.path() / "map_curtain_40_1e5.dat", "curtain_40_1e5", 0.4, 1.5,
             "book rk4 book \"h = 1/5520\" 2208 12 5e-4 5e-04 ok\n"
             "book implicit_euler book \"h = 1/60\" 24 0.8 5e-3 5e-03 ok\n"
             "book xpbd book \"xpbd/16sub, h = 1/60\" 24 4 5e-3 5e-03 ok\n"
             "peer odeint_rk4 plain \"h = 1/5520\" 2208 16 5e-3 5e-03 ok\n");
  const cloth_test::ProgramRun run = cloth_test::run_chapter("ch10_map", {"--tables", "--out", "."}, dir.path());
  REQUIRE(run.status == 0);
  const std::string curtain = cloth_test::read_text(dir.path() / "map_curtain.md");
  const double rk4 = 12 * std::pow(2.0, std::log2((12 / 0.4) / (1 / 0.6))), peer = 16 * ((16 / 0.4) / (2 / 0.6));
  CHECK(rk4 == doctest::Approx(216).epsilon(1e-12));
  const std::string row = "| 80 x 80 | 10⁵ | not measured (1.5 m to 0.4 s at 40 x 40) | ";
  CHECK(curtain.find(row + "1 mm | *predicted* rk4: " + printed("%.2g", rk4) + " s (n^4.2) | not reached | " +
                     "not predicted: not reached on 40 x 40 |") != std::string::npos);
  CHECK(curtain.find(row + "1 cm | *predicted* implicit_euler: " + printed("%.2g", 0.8 * 4) + " s (n^2) | " +
                     "*predicted* odeint_rk4 (plain forces): " + printed("%.2g", peer) + " s (n^3.6) | " +
                     "*predicted* implicit_euler: 3.2 s (n^2) |") != std::string::npos);
  // The check of the rule on the measured 40 x 40 part: from the one grid below it, the a-priori p = 3, at its own
  // horizon: 1 s x 8 x 0.4 / 0.6 = 5.33 s against the 12 s measured.
  const std::string check = cloth_test::read_text(dir.path() / "map_validation.md");
  CHECK(check.find(std::string("| curtain | 40 x 40 | 10⁵ | 1 mm | the book | rk4: 5.3 s (n^3) | rk4: 12 s | ") +
                   printed("%#.3g", 12 / (8 * 0.4 / 0.6)) + " |") != std::string::npos);
  // Three significant figures, not two decimals: 0.8 s against 0.5 x 8 x 0.4 / 0.6 = 2.67 s prints 0.300.
  CHECK(check.find("| curtain | 40 x 40 | 10⁵ | 1 cm | implicit or position-based | implicit_euler: 2.7 s (n^3) | "
                   "implicit_euler: 0.8 s | 0.300 |") != std::string::npos);
  // A measured part keeps its measured cells.
  CHECK(curtain.find("| 40 x 40 | 10⁵ | 1.5 m to 0.4 s | 1 mm | rk4, h = 1/5520: 12 s |") != std::string::npos);
}
#endif
