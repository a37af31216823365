// Chapter 10: real cloth in physical units. The fabric preset and the same square metre at finer grids; the
// explicit methods' stable step, predicted from the lattice and measured; the practitioner's question (what
// each method costs to reach 1 cm and 1 mm at T); and the map of the cheapest method over resolution and
// stiffness, predicted by a cost model. Each study is in a file named for what it studies (real_cloth.hpp).
// --quick is the reduced sweep the plots target runs; without it the full sweep runs. --curtain runs the study
// of cloth that moves instead (curtain.hpp).
#include "curtain.hpp"
#include "real_cloth.hpp"

#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <cstdio>
#include <map>

using namespace cloth;

namespace {

// Every method's error curve on the 20 x 20 fabric at each stiffness, to T = 0.5 s (curves_K*.dat).
std::map<double, ch10::Curves> error_curves(const ch10::Settings& s, const ch10::CurvePlan& plan) {
  std::map<double, ch10::Curves> curves;
  for (double K : ch10::stiffnesses) {
    curves[K] = ch10::error_curves(K, 0.5, ch10::methods, !s.quick && K <= 1e5, plan);
    ch10::print_curves(curves[K]);
    ch10::write_curves(s, curves[K], ch10::curves_tag(K));
  }
  return curves;
}

// What each method costs to reach 1 cm and 1 mm at T = 0.5 s on the stiff fabric (K = 1e5 N/m), and in the full
// sweep at T = 1 s too (practitioner_T*.md, verdict_T*_1cm.md, verdict_T*_1mm.md).
void practitioner_questions(const ch10::Settings& s, const ch10::Curves& at_half_second, const ch10::CurvePlan& plan) {
  std::string summary;
  ch10::practitioner(s, at_half_second, ch10::methods, summary);
  if (!s.quick) {
    const ch10::Curves long_run = ch10::error_curves(1e5, 1.0, ch10::methods, true, plan);
    ch10::print_curves(long_run);
    ch10::practitioner(s, long_run, ch10::methods, summary);
  }
  std::fputs(summary.c_str(), stdout);
  ch10::write_text(s.out, "practitioner_summary.txt", summary);
}

// Every file of either mode, quick or full: the files an earlier run of another mode may have left.
OutputList every_output() { return ch10::real_cloth_outputs(false) + ch10::curtain_outputs(false); }

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch10_real_cloth",
                  "Chapter 10: real cloth in physical units. Fabric preset, refinement, stable steps, the cost of\n"
                  "each method to reach 1 cm and 1 mm, and the map of the cheapest method. The scenes are the\n"
                  "chapter's own; --out says where the tables and data go.");
  cli.use_common({"--out"});
  ch10::Settings s;
  bool curtain = false;
  cli.add_switch("--quick", "a reduced sweep for the plots target (under a minute)", [&] { s.quick = true; });
  cli.add_switch("--curtain", "instead, the study of cloth that moves (the curtain)", [&] { curtain = true; });
  const auto outputs = [&] { return curtain ? ch10::curtain_outputs(s.quick) : ch10::real_cloth_outputs(s.quick); };
  cli.declare_outputs([&](const Options&) { return outputs(); });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    prepare_declared_outputs(opt.run.out_dir, outputs(), every_output());
    s.out = opt.run.out_dir;
    s.command = reader_command(argc, argv);
    if (curtain) {
      ch10::curtain_study(s.quick, s.out, s.command);
      return 0;
    }
    ch10::preset(s);                           // preset.md: the fabric at 20 to 153 particles per side
    ch10::stable_steps(s, ch10::stiffnesses);  // stable_step.md: predicted from the lattice and measured
    const ch10::CurvePlan plan{.budget = s.quick ? 0.08 : 2.0,
                               .max_halvings = s.quick ? 4 : 7,
                               .reference_division = s.quick ? 3.0 : 4.0};
    const std::map<double, ch10::Curves> curves = error_curves(s, plan);
    practitioner_questions(s, curves.at(1e5), plan);
    ch10::refinement(s);                       // refinement.md: the motion converges as the grid is refined
    ch10::cost_map(s, curves, ch10::methods);  // step_cost.md, map_1cm.md, map_1mm.md: the cheapest method
    return 0;
  });
}
