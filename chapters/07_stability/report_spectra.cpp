// The spectra of the report's three (K, D) for Chapter 7: each case's rest and sagged spectrum times h, the
// transcript the page shows, and the reach of the damped modes.
#include "cloth_spectrum.hpp"

#include "base/format_number.hpp"
#include "model/report_cases.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/parallel_runs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace ch07 {

using cloth::ForceField;
using cloth::Scene;
using cloth::SceneParams;
using cloth::Vector;

namespace {

// How many of the largest eigenvalues stand for the whole spectrum where it is too large to compute.
constexpr int extreme_count = 12;

struct SaggedSpectrum {
  std::vector<Complex> lambda;
  std::string how;
};

SaggedSpectrum sagged_spectrum(ForceField& field, const Vector& x, double D, bool dense_damped) {
  const int n = field.dof_count();
  const Vector zero = Vector::Zero(n);
  SaggedSpectrum s;
  if (D == 0) {
    // Undamped: lambda = +-i omega, omega^2 the eigenvalues of -M^{-1} df/dx (symmetric).
    const bool dense = n <= cloth::dense_symmetric_limit;
    const std::vector<double> omega2 =
        dense ? cloth::stiffness_eigenvalues(field, x) : cloth::largest_stiffness_eigenvalues(field, x, extreme_count);
    for (double w2 : omega2)
      for (const Complex& l : cloth::mode_eigenvalues(w2, 0)) s.lambda.push_back(l);
    s.how = dense ? "all, symmetric solver" : "largest, Lanczos";
    return s;
  }
  if (dense_damped && n <= cloth::dense_general_limit) {
    s.lambda = cloth::dense_spectrum(field, x, zero);
    s.how = "all, dense general solver";
    return s;
  }
  if (dense_damped)
    std::printf("  the dense spectrum of the damped cloth is computed for at most %d unknowns (this grid has %d: "
                "O(n^3) time and O(n^2) memory); its %d largest eigenvalues stand for it\n",
                cloth::dense_general_limit, n, extreme_count);
  s.lambda = cloth::largest_eigenvalues(field, x, zero, extreme_count);
  s.how = "largest, Arnoldi";
  return s;
}

void write_points(const std::string& path, const std::string& header, const std::vector<Complex>& lambda, double h) {
  cloth::OutputFile out(path);
  std::fprintf(out.get(), "# %s: Re, Im\n", header.c_str());
  for (const Complex& l : lambda) std::fprintf(out.get(), "%.8g %.8g\n", h * l.real(), h * l.imag());
  out.commit();
}

// One report case's spectra and what the transcript says of them.
struct CaseSpectra {
  double sag = 0, rest_largest = 0, sagged_largest = 0, power = 0;
  double rest_leftmost = 0, sagged_leftmost = 0;  // the most negative Re(lambda)
  std::string line;
};

CaseSpectra case_spectra(const std::string& dir, const SceneParams& scene, const RestSpectrum& rest,
                         const cloth::Equilibrium& eq, const cloth::ReportCase& c, double h, bool dense_damped) {
  const std::string tag = c.name();
  CaseSpectra out;
  std::vector<Complex> at_rest;
  for (const Mode& mode : rest_modes(rest, c.K, c.D, scene.mass))
    for (const Complex& l : mode) {
      at_rest.push_back(l);
      out.rest_largest = std::max(out.rest_largest, std::abs(l));
      out.rest_leftmost = std::min(out.rest_leftmost, l.real());
    }
  write_points(dir + "/spectrum_rest_" + tag + ".dat", "h lambda at the rest state, h = " + cloth::format_number(h),
               at_rest, h);
  const Scene s(cloth::with_K_and_D(scene, c.K, c.D));
  ForceField field(s);
  const SaggedSpectrum sagged = sagged_spectrum(field, eq.x, c.D, dense_damped);
  write_points(dir + "/spectrum_sagged_" + tag + ".dat",
               "h lambda at the sagged equilibrium (" + sagged.how + "), h = " + cloth::format_number(h), sagged.lambda, h);
  for (const Complex& l : sagged.lambda) {
    out.sagged_largest = std::max(out.sagged_largest, std::abs(l));
    out.sagged_leftmost = std::min(out.sagged_leftmost, l.real());
  }
  // The power iteration (analysis/power_iteration.hpp) as an independent check of the largest |lambda|.
  const cloth::PowerIterationResult pw = cloth::largest_eigenvalue_magnitude(field, eq.x, Vector::Zero(eq.x.size()));
  out.sag = -eq.x.minCoeff();
  out.power = pw.magnitude;
  char line[400];
  std::snprintf(line, sizeof line,
                "K = %g, D = %g: sag %.3f m (%d iterations); max |lambda| rest %.2f, sagged %.2f (%s), power "
                "iteration %.2f in %d iterations; h max|lambda| = %.3f\n",
                c.K, c.D, out.sag, eq.iterations, out.rest_largest, out.sagged_largest, sagged.how.c_str(), pw.magnitude,
                pw.iterations, h * out.sagged_largest);
  out.line = wrapped(std::string(line, std::strlen(line) - 1));
  return out;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> report_spectra(const std::string& dir, const SceneParams& scene,
                                                                const RestSpectrum& rest, Equilibria& equilibria,
                                                                double h, bool dense_damped, int threads) {
  char rest_line[300];
  if (rest.exact)
    std::snprintf(rest_line, sizeof rest_line, "rest state: %zu eigenvalues of L in [%.3g, %.4f]; %d of them are zero "
                  "(the flat sheet has no out-of-plane stiffness)\n", rest.mu.size(), rest.mu.front(), rest.mu_max,
                  rest.zero_count);
  else
    std::snprintf(rest_line, sizeof rest_line, "rest state: largest eigenvalue of L %.4f (Lanczos); the grid is too "
                  "large for a dense solve, so the rest spectrum is drawn from %zu samples of [0, %.4f]\n",
                  rest.mu_max, rest.mu.size(), rest.mu_max);
  std::fputs(rest_line, stdout);
  std::vector<std::pair<std::string, std::string>> summary = {{"rest_L_max_eigenvalue", cloth::format_number(rest.mu_max)}};
  std::vector<double> stiffnesses;
  for (const cloth::ReportCase& c : cloth::report_cases) stiffnesses.push_back(c.K);
  equilibria.prepare(stiffnesses, threads);
  // The three cases are independent (each its own ForceField; the equilibria are only read): one per thread.
  std::vector<CaseSpectra> cases(std::size(cloth::report_cases));
  cloth::run_in_parallel(cases.size(), threads, [&](std::size_t k) {
    cloth::throw_if_interrupted();
    const cloth::ReportCase& c = cloth::report_cases[k];
    cases[k] = case_spectra(dir, scene, rest, equilibria.at(c.K), c, h, dense_damped);
  });
  std::string transcript = wrapped(std::string(rest_line, std::strlen(rest_line) - 1));
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const CaseSpectra& r = cases[k];
    const std::string tag = cloth::report_cases[k].name();
    std::fputs(r.line.c_str(), stdout);
    transcript += r.line;
    summary.emplace_back("sag_" + tag, cloth::format_number(r.sag));
    summary.emplace_back("max_abs_lambda_rest_" + tag, cloth::format_number(r.rest_largest));
    summary.emplace_back("max_abs_lambda_sagged_" + tag, cloth::format_number(r.sagged_largest));
    summary.emplace_back("power_iteration_sagged_" + tag, cloth::format_number(r.power));
  }
  cloth::write_text_fragment(dir + "/spectra.txt", transcript);
  // How far out along the negative real axis the damped case's stiffest mode lies, against the regions.
  const auto damped = std::find_if(std::begin(cloth::report_cases), std::end(cloth::report_cases),
                                   [](const cloth::ReportCase& c) { return c.D > 0; });
  const CaseSpectra& d = cases[static_cast<std::size_t>(damped - std::begin(cloth::report_cases))];
  // Whether h lambda lies inside explicit Euler's and RK4's regions, said for the rest and the sagged state
  // separately (the two can differ).
  const auto where = [&](double leftmost) {
    const Complex z(h * leftmost, 0);
    std::string said;
    for (const char* method : {"explicit_euler", "rk4"}) {
      const bool inside = growth_factor(stability_model(method), 1.0, {Mode{z, z}}) <= 1 + 1e-12;
      said += std::string(said.empty() ? "" : " and ") + (inside ? "inside " : "outside ") + method_label(method) + "'s" +
              (said.empty() ? " region" : "");
    }
    return said;
  };
  std::string sags, largest;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const cloth::ReportCase& c = cloth::report_cases[k];
    const bool last = k + 1 == cases.size();
    largest += (k == 0 ? "" : last ? " and " : ", ") + cloth::format_fixed(cases[k].sagged_largest, 1);
    if (c.D == 0) sags += (k == 0 ? "" : " and ") + cloth::format_fixed(cases[k].sag, 1) + " m at K = " + cloth::format_number(c.K);
  }
  const cloth::Grid& grid = scene.grid;
  cloth::write_text_fragment(
      dir + "/grid_summary.md",
      "On this " + std::to_string(grid.M) + " x " + std::to_string(grid.N) + " cloth (" +
          std::to_string(cloth::Scene(scene).dof_count()) + " unknowns) the largest eigenvalue of L is μ_max = " +
          cloth::format_fixed(rest.mu_max, 2) + "; the cloth sags " + sags +
          ", and the largest |λ| at the sagged state are " + largest + " for the report's three cases.\n");
  cloth::write_text_fragment(dir + "/damped_reach.md",
                             "At h = " + cloth::format_number(h) + " s the stiffest modes of the damped cloth (K = " +
                                 cloth::format_number(damped->K) + ", D = " + cloth::format_number(damped->D) +
                                 ") lie at hλ = " + cloth::format_fixed(h * d.rest_leftmost, 2) + " at rest (" +
                                 where(d.rest_leftmost) + ") and at hλ = " +
                                 cloth::format_fixed(h * d.sagged_leftmost, 2) + " at the sagged state (" +
                                 where(d.sagged_leftmost) + ").\n");
  return summary;
}

}  // namespace ch07
