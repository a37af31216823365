// Chapter 11's studies.
#include "report.hpp"

namespace ch11 {

namespace {
bool quick = false;
}

void add_report_flags(cloth::CommandLine& cli) {
  cli.add_switch("--quick", "with --report-runs: shorter runs and a smaller benchmark", [] { quick = true; });
}

int run_report(const cloth::CommandLine&, int, char**, const cloth::Options&) { return 0; }

}  // namespace ch11
