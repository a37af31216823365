// Chapter 12's set of runs (--report-runs): the cantilever shapes against the elastica, the convergence of the tip
// deflection with the spacing for each bending model, Peirce's approximation, the standard's reading on real
// fabrics, and what bending costs beside the springs.
#pragma once

#include <string>
#include <vector>

/// The files `--report-runs` writes, for prepare_outputs.
std::vector<std::string> report_outputs();

/// Writes them into `dir`; `full` refines the convergence study further. `command` is the line under each table.
/// Returns the exit status (0).
int report_runs(const std::string& dir, bool full, const std::string& command);
