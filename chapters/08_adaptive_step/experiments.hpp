// Chapter 8's studies: the controllers on the hard case (steps against the shortest spring), how each pair's
// error estimate answers a jump inside a step, and each pair's estimate against the true local error on the cloth.
#pragma once

#include "program/command_line.hpp"

#include <string>
#include <vector>

namespace ch08 {

/// The files run_experiments writes, relative to `--out`.
std::vector<std::string> experiment_outputs();

/// Runs every study and writes its data and its tables for the page into opt.run.out_dir (see experiments.cpp);
/// `command` is the command line a reader would type, named under each table.
void run_experiments(const cloth::Options& opt, bool quick, const std::string& command);

}  // namespace ch08
