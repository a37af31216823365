// Chapter 6: every numeric factorization of the same Newton matrix, timed side by side: the core's block LDL^T and
// LDU (integrators/block_ldu.hpp), Eigen's scalar factorizations and SparseLU, and CHOLMOD's when it is installed.
// The ordering and the symbolic factorization are done once per scene and not timed.
#include "benchmarks.hpp"

#include "integrators/block_ldu.hpp"
#include "program/timing.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#ifdef CLOTH_HAVE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace ch06 {

using namespace cloth;

namespace {

template <class Solver>
Benchmark factorization(const char* name, Solver& solver, const SparseMatrix& A, int runs) {
  solver.analyzePattern(A);  // the ordering and the symbolic factorization: once per scene, not timed
  return timed_benchmark(name, time_runs([&] { solver.factorize(A); }, {.runs = runs, .warmup = 2}));
}

}  // namespace

void time_factorizations(const SparseMatrix& A, int runs, std::vector<Benchmark>& out) {
  // Numeric factorizations of the definite matrix (positive definite, so LL^T works as well as LDL^T). First the
  // core's block factorization (integrators/block_ldu.hpp), symmetric and general, then what Eigen and CHOLMOD
  // offer on the same matrix.
  for (const auto symmetry : {BlockLDU::Symmetry::symmetric, BlockLDU::Symmetry::general}) {
    BlockLDU block;
    block.analyze(A, symmetry);
    const Timing t = time_runs([&] { block.factorize(A); }, {.runs = runs, .warmup = 2, .repeat = 5});
    const bool symmetric = symmetry == BlockLDU::Symmetry::symmetric;
    out.push_back(timed_benchmark(symmetric ? "factorize_block_ldlt_amd" : "factorize_block_ldu_amd", t,
                       block.factorization_flops(), "multiply_adds"));
  }
  {
    Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<int>> s;
    out.push_back(factorization("factorize_eigen_sparselu_colamd", s, A, runs));
  }
  {
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> s;
    out.push_back(factorization("factorize_eigen_ldlt_amd", s, A, runs));
  }
  {
    Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower, Eigen::AMDOrdering<int>> s;
    out.push_back(factorization("factorize_eigen_llt_amd", s, A, runs));
  }
  {
    Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>> s;
    out.push_back(factorization("factorize_eigen_ldlt_natural", s, A, runs));
  }
#ifdef CLOTH_HAVE_CHOLMOD
  // CHOLMOD with one ordering each (its default tries several and keeps the least fill).
  const auto cholmod = [&](auto& s, const char* name, int ordering) {
    s.cholmod().nmethods = 1;
    s.cholmod().method[0].ordering = ordering;
    Benchmark b = factorization(name, s, A, runs);
    b.count = s.cholmod().lnz;
    b.count_name = "factor_nonzeros";
    out.push_back(b);
  };
  {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> s;
    cholmod(s, "factorize_cholmod_supernodal_amd", CHOLMOD_AMD);
  }
  {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> s;
    cholmod(s, "factorize_cholmod_supernodal_metis", CHOLMOD_METIS);
  }
  {
    Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Lower> s;
    cholmod(s, "factorize_cholmod_simplicial_amd", CHOLMOD_AMD);
  }
  {
    Eigen::CholmodSimplicialLDLT<SparseMatrix, Eigen::Lower> s;
    cholmod(s, "factorize_cholmod_simplicial_metis", CHOLMOD_METIS);
  }
#endif

}

}  // namespace ch06
