// Chapter 11's studies (--report-runs), in the order of the page.
#include "report.hpp"

#include "studies.hpp"

#include "base/input_error.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"
#include "program/output_kinds.hpp"
#include "program/output_spec.hpp"

namespace ch11 {

namespace {
bool quick = false;
}

void add_report_flags(cloth::CommandLine& cli) {
  cli.add_switch("--quick",
                 "with --report-runs: the fold and its skins on a 30 x 100 strip to 1 s instead of 30 x 200 to 1.5 s "
                 "(the plots' version)",
                 [] { quick = true; });
}

cloth::OutputList report_outputs() {
  using cloth::OutputKind;
  using namespace cloth::output_kinds;
  return {{"incline.md", fragment, "the incline against g (sin - mu_k cos), below and beyond the cone"},
          {"incline.dat", figure, "the mean displacement down the slope against the closed form"},
          {"incline_frames.dat", figure, "frames of the sheet sliding down the 30-degree incline"},
          {"incline_geometry.txt", figure, "the incline the animation draws, in run.txt's lines"},
          {"sphere.md", fragment, "every family on the small drape: deepest penetration, kinetic energy at T"},
          {"sphere_energy.dat", figure, "kinetic energy over its peak, one block per method"},
          {"sphere_frames.dat", figure, "frames of the 20 x 20 sheet draping over the sphere"},
          {"sphere_geometry.txt", figure, "the sphere and the ground the animation and the drape's still draw"},
          {"sdirk2_rest.md", fragment, "SDIRK2 on the drape at three steps: energy left, the fastest velocity and its motion"},
          {"sdirk2_stages.md", fragment, "SDIRK2 at 10 ms, corrected after the step or filtered in each stage"},
          {"sphere_rest.md", fragment, "the scene's drape at 10 s: kinetic energy over its peak, deepest penetration"},
          {"fold.md", fragment, "the folding strip: closest pair, passes, hash builds, cost against the forces"},
          {"fold_frames.dat", figure, "frames of the strip folding"},
          {"fold_geometry.txt", figure, "the ground the animation draws, in run.txt's lines"},
          {"skin.md", fragment, "the fold with each skin of the kept list: builds, candidates, cost"},
          {"hash.md", fragment, "a step's self-collision against a force evaluation, 30 x 100 to 30 x 800"},
          {"adaptive_skin.md", fragment, "the fold's candidates refreshed particle by particle: queries and distances"},
          {"patch_hierarchy.md", fragment, "the distances a refitted hierarchy of mesh patches tests per step on the fold"},
          {"edge_crossing.md", fragment, "whether two crossing edges pass through each other, by spacing"}};
}

int run_report(int argc, char** argv, const cloth::Options& opt) {
  // The studies fix their own scenes and methods: a flag that would change them is refused, not ignored.
  for (const std::string& flag : opt.given)
    if (flag != "--report-runs" && flag != "--quick" && flag != "--out")
      throw cloth::InputError(flag + ": --report-runs runs the chapter's own scenes; it takes --quick and --out only");
  cloth::prepare_declared_outputs(opt.run.out_dir, report_outputs(), cloth::run_output_specs());
  const Study study{opt.run.out_dir, cloth::reader_command(argc, argv), quick};
  incline_study(study);
  sphere_study(study);
  sdirk2_rest_study(study);
  sdirk2_stages_study(study);
  fold_study(study);
  skin_study(study);
  hash_benchmark(study);
  adaptive_skin_study(study);
  patch_hierarchy_study(study);
  edge_crossing_study(study);
  return 0;
}

}  // namespace ch11
