// Chapter 7: when is each method stable? Draws every method's stability region from its tableau, the cloth's
// spectrum over it, predicts the largest stable step h_max from the two, and measures h_max by bisection on the
// report scene over a log grid of K, for D = 0 and D = 20.
#include "program/command_line.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "program/output.hpp"
#include "analysis/spectrum.hpp"
#include "integrators/method_registry.hpp"
#include "integrators/simulate.hpp"
#include "analysis/stability_function.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <thread>

using namespace cloth;

namespace {

// One mode of the linearised cloth: its two eigenvalues as a first-order system (a conjugate pair, or two real
// roots of an overdamped mode). Symplectic Euler needs the pair; the other methods act on each eigenvalue.
using Mode = std::array<Complex, 2>;

// [growth_factor]
// The largest factor by which one step of `method` multiplies a mode of the linearised cloth: |R(h lambda)|
// for a Runge-Kutta method, |1/(1 - h lambda)| for implicit Euler, the spectral radius of the 2 x 2 step matrix
// for symplectic Euler. The step is linearly stable when this is at most 1.
double growth_factor(const std::string& method, double h, const std::vector<Mode>& modes) {
  // R(z) of a tableau is a polynomial whose coefficients come from A and b (stability_polynomial).
  std::vector<double> poly;
  const Method& row = find_method(method);
  if (row.family == MethodFamily::explicit_runge_kutta) poly = stability_polynomial(*row.tableau);
  double worst = 0;
  for (const Mode& mode : modes) {
    if (method == "symplectic_euler") {
      worst = std::max(worst, symplectic_euler_amplification(h * mode[0], h * mode[1]));
      continue;
    }
    for (const Complex& lambda : mode) {
      const Complex z = h * lambda;
      Complex R = 0;
      for (auto r = poly.rbegin(); r != poly.rend(); ++r) R = R * z + *r;  // Horner
      if (poly.empty()) R = implicit_euler_stability(z);
      worst = std::max(worst, std::abs(R));
    }
  }
  return worst;
}
// [growth_factor]

// [predicted_hmax]
// Predicted h_max: the largest h with growth factor <= 1 for every mode (strict linear stability), and the
// finite-horizon version: the largest h whose worst mode's energy, which grows like growth^(2 T / h), at most
// doubles over T. A method with no strict limit on the imaginary axis (explicit Euler at D = 0) still has one.
struct Prediction {
  double strict = 0;
  double horizon = 0;
};
Prediction predict(const std::string& method, const std::vector<Mode>& modes, double T, double h_cap) {
  Prediction p;
  p.strict = stability_limit_along([&](double h) { return growth_factor(method, h, modes) <= 1 + 1e-12; }, h_cap, 200,
                                   40);
  p.horizon = stability_limit_along(
      [&](double h) { return 2 * T / h * std::log(growth_factor(method, h, modes)) <= std::log(2.0); }, h_cap, 200, 40);
  return p;
}
// [predicted_hmax]

std::vector<Mode> rest_modes(const std::vector<double>& mu, double K, double D, double m) {
  std::vector<Mode> modes;
  modes.reserve(mu.size());
  for (double u : mu) modes.push_back(mode_eigenvalues(K * u / m, D * u / m));
  return modes;
}

// [bounded_run]
// The measured notion of "stable": simulate() finishes (status ok: no non-finite or runaway state) and the
// energy above the sagged equilibrium never exceeds twice its initial value, E(t) - E_eq <= 2 (E(0) - E_eq)
// for all t <= T. The exact solution has E(t) <= E(0) for every D >= 0, so a run that doubles its excess energy
// is being driven by the integrator, not the physics.
std::string unbounded_reason(const SceneParams& params, const std::string& method, double h, double T,
                             double E_eq) {
  const Scene scene(params);
  ForceField field(scene);
  auto stepper = make_stepper(method, field);
  RunSettings run;
  run.dt = h;
  run.t_end = T;
  run.frames = 1;
  const RunResult result = simulate(*stepper, run, true);
  if (result.status != RunStatus::ok) return result.message;
  const double excess0 = result.energy.front().energy.total() - E_eq;
  for (const EnergySample& s : result.energy)
    if (s.energy.total() - E_eq > 2 * excess0) return "excess energy doubled at t = " + std::to_string(s.t) + " s";
  return {};
}
bool bounded(const SceneParams& params, const std::string& method, double h, double T, double E_eq) {
  return unbounded_reason(params, method, h, T, E_eq).empty();
}
// [bounded_run]

struct Measurement {
  double h = 0;       // largest h found bounded (0: none down to the floor)
  double h_fail = 0;  // smallest h found unbounded (0: none up to the ceiling)
  int runs = 0;
};

// Brackets the boundary by doubling or halving from a guess, then bisects it geometrically `bisections` times.
Measurement measure(const SceneParams& params, const std::string& method, double guess, double T, double E_eq,
                    double h_floor, double h_ceiling, int bisections) {
  Measurement m;
  const auto ok = [&](double h) {
    ++m.runs;
    return bounded(params, method, h, T, E_eq);
  };
  double h = std::clamp(guess, h_floor, h_ceiling);
  double lo = 0, hi = 0;
  if (ok(h)) {
    lo = h;
    while (lo < h_ceiling) {
      const double up = std::min(2 * lo, h_ceiling);
      if (!ok(up)) {
        hi = up;
        break;
      }
      lo = up;
    }
  } else {
    hi = h;
    while (hi > h_floor) {
      const double down = std::max(0.5 * hi, h_floor);
      if (ok(down)) {
        lo = down;
        break;
      }
      hi = down;
    }
  }
  if (lo > 0 && hi > 0)
    for (int k = 0; k < bisections; ++k) {
      const double mid = std::sqrt(lo * hi);
      (ok(mid) ? lo : hi) = mid;
    }
  m.h = lo;
  m.h_fail = hi;
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch07_stability",
                  "Chapter 7: stability regions from the Butcher tableaus, the cloth's spectrum over them, predicted\n"
                  "and measured largest stable steps h_max over K in [10, 1e5] and D in {0, 20}.");
  bool full = false;
  int threads = 2;
  cli.add_switch("--full", "full-resolution sweep: 13 values of K, 7 bisections, every tableau, and the exact "
                           "dense spectrum of the damped sagged cloth (several minutes)",
                 [&] { full = true; });
  cli.add_value("--threads", "N", "worker threads for the sweep (default 2)", [&](const std::string& s) {
    const long long n = parse_integer(s);
    if (n < 1 || n > 64) throw InputError("expected a whole number from 1 to 64");
    threads = static_cast<int>(n);
  });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    prepare_output_dir(opt.run.out_dir);
    const std::string dir = opt.run.out_dir + "/";
    const double T = opt.run.t_end;
    const double h_plot = opt.run.dt;
    const double m = opt.scene.mass;

    // 1. Stability regions: |R(z)| on a grid of the complex plane, one gnuplot index block per method; the
    // figure draws the contour |R| = 1. Symplectic Euler's is drawn for conjugate-pair modes (z, conj z).
    std::vector<std::string> region_methods;
    for (const Method* m : methods_of(MethodFamily::explicit_runge_kutta)) region_methods.push_back(m->name);
    region_methods.emplace_back("implicit_euler");
    region_methods.emplace_back("symplectic_euler");
    {
      std::FILE* out = std::fopen((dir + "regions.dat").c_str(), "w");
      for (const std::string& method : region_methods) {
        std::fprintf(out, "# %s: Re z, Im z, |R(z)|\n", method.c_str());
        for (int i = 0; i <= 260; ++i) {
          const double re = -4.0 + 6.5 * i / 260;
          for (int j = 0; j <= 240; ++j) {
            const double im = -3.5 + 7.0 * j / 240;
            const Complex z(re, im);
            const double g = growth_factor(method, 1.0, {Mode{z, std::conj(z)}});
            // growth_factor takes the larger of |R(z)|, |R(conj z)|: equal for real tableaus.
            std::fprintf(out, "%.6g %.6g %.6g\n", re, im, std::min(g, 10.0));
          }
          std::fprintf(out, "\n");
        }
        std::fprintf(out, "\n");
      }
      std::fclose(out);
    }
    // The region's reach along the two axes, printed and checked against the closed forms in the text.
    std::printf("stability interval of each method along the negative real axis and the imaginary axis:\n");
    std::vector<std::pair<std::string, std::string>> summary;
    for (const std::string& method : region_methods) {
      if (method == "implicit_euler") continue;
      const auto stable_at = [&](Complex z) { return growth_factor(method, 1.0, {Mode{z, std::conj(z)}}) <= 1 + 1e-12; };
      const double real = stability_limit_along([&](double t) { return stable_at({-t, 0}); }, 10);
      const double imag = stability_limit_along([&](double t) { return stable_at({-1e-300, t}); }, 10);
      std::printf("  %-17s real %.4f  imaginary %.4f\n", method.c_str(), real, imag);
      summary.emplace_back(method + "_real_limit", format_number(real));
      summary.emplace_back(method + "_imaginary_limit", format_number(imag));
    }

    // 2. The spectrum at the rest state. There df/dx = -K L and df/dv = -D L with one longitudinal Laplacian L
    // (the damper acts on relative velocities, zero in the uniform initial fall), so one symmetric
    // eigenproblem of L gives the exact spectrum for every (K, D).
    SceneParams unit = opt.scene;
    unit.stiffness = 1.0;
    unit.damping = 0.0;
    const Scene unit_scene(unit);
    ForceField unit_field(unit_scene);
    std::vector<double> mu = stiffness_eigenvalues(unit_field, unit_scene.initial_positions());
    for (double& u : mu) u = std::max(u, 0.0) * m;  // eigenvalues of L itself; rounding below 0 is 0
    std::printf("rest state: %zu eigenvalues of L in [%.3g, %.4f]; %d of them are zero (the flat sheet has no "
                "out-of-plane stiffness)\n",
                mu.size(), mu.front(), mu.back(),
                static_cast<int>(std::count_if(mu.begin(), mu.end(), [&](double u) { return u < 1e-9 * mu.back(); })));
    summary.emplace_back("rest_L_max_eigenvalue", format_number(mu.back()));

    // The report's three (K, D): their spectra times h over the regions.
    const std::vector<std::pair<double, double>> report_cases = {{50, 0}, {200, 0}, {200, 20}};
    std::map<double, Equilibrium> equilibria;  // by K
    const auto equilibrium = [&](double K) -> const Equilibrium& {
      auto it = equilibria.find(K);
      if (it != equilibria.end()) return it->second;
      SceneParams p = opt.scene;
      p.stiffness = K;
      p.damping = 0;
      const Scene s(p);
      ForceField f(s);
      Equilibrium eq = static_equilibrium(f);
      if (!eq.converged)
        std::fprintf(stderr, "ch07_stability: the sagged equilibrium for K = %g did not converge (|f| = %.3g N)\n", K,
                     eq.residual);
      return equilibria.emplace(K, std::move(eq)).first->second;
    };
    for (const auto& [K, D] : report_cases) {
      const std::string tag = "K" + format_number(K) + "_D" + format_number(D);
      std::FILE* out = std::fopen((dir + "spectrum_rest_" + tag + ".dat").c_str(), "w");
      std::fprintf(out, "# h lambda at the rest state, h = %g: Re, Im\n", h_plot);
      for (const Mode& mode : rest_modes(mu, K, D, m))
        for (const Complex& l : mode) std::fprintf(out, "%.8g %.8g\n", h_plot * l.real(), h_plot * l.imag());
      std::fclose(out);

      SceneParams p = opt.scene;
      p.stiffness = K;
      p.damping = D;
      const Scene s(p);
      ForceField f(s);
      const Equilibrium& eq = equilibrium(K);
      const Vector zero = Vector::Zero(eq.x.size());
      std::vector<Complex> lambda;
      std::string how;
      if (D == 0) {
        // Undamped: lambda = +-i omega, omega^2 the eigenvalues of -M^{-1} df/dx (symmetric).
        for (double w2 : stiffness_eigenvalues(f, eq.x))
          for (const Complex& l : mode_eigenvalues(w2, 0)) lambda.push_back(l);
        how = "symmetric";
      } else if (full) {
        lambda = dense_spectrum(f, eq.x, zero);
        how = "dense";
      } else {
        // The damped sagged J is not symmetric and a dense solve of its 2376 x 2376 matrix takes minutes:
        // by default only its dominant eigenvalues, from the power iteration (--full draws all of them).
        const PowerIterationResult pw = largest_eigenvalue_magnitude(f, eq.x, zero);
        lambda = {pw.dominant, std::conj(pw.dominant)};
        how = "power";
      }
      out = std::fopen((dir + "spectrum_sagged_" + tag + ".dat").c_str(), "w");
      std::fprintf(out, "# h lambda at the sagged equilibrium (%s), h = %g: Re, Im\n", how.c_str(), h_plot);
      double largest = 0, most_negative = 0;
      for (const Complex& l : lambda) {
        std::fprintf(out, "%.8g %.8g\n", h_plot * l.real(), h_plot * l.imag());
        largest = std::max(largest, std::abs(l));
        most_negative = std::min(most_negative, l.real());
      }
      std::fclose(out);
      const PowerIterationResult pw = largest_eigenvalue_magnitude(f, eq.x, zero);
      double rest_largest = 0;
      for (const Mode& mode : rest_modes(mu, K, D, m))
        rest_largest = std::max({rest_largest, std::abs(mode[0]), std::abs(mode[1])});
      std::printf("K = %g, D = %g: sag %.3f m; max |lambda| rest %.2f, sagged %.2f (%s), power iteration %.2f in %d "
                  "iterations; h max|lambda| = %.3f\n",
                  K, D, -eq.x.minCoeff(), rest_largest, largest, how.c_str(), pw.magnitude, pw.iterations,
                  h_plot * largest);
      summary.emplace_back("sag_" + tag, format_number(-eq.x.minCoeff()));
      summary.emplace_back("max_abs_lambda_rest_" + tag, format_number(rest_largest));
      summary.emplace_back("max_abs_lambda_sagged_" + tag, format_number(largest));
      summary.emplace_back("power_iteration_sagged_" + tag, format_number(pw.magnitude));
    }

    // 3. Predicted and measured h_max over a log grid of K, for D = 0 and D = 20.
    std::vector<double> stiffnesses;
    const int per_decade = full ? 3 : 1;
    for (int k = 0; k <= 4 * per_decade; ++k) stiffnesses.push_back(std::pow(10.0, 1.0 + static_cast<double>(k) / per_decade));
    const std::vector<double> dampings = {0, 20};
    std::vector<std::string> methods = {"explicit_euler", "symplectic_euler", "heun", "rk4"};
    if (full) methods.insert(methods.end(), {"kutta3", "midpoint", "rule38"});
    const int bisections = full ? 7 : 3;
    const double h_floor = 1e-4, h_ceiling = 0.2;

    struct Job {
      double K, D;
      std::string method;
      double guess, E_eq;
      Measurement result;
      std::string outcome;
    };
    std::vector<Job> jobs;
    // The rest-state prediction costs no simulation, so it is drawn as a curve over 4 points per decade of K.
    {
      std::FILE* out = std::fopen((dir + "predicted_rest.dat").c_str(), "w");
      std::fprintf(out, "# K D method h_strict h_horizon (rest-state spectrum)\n");
      for (double D : dampings)
        for (const std::string& method : methods) {
          for (int k = 0; k <= 16; ++k) {
            const double K = std::pow(10.0, 1.0 + k / 4.0);
            const Prediction r = predict(method, rest_modes(mu, K, D, m), T, 1.0);
            std::fprintf(out, "%g %g %s %.6g %.6g\n", K, D, method.c_str(), r.strict, r.horizon);
          }
          std::fprintf(out, "\n\n");
        }
      std::fclose(out);
    }
    std::FILE* pred = std::fopen((dir + "predicted.dat").c_str(), "w");
    std::fprintf(pred, "# K D method h_strict_rest h_horizon_rest h_strict_sagged (dominant eigenvalue; nan: n/a)\n");
    for (double D : dampings)
      for (double K : stiffnesses) {
        const Equilibrium& eq = equilibrium(K);
        SceneParams p = opt.scene;
        p.stiffness = K;
        p.damping = D;
        const Scene s(p);
        ForceField f(s);
        const Vector zero = Vector::Zero(eq.x.size());
        const Energy e = f.energy(eq.x, zero);
        const double E_eq = e.gravity + e.spring;
        const PowerIterationResult pw = largest_eigenvalue_magnitude(f, eq.x, zero);
        const std::vector<Mode> rest = rest_modes(mu, K, D, m);
        for (const std::string& method : methods) {
          const Prediction r = predict(method, rest, T, 1.0);
          // At the sagged state only the dominant eigenvalue is known; it is a conjugate pair when undamped. A
          // real dominant pair of an overdamped cloth does not tell symplectic Euler its partner: n/a.
          double sagged = NAN;
          const bool pair = std::abs(pw.dominant.imag()) > 1e-9 * std::abs(pw.dominant);
          if (method != "symplectic_euler" || pair)
            sagged = predict(method, {Mode{pw.dominant, std::conj(pw.dominant)}}, T, 1.0).strict;
          std::fprintf(pred, "%g %g %s %.6g %.6g %.6g\n", K, D, method.c_str(), r.strict, r.horizon, sagged);
          jobs.push_back({K, D, method, r.strict > 0 ? r.strict : r.horizon, E_eq, {}, {}});
        }
        // Implicit Euler is A-stable: no predicted limit. It is run once, at the ceiling, where it is cheapest.
        if (K == stiffnesses.front() || K == stiffnesses.back() || std::abs(std::log10(K) - 3) < 1e-9)
          jobs.push_back({K, D, "implicit_euler", h_ceiling, E_eq, {}, {}});
      }
    std::fclose(pred);

    std::atomic<std::size_t> next{0};
    std::mutex print;
    const auto worker = [&] {
      for (std::size_t j; (j = next++) < jobs.size();) {
        Job& job = jobs[j];
        const auto start = std::chrono::steady_clock::now();
        SceneParams p = opt.scene;
        p.stiffness = job.K;
        p.damping = job.D;
        if (job.method == "implicit_euler") {
          // A-stable, so the question is only whether Newton's method converges: probe h = 0.1 (and the
          // report's 0.01 with --full, 10 times dearer).
          for (double h : full ? std::vector<double>{0.01, 0.1} : std::vector<double>{0.1}) {
            const std::string why = unbounded_reason(p, job.method, h, T, job.E_eq);
            ++job.result.runs;
            job.outcome += (job.outcome.empty() ? "" : "; ") + std::string("h = ") + format_number(h) + ": " +
                           (why.empty() ? "bounded" : why);
            if (why.empty()) job.result.h = h;
            else if (job.result.h_fail == 0) job.result.h_fail = h;
          }
        } else {
          job.result = measure(p, job.method, job.guess, T, job.E_eq, h_floor, h_ceiling, bisections);
        }
        const std::lock_guard<std::mutex> lock(print);
        std::printf("  measured K = %-7g D = %-3g %-17s h_max in [%.4g, %.4g] (%d runs, %.2f s)\n", job.K, job.D,
                    job.method.c_str(), job.result.h, job.result.h_fail, job.result.runs,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        if (!job.outcome.empty()) std::printf("    %s\n", job.outcome.c_str());
      }
    };
    std::printf("measuring h_max: %zu bisections over %d threads, floor %g s, ceiling %g s\n", jobs.size(), threads,
                h_floor, h_ceiling);
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
    for (std::thread& t : pool) t.join();

    std::FILE* meas = std::fopen((dir + "measured.dat").c_str(), "w");
    std::fprintf(meas, "# K D method h_bounded h_unbounded runs (geometric mean plotted; 0: not found in [%g, %g])\n",
                 h_floor, h_ceiling);
    for (const Job& job : jobs)
      std::fprintf(meas, "%g %g %s %.6g %.6g %d\n", job.K, job.D, job.method.c_str(), job.result.h, job.result.h_fail,
                   job.result.runs);
    std::fclose(meas);
    std::FILE* implicit = std::fopen((dir + "implicit_euler.txt").c_str(), "w");
    for (const Job& job : jobs)
      if (!job.outcome.empty()) std::fprintf(implicit, "K = %g, D = %g: %s\n", job.K, job.D, job.outcome.c_str());
    std::fclose(implicit);
    summary.emplace_back("sweep_jobs", std::to_string(jobs.size()));
    write_key_values(dir + "summary.txt", summary);
    return 0;
  });
}
