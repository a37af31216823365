// Chapter 10's study of cloth that moves: the curtain (the fabric hung by one edge, released flat), the curtain
// given a swing, and the four-corner sheet, each against a Dormand-Prince reference recorded at every frame, with
// every method of the chapter measured by the measures of analysis/trajectory_measures.hpp beside the size of the
// motion.
#pragma once

#include "program/output_spec.hpp"

#include <string>

namespace ch10 {

/// The files the curtain study writes into its output folder (fragments, data, the figures' data), `quick` in the
/// quick run.
cloth::OutputList curtain_outputs(bool quick);

/// Runs the study and writes its files to `out`; `command` is what a reader types to measure the tables again.
void curtain_study(bool quick, const std::string& out, const std::string& command);

}  // namespace ch10
