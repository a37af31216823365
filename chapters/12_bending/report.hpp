// Chapter 12's set of runs (--report-runs): the cantilever shapes against the elastica, the convergence of the tip
// deflection with the spacing for each bending model, Peirce's approximation, the standard's reading on real
// fabrics, and what bending costs beside the springs.
#pragma once

#include "analysis/cantilever.hpp"
#include "program/output_spec.hpp"

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

/// The files `--report-runs` writes, declared once (program/output_spec.hpp).
cloth::OutputList report_outputs();

/// Writes them into `dir`; `full` refines the convergence study further. `command` is the line under each table.
/// Returns the exit status (0).
int report_runs(const std::string& dir, bool full, const std::string& command);

/// The parts of report_runs in cost.cpp: cost.md (one evaluation of each term) and stable_step.md (the fastest
/// bending mode against the springs' as the spacing halves).
void write_cost(const std::string& dir, const std::string& command);
void write_stable_step(const std::string& dir, const std::string& command);

/// The part in rolled.cpp: rolled.md, a sheet rolled onto a cylinder and released, by XPBD and local/global with
/// bending against implicit Euler at the same step (the gap and the energy each keeps).
void write_rolled(const std::string& dir, const std::string& command);
/// The part in fabrics.cpp: fabrics.md, the standard's 41.5 degree reading on simulated strips of measured fabrics.
void write_fabrics(const std::string& dir, const std::string& command);

/// The strip's centre line at free positions `x`, one "x z" line per row from the clamp line (0, 0) to the tip,
/// along the clamp's direction and up, the rows averaged across the strip, in units of `unit` [m].
void write_centre_line(std::FILE* out, const cloth::Cantilever& strip, const cloth::Vector& x, double unit);

/// The processor time of one call of `work` as a table cell in milliseconds: the median over 5 runs of the mean of
/// 5 calls, and the fastest and slowest runs beside it, "4.073 (3.951-4.310)" (program/timing.hpp).
std::string milliseconds_cell(const std::function<void()>& work);

/// The files `--drape-runs` writes, declared once.
cloth::OutputList drape_outputs();

/// The curtain of Chapter 10 hanging with and without bending (drape.cpp): the hem's shape, the sheet's
/// curvature over time, and what the bending term costs per step. Returns the exit status (0).
int drape_runs(const std::string& dir, const std::string& command);
