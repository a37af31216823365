// What ch09_implicit_runge_kutta --report-runs writes, declared once: the page's fragments, the figures' data and
// a folder per method of the energy study.
#include "studies.hpp"

#include "program/output_kinds.hpp"

using namespace cloth;

namespace ch09 {

OutputList report_outputs() {
  using namespace cloth::output_kinds;
  OutputList files = {
      {"methods.md", fragment, "the implicit rows of the registry and what their tableaus decide"},
      {"energy_summary.dat", data, "E(T) / E(0), its range and the work of each method, undamped cloth"},
      {"energy_summary.md", fragment, "E(T) / E(0) and its range for each method on the undamped cloth"},
      {"orders.dat", figure, "each method's error at T against the step, (K, D) = (200, 20)"},
      {"orders.md", fragment, "the errors and the observed order of each method"},
      {"stiffness.md", fragment, "the stiff cloth's fastest mode and h lambda over the study's steps"},
      {"work_precision.dat", figure, "time against error, full and modified Newton, (K, D) = (5000, 20)"},
      {"work_precision.md", fragment, "full against modified Newton at the smallest step"}};
  for (const MethodChoice& m : study_methods({})) files = files + run_output_specs("energy_" + m.argument, {"energy.dat"});
  return files;
}

}  // namespace ch09
