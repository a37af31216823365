// The K x D sweep's table (see experiments.hpp): per method, per (K, D), how the run ended and what its energy did.
#include "experiments.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ch05 {

using namespace cloth;

void write_sweep(const std::vector<Run>& runs, const Options& opt, const Settings& settings,
                 const EnergyReference& reference) {
  const double h = opt.run.dt;
  const Scene base_scene(opt.scene);  // K and D aside, every run's scene: which particles are pinned
  OutputFile out(opt.run.out_dir + "/sweep.dat");
  std::fprintf(out.get(),
               "# method_index(0 explicit_euler,1 symplectic_euler,2 rk4,3 implicit_euler) K_index D_index K D "
               "status(0 bounded,1 diverged,2 step failed) t_stopped[s] energy_gain energy_final_change sag_T[m] "
               "t_end[s] newton_per_step outcome\n"
               "# energy_gain = max over s <= t of (E(t)-E(s))/E_ref (>= 0; 0 for a method that never adds energy), "
               "energy_final_change = (E(T)-E(0))/E_ref, E_ref = %s; NaN for a stopped run; outcome: bounded, "
               "diverged, or the kind of the failed step\n",
               reference.description().c_str());
  const double nan = std::nan("");
  for (std::size_t m = 0; m < methods.size(); ++m) {
    for (std::size_t k = 0; k < sweep_K.size(); ++k)
      for (std::size_t d = 0; d < sweep_D.size(); ++d) {
        const Run& run = sweep_run(runs, m, k, d);
        const RunResult& res = run.result;
        const bool stopped = res.status != RunStatus::ok;
        const EnergyMeasures e = energy_measures(res.energy, reference);
        std::fprintf(out.get(), "%zu %zu %zu %g %g %d %.4g %.6g %.6g %.6g %g %.3g \"%s\"\n", m, k, d, run.K, run.D,
                     static_cast<int>(res.status), stop_time(res, h), stopped ? nan : e.gain,
                     stopped ? nan : e.final_change, stopped ? nan : lowest_z(base_scene, res.frames.back().positions),
                     run.t_end, res.newton_iterations_per_step(), outcome(res).c_str());
      }
    std::fprintf(out.get(), "\n\n");
  }
  out.commit();

  // The page's tables. sweep.md: per method and K, each D's energy gain, or when the run stopped.
  std::vector<std::string> header = {"method", "K [N/m]"};
  for (const double D : sweep_D) header.push_back("D = " + format_number(D));
  MarkdownTable table(header, "lr" + std::string(sweep_D.size(), 'r'));
  for (std::size_t m = 0; m < methods.size(); ++m)
    for (std::size_t k = 0; k < sweep_K.size(); ++k) {
      const Run& first = sweep_run(runs, m, k, 0);
      std::vector<std::string> row = {k == 0 ? find_method(methods[m]).title + " (T = " + format_number(first.t_end) +
                                                   " s)"
                                             : "",
                                      format_number(sweep_K[k])};
      for (std::size_t d = 0; d < sweep_D.size(); ++d) {
        const RunResult& res = sweep_run(runs, m, k, d).result;
        row.push_back(res.status != RunStatus::ok
                          ? outcome(res) + " at " + format_number(stop_time(res, h), 3) + " s"
                          : format_number(energy_measures(res.energy, reference).gain, 3));
      }
      table.add_row(row);
    }
  write_text_fragment(opt.run.out_dir + "/sweep.md",
                      "Energy gain relative to " + reference.description() + ", or when the run stopped:\n\n" +
                          table.markdown() + "\n" + measured_by_line(settings.command));

  // sweep_implicit.md: implicit Euler's undamped runs, whose only loss of energy is the method's.
  const auto implicit = static_cast<std::size_t>(std::find(methods.begin(), methods.end(), "implicit_euler") -
                                                 methods.begin());
  const std::string ratio = reference.launch ? "E(T)/E(0) - 1" : "(E(T) - E(0))/E_ref";
  MarkdownTable lost({"implicit Euler, D = 0", "T [s]", ratio, "lowest z at T [m]"}, "lrrr");
  for (std::size_t k = 0; k < sweep_K.size(); ++k) {
    const Run& run = sweep_run(runs, implicit, k, 0);
    const RunResult& res = run.result;
    const bool stopped = res.status != RunStatus::ok;
    lost.add_row({"K = " + format_number(run.K), format_number(run.t_end),
                  stopped ? outcome(res) : format_number(energy_measures(res.energy, reference).final_change, 3),
                  stopped ? "" : format_number(lowest_z(base_scene, res.frames.back().positions), 3)});
  }
  write_table_fragment(opt.run.out_dir + "/sweep_implicit.md", lost, settings.command);
}

}  // namespace ch05
