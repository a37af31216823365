// Chapter 6's micro-benchmarks: what one force evaluation, one Newton-matrix refill, one sparse factorization,
// one CG solve, one Newton iteration and one Runge-Kutta step cost on a folded cloth, each the median of
// several timed runs after a warm-up (program/timing.hpp).
#pragma once

#include "model/force_field.hpp"
#include "model/scene.hpp"
#include "program/timing.hpp"

#include <string>
#include <utility>
#include <vector>

namespace ch06 {

/// One timed quantity: a name, the median wall-clock and thread-CPU microseconds with the fastest and slowest CPU
/// run (the spread), and a machine-independent count beside it (CG iterations, nonzeros of the factor, ...; 0 when
/// there is none).
struct Benchmark {
  std::string name;
  double microseconds = 0;
  double cpu_microseconds = 0;
  double fastest_cpu_microseconds = 0, slowest_cpu_microseconds = 0;
  double count = 0;
  std::string count_name;
};

/// A benchmark from its timing: the median wall and CPU times, with the fastest and slowest CPU run, in microseconds.
inline Benchmark timed_benchmark(std::string name, const cloth::Timing& t, double count = 0, std::string unit = "") {
  return {std::move(name), 1e6 * t.median_wall, 1e6 * t.median_cpu, 1e6 * t.fastest_cpu, 1e6 * t.slowest_cpu, count,
          std::move(unit)};
}

/// Every numeric factorization of the definite Newton matrix A, side by side (factorizations.cpp).
void time_factorizations(const cloth::SparseMatrix& A, int runs, std::vector<Benchmark>& out);

/// Runs every micro-benchmark on `params` (the report scene at 20 x 20 by default), on the cloth's states from
/// t = 0.5 s on, where it is folded. `runs` timed runs per quantity.
std::vector<Benchmark> run_benchmarks(const cloth::SceneParams& params, int runs);

/// benchmarks.md (the core's micro-benchmarks), factorizations.md (every factorization of the same matrix) and
/// factorization_speedup.md (a sentence: how much faster the block factorizations are): benchmark_fragments.cpp.
void write_benchmark_fragments(const std::string& dir, const std::vector<Benchmark>& bench, const std::string& command);

}  // namespace ch06
