// Chapter 11's studies (--report-runs): the three scenes run for the page's figures and animations, the measured
// tables as fragments, and the cost of self-collision against the forces.
#pragma once

#include "program/command_line.hpp"
#include "program/output_spec.hpp"

namespace ch11 {

/// Adds the studies' own flags (`--quick`) to `cli`.
void add_report_flags(cloth::CommandLine& cli);

/// The files `--report-runs` writes into `--out`, declared once (program/output_spec.hpp).
[[nodiscard]] cloth::OutputList report_outputs();

/// Runs the studies into opt.run.out_dir; the command is recorded in each fragment. Returns the exit status.
int run_report(int argc, char** argv, const cloth::Options& opt);

}  // namespace ch11
