// Chapter 6's micro-benchmarks as the page quotes them (see benchmarks.hpp): the core's costs, every
// factorization of the same matrix, and how much faster the block factorizations are. Nothing here measures.
#include "benchmarks.hpp"
#include "page_text.hpp"

#include "program/fragment.hpp"

#include <map>

namespace ch06 {

using namespace cloth;

namespace {

std::string us(double microseconds) { return whole_or(microseconds, 3); }

// The median with the spread of the runs: "12.3 (12.1-13.0)".
std::string us_with_spread(const Benchmark& b) {
  return us(b.cpu_microseconds) + " (" + us(b.fastest_cpu_microseconds) + "-" + us(b.slowest_cpu_microseconds) + ")";
}

const Benchmark* find(const std::vector<Benchmark>& bench, const std::string& name) {
  for (const Benchmark& b : bench)
    if (b.name == name) return &b;
  return nullptr;
}

std::string count_text(const Benchmark& b) {
  if (b.count_name.empty() || b.count == 0) return "";
  static const std::map<std::string, std::string> units = {{"multiply_adds", "multiply-adds"},
                                                           {"cg_iterations_per_solve", "CG iterations per solve"},
                                                           {"rhs_evaluations", "force evaluations"},
                                                           {"iterations", "CG iterations"}};
  const auto found = units.find(b.count_name);
  std::string unit = found == units.end() ? b.count_name : found->second;
  if (b.count == 1 && unit.back() == 's') unit.pop_back();  // 1 force evaluation
  return (b.count >= 1e5 ? g(b.count, 3) : g(b.count, 6)) + " " + unit;
}

}  // namespace

void write_benchmark_fragments(const std::string& dir, const std::vector<Benchmark>& bench,
                               const std::string& command) {
  MarkdownTable core({"quantity", "thread CPU, median (fastest-slowest) [us]", "count"}, "lrr");
  for (const auto& [name, title] : std::vector<std::pair<std::string, std::string>>{
           {"force_evaluation", "one force evaluation"},
           {"newton_matrix_refill_symmetric", "Newton matrix refill (symmetric)"},
           {"factorize_block_ldlt_amd", "numeric factorization, direct path (block LDL^T)"},
           {"pcg_block_jacobi_warm_1e-8", "one CG solve to 1e-8, block-Jacobi, warm-started"},
           {"newton_iteration_ldlt", "one Newton iteration, direct"},
           {"newton_iteration_cg_warm", "one Newton iteration, warm-started CG"},
           {"rk4_step_tableau", "one RK4 step, tableau engine"},
           {"rk4_step_hand_unrolled", "one RK4 step, hand-unrolled"},
           {"explicit_euler_step", "one explicit Euler step, tableau engine"},
           {"explicit_euler_step_hand_written", "one explicit Euler step, written out"}})
    if (const Benchmark* b = find(bench, name)) core.add_row({title, us_with_spread(*b), count_text(*b)});
  write_table_fragment(dir + "/benchmarks.md", core, command);

  const Benchmark* block = find(bench, "factorize_block_ldlt_amd");
  const Benchmark* ldu = find(bench, "factorize_block_ldu_amd");
  MarkdownTable factorizations({"factorization", "multiply-adds", "nonzeros of L", "thread CPU [us]",
                                "time / block LDL^T"},
                               "lrrrr");
  const Benchmark* best_scalar = nullptr;
  for (const auto& [name, title] : std::vector<std::pair<std::string, std::string>>{
           {"factorize_block_ldlt_amd", "block LDL^T, AMD on the particle graph (cloth::BlockLDU)"},
           {"factorize_block_ldu_amd", "block LDU, the same, general mode"},
           {"factorize_eigen_ldlt_amd", "Eigen SimplicialLDLT, AMD"},
           {"factorize_eigen_llt_amd", "Eigen SimplicialLLT, AMD"},
           {"factorize_eigen_ldlt_natural", "Eigen SimplicialLDLT, no ordering"},
           {"factorize_eigen_sparselu_colamd", "Eigen SparseLU, COLAMD (partial pivoting)"},
           {"factorize_cholmod_supernodal_amd", "CHOLMOD supernodal LL^T, AMD"},
           {"factorize_cholmod_supernodal_metis", "CHOLMOD supernodal LL^T, METIS"},
           {"factorize_cholmod_simplicial_amd", "CHOLMOD simplicial LDL^T, AMD"},
           {"factorize_cholmod_simplicial_metis", "CHOLMOD simplicial LDL^T, METIS"}}) {
    const Benchmark* b = find(bench, name);
    if (!b || !block) continue;
    const bool flops = b->count_name == "multiply_adds", nonzeros = b->count_name == "factor_nonzeros";
    factorizations.add_row({title, flops ? g(b->count, 3) : "", nonzeros ? g(b->count, 6) : "",
                            us(b->cpu_microseconds), g(b->cpu_microseconds / block->cpu_microseconds, 2)});
    const bool scalar = name.find("block") == std::string::npos && name.find("sparselu") == std::string::npos;
    if (scalar && (!best_scalar || b->cpu_microseconds < best_scalar->cpu_microseconds)) best_scalar = b;
  }
  write_table_fragment(dir + "/factorizations.md", factorizations, command);

  const Benchmark* lu = find(bench, "factorize_eigen_sparselu_colamd");
  std::string speedup;
  if (block && ldu && lu && best_scalar)
    speedup = "In this run the block LDL^T factorization is " +
              g(best_scalar->cpu_microseconds / block->cpu_microseconds) +
              " times faster than the fastest scalar factorization of the same matrix and sustains " +
              g(1e-3 * block->count / block->cpu_microseconds) +
              " billion multiply-adds per second; the block LDU for a non-symmetric matrix is " +
              g(lu->cpu_microseconds / ldu->cpu_microseconds) + " times faster than Eigen's SparseLU.\n";
  write_text_fragment(dir + "/factorization_speedup.md", speedup);
}

}  // namespace ch06
