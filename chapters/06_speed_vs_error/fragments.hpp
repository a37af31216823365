// Chapter 6's page quotes what the program measured when the book was built: these functions turn the results of
// the benchmarks and studies into the tables and sentences the page includes (program/fragment.hpp). Each writes
// one file into the output folder; main.cpp lists them among its outputs.
#pragma once

#include "benchmarks.hpp"
#include "studies.hpp"

#include <string>
#include <vector>

namespace ch06 {

/// The fragments the micro-benchmarks write, `--bench-only` included.
std::vector<std::string> benchmark_fragment_names();
/// The fragments the studies write.
std::vector<std::string> study_fragment_names();

/// benchmarks.md (the core's micro-benchmarks), factorizations.md (every factorization of the same matrix) and
/// factorization_speedup.md (a sentence: how much faster the block factorizations are).
void write_benchmark_fragments(const std::string& dir, const std::vector<Benchmark>& bench, const std::string& command);

/// Everything the studies measured, as the page quotes it.
struct StudyResults {
  NearZero near_zero;
  std::vector<LocalError> local_errors;
  std::vector<ObservedOrder> orders;
  std::vector<Sensitivity> sensitivity;
  std::vector<ReferenceCheck> references;
  std::vector<WorkPoint> work;
  std::vector<ScalingPoint> scaling;
};

/// near_zero.md, local_error.md, jumps.md, observed_orders.md, sensitivity.md, reference.md, fastest.md,
/// fastest_summary.md, dropped.md, effective_orders.md, implicit_variants.md, stiff_pick.md, scaling.md.
void write_study_fragments(const std::string& dir, const StudyResults& r, const std::vector<Config>& configs,
                           const std::string& command);

}  // namespace ch06
