// Chapter 8's studies: the controllers on the hard case (steps against the shortest spring), how each pair's
// error estimate answers a jump inside a step, and each pair's estimate against the true local error on the cloth.
#pragma once

#include "program/command_line.hpp"
#include "program/output_spec.hpp"

#include <string>
#include <vector>

namespace ch08 {

/// The files run_experiments writes, relative to `--out`, declared once (program/output_spec.hpp).
cloth::OutputList experiment_outputs();

/// pairs.md: the registry's pairs with the residuals of their order conditions (pair_tables.cpp).
void pairs_table(const std::string& dir, const std::string& command);
/// order_conditions.md and tree_counts.md: the conditions up to order 4, and the number of trees by order.
void conditions_table(const std::string& dir, const std::string& command);
/// jump_response.dat and jump_response.md: each pair's true error and estimate for a jump inside a step.
void jump_response(const cloth::Options& opt, const std::string& command);

/// Runs every study and writes its data and its tables for the page into opt.run.out_dir (see experiments.cpp);
/// `command` is the command line a reader would type, named under each table.
void run_experiments(const cloth::Options& opt, bool quick, const std::string& command);

}  // namespace ch08
