// The K x D sweep's table (see experiments.hpp): per method, per (K, D), how the run ended and what its energy did.
#include "experiments.hpp"

#include "base/format_number.hpp"
#include "program/output.hpp"

#include <cmath>
#include <cstdio>

namespace ch05 {

using namespace cloth;

void write_sweep(const std::vector<Run>& runs, const Options& opt) {
  const double h = opt.run.dt;
  const Scene base_scene(opt.scene);  // K and D aside, every run's scene: which particles are pinned
  OutputFile out(opt.run.out_dir + "/sweep.dat");
  std::fprintf(out.get(),
               "# method_index(0 explicit_euler,1 symplectic_euler,2 rk4,3 implicit_euler) K_index D_index K D "
               "status(0 bounded,1 diverged,2 step failed) t_stopped[s] energy_gain energy_final_change sag_T[m] "
               "t_end[s] newton_per_step outcome\n"
               "# energy_gain = max over s <= t of (E(t)-E(s))/|E(0)| (>= 0; 0 for a method that never adds energy), "
               "energy_final_change = (E(T)-E(0))/|E(0)|; NaN for a stopped run; outcome: bounded, diverged, or the "
               "kind of the failed step\n");
  const double nan = std::nan("");
  for (std::size_t m = 0; m < methods.size(); ++m) {
    for (std::size_t k = 0; k < sweep_K.size(); ++k)
      for (std::size_t d = 0; d < sweep_D.size(); ++d) {
        const Run& run = sweep_run(runs, m, k, d);
        const RunResult& res = run.result;
        const bool stopped = res.status != RunStatus::ok;
        const EnergyMeasures e = energy_measures(res.energy);
        std::fprintf(out.get(), "%zu %zu %zu %g %g %d %.4g %.6g %.6g %.6g %g %.3g \"%s\"\n", m, k, d, run.K, run.D,
                     static_cast<int>(res.status), stop_time(res, h), stopped ? nan : e.gain,
                     stopped ? nan : e.final_change, stopped ? nan : lowest_z(base_scene, res.frames.back().positions),
                     run.t_end, res.newton_iterations_per_step(), outcome(res).c_str());
      }
    std::fprintf(out.get(), "\n\n");
  }
  out.commit();
}

}  // namespace ch05
