// Chapter 10's map, measured: for the curtain and the swinging curtain at 20 x 20 to 160 x 160 particles on the same
// square metre and stiffness from 1e3 to 1e6 N/m, the fastest program reaching each accuracy level over every frame,
// the book's methods beside Boost.Odeint, SUNDIALS and a plain XPBD program. Each part of the map is measured by
// name (--part), the full sweep part by part (--all), and the tables are written from the parts' files (--tables).
#include "map_sweep.hpp"

#include "base/input_error.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace cloth;

namespace {

// The parts a run measures: --quick's one small part, every part with --all, else those named by --part.
std::vector<ch10::MapPart> parts_measured(const std::vector<ch10::MapPart>& named, bool all, bool quick) {
  if (quick) return {{"curtain", 12, 1e4}};
  return all ? ch10::full_map() : named;
}

// The files a run writes: each part's runs, and with the tables the map of each scene. The page includes the
// quick run's curtain table; the full map's tables it includes from the committed data/map_full.
OutputList map_outputs(const std::vector<ch10::MapPart>& parts, bool tables, bool quick) {
  OutputList files;
  for (const ch10::MapPart& p : parts)
    files.push_back({"map_" + p.name() + ".dat", OutputKind::data, "every run of the part: setting, CPU time, error"});
  if (tables)
    files = files + OutputList{{"map_curtain.md", quick ? OutputKind::fragment : OutputKind::data,
                                "the fastest program to each level on the curtain, per grid and K"},
                               {"map_swing.md", OutputKind::data,
                                "the fastest program to each level on the swinging curtain, per grid and K"},
                               {"map_validation.md", OutputKind::data,
                                "each measured cell against the cost model's prediction from the grids below"}};
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch10_map",
                  "Chapter 10's map: the curtain and the swinging curtain at n x n particles on one square metre and\n"
                  "stiffness K, every program as a ladder of finer settings against a Dormand-Prince reference; the\n"
                  "fastest run reaching plausible motion (5 % of the motion), 1 cm and 1 mm over every frame.");
  cli.use_common({"--out"});
  std::vector<ch10::MapPart> parts;
  ch10::SweepPlan plan;
  bool all = false, quick = false, tables = false;
  cli.add_value("--part", "PART[,PART]...", "measure these parts of the map, each SCENE_N_1eE (curtain|swing, n, K = 1eE)",
                [&](const std::string& s) {
                  std::size_t start = 0;
                  for (std::size_t comma = s.find(','); ; start = comma + 1, comma = s.find(',', start)) {
                    parts.push_back(ch10::parse_map_part(s.substr(start, comma - start)));
                    if (comma == std::string::npos) break;
                  }
                });
  cli.add_switch("--all", "measure every part, cheapest first, skipping a part whose reference alone is predicted "
                          "over the run budget", [&] { all = true; });
  cli.add_switch("--quick", "one small part with a one-second budget per run (for the plots target)",
                 [&] { quick = true; });
  cli.add_switch("--tables", "write the map's tables from the parts measured in --out", [&] { tables = true; });
  cli.add_value("--budget", "SECONDS", "no run predicted longer than this is started (default 600)",
                [&](const std::string& s) { plan.run_budget = parse_number(s); });
  cli.declare_outputs([&](const Options&) {
    return map_outputs(parts_measured(parts, all, quick), tables || quick, quick);
  });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const std::string dir = opt.run.out_dir;
    const std::string command = reader_command(argc, argv);
    if (parts.empty() && !all && !quick && !tables)
      throw InputError("nothing to measure: expected --part, --all, --quick or --tables");
    if (quick && (all || !parts.empty())) throw InputError("--quick measures its own part: expected no --part or --all");
    parts = parts_measured(parts, all, quick);
    if (quick) {
      plan.run_budget = 1;
      plan.reference_tolerance = 1e-8;
      plan.max_runs_per_series = 4;
      plan.prune_factor = 3;
      tables = true;
    }
    prepare_declared_outputs(dir, map_outputs(parts, tables, quick));
    // The reference's cost model: Dormand-Prince's step is bounded by its stability on the fastest lattice mode,
    // omega ~ n sqrt(K), so its time grows like particles x steps ~ n^3 sqrt(K) (fitted on the parts measured).
    double reference_rate = 0;
    for (const ch10::MapPart& p : parts) {
      const double size = std::pow(p.n, 3) * std::sqrt(p.K);
      if (all && reference_rate * size > plan.run_budget) {
        std::printf("%s: reference predicted at %.0f s, over the budget: not measured\n", p.name().c_str(),
                    reference_rate * size);
        continue;
      }
      reference_rate = std::max(reference_rate, ch10::measure_part(p, plan, dir, command) / size);
    }
    if (tables) ch10::write_map_tables(dir, command, !quick);
    return 0;
  });
}
