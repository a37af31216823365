// Chapter 11's studies (--report-runs), in the order of the page.
#include "report.hpp"

#include "studies.hpp"

#include "base/input_error.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

namespace ch11 {

namespace {
bool quick = false;
}

void add_report_flags(cloth::CommandLine& cli) {
  cli.add_switch("--quick", "with --report-runs: shorter runs and a smaller benchmark (the plots' version)",
                 [] { quick = true; });
}

int run_report(int argc, char** argv, const cloth::Options& opt) {
  // The studies fix their own scenes and methods: a flag that would change them is refused, not ignored.
  for (const std::string& flag : opt.given)
    if (flag != "--report-runs" && flag != "--quick" && flag != "--out")
      throw cloth::InputError(flag + ": --report-runs runs the chapter's own scenes; it takes --quick and --out only");
  cloth::prepare_outputs(opt.run.out_dir, {"incline.md", "incline.dat", "incline_frames.dat", "sphere.md",
                                           "sphere_energy.dat", "sphere_frames.dat", "sphere_rest.md", "fold.md", "fold_frames.dat",
                                           "hash.md", "edge_crossing.md"});
  const Study study{opt.run.out_dir, cloth::reader_command(argc, argv), quick};
  incline_study(study);
  sphere_study(study);
  fold_study(study);
  hash_benchmark(study);
  edge_crossing_study(study);
  return 0;
}

}  // namespace ch11
