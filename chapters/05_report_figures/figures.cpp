// The data of the report's figures (see experiments.hpp): per run its energy and sag against time and its
// strain-coloured mesh every T / 20; the summary table; and the small tables that tell plot.gp which block of
// each mesh file to draw and what its labels say.
#include "experiments.hpp"
#include "strain_mesh.hpp"

#include "base/format_number.hpp"
#include "integrators/method_registry.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ch05 {

using namespace cloth;

namespace {

bool diverged(const RunResult& r) { return r.status != RunStatus::ok; }

// "diverged at t = 0.9 s", "newton not converged at t = 1.41 s": how a run ended and when.
std::string ended(const RunResult& r, double h) { return outcome(r) + " at t = " + format_number(stop_time(r, h), 3) + " s"; }

// The method's title from the registry ("explicit Euler").
std::string title_of(const std::string& method) { return find_method(method).title; }

// A string column of a gnuplot data file: quoted, so that it may hold spaces.
std::string quoted(const std::string& text) { return '"' + text + '"'; }

// Energy and sag against time, one line per step.
void write_series(const std::string& path, const Run& run, const Scene& scene, const EnergyReference& reference) {
  const RunResult& res = run.result;
  OutputFile series(path);
  std::fprintf(series.get(), "# %s K=%g D=%g: t[s] E_total[J] E/E_ref lowest_z[m]  (E_ref = %s)\n",
               run.method.c_str(), run.K, run.D, reference.description().c_str());
  for (std::size_t k = 0; k < res.energy.size() && k < res.frames.size(); ++k)
    std::fprintf(series.get(), "%.6g %.10g %.10g %.8g\n", res.energy[k].t, res.energy[k].energy.total(),
                 res.energy[k].energy.total() / reference.joules, lowest_z(scene, res.frames[k].positions));
  series.commit();
}

// How many meshes a run's mesh file holds, and the box around all of them (the animation's fixed box).
struct MeshBox {
  int blocks = 0;
  Eigen::Vector3d lo = Eigen::Vector3d::Zero(), hi = Eigen::Vector3d::Zero();
};

// The strain-coloured structural mesh every `stride` frames (T / movie_frames), then the last sane state `last`
// if the run stopped.
MeshBox write_mesh(const std::string& path, const RunResult& res, const Scene& scene, const Vector& last,
                   std::size_t stride) {
  OutputFile mesh(path);
  MeshBox box;
  const auto draw = [&](const Vector& positions, double t) {
    write_strain_block(mesh.get(), scene, positions, t, SpringFamily::structural);
    for (Eigen::Index k = 0; k < positions.size(); k += 3) {
      box.lo = box.lo.cwiseMin(positions.segment<3>(k));
      box.hi = box.hi.cwiseMax(positions.segment<3>(k));
    }
    ++box.blocks;
  };
  for (std::size_t k = 0; k < res.frames.size(); k += stride) draw(res.frames[k].positions, res.frames[k].t);
  if (diverged(res)) draw(last, res.t);
  mesh.commit();
  return box;
}

// runs.dat's row of run number `number`: its name, title, how it ended, its mesh count, and its box.
void write_run_row(std::FILE* table, std::size_t number, const Run& run, const std::string& ending, const MeshBox& box) {
  std::fprintf(table, "%zu %s %s %s %d %s", number, run_name(run).c_str(), quoted(find_method(run.method).title).c_str(),
               quoted(ending).c_str(), box.blocks, format_number(run.result.t, 4).c_str());
  for (int a = 0; a < 3; ++a)
    std::fprintf(table, " %s %s", format_number(box.lo[a], 4).c_str(), format_number(box.hi[a], 4).c_str());
  std::fprintf(table, "\n");
}

// instants.dat's rows of run number `number`: the mesh block of each sheet's instant, or the last one for a run
// that stopped before it.
void write_instants(std::FILE* instants, std::size_t number, const RunResult& res, int blocks, std::size_t stride,
                    double h, double T) {
  for (std::size_t i = 0; i < sheet_fractions.size(); ++i) {
    const double frac = sheet_fractions[i];
    const int wanted = static_cast<int>(std::lround(frac * movie_frames));
    const bool have = static_cast<std::size_t>(wanted) * stride < res.frames.size();
    const std::string at = "t = " + format_number(frac * T) + " s";
    std::fprintf(instants, "%zu %zu %d %s\n", number, i + 1, have ? wanted : blocks - 1,
                 quoted(have ? at : at + ": " + ended(res, h) + ", last frame t = " + format_number(res.t, 3) + " s")
                     .c_str());
  }
}

// Per case: a log energy axis when some method's energy grew tenfold, and a sag range that shows the bounded
// runs (exploding ones leave it, which the plot says).
void write_cases(const std::string& path, const std::vector<Run>& runs, const SceneParams& scene_params,
                 const EnergyReference& reference) {
  const std::size_t cases = report_cases.size();
  OutputFile case_table(path);
  std::fprintf(case_table.get(), "# case K D log_energy_axis sag_low[m]\n");
  const Scene base_scene(scene_params);  // K and D aside, every run's scene: which particles are pinned
  for (std::size_t c = 0; c < cases; ++c) {
    double worst_gain = 0, low = 0;
    for (std::size_t m = 0; m < methods.size(); ++m) {
      const RunResult& res = runs[m * cases + c].result;
      const double gain = energy_measures(res.energy, reference).gain;
      worst_gain = std::max(worst_gain, gain);
      if (!diverged(res) && gain < 1.0)
        for (const Frame& f : res.frames) low = std::min(low, lowest_z(base_scene, f.positions));
    }
    std::fprintf(case_table.get(), "%zu %s %s %d %s\n", c + 1, format_number(report_cases[c].K).c_str(),
                 format_number(report_cases[c].D).c_str(), worst_gain > 9.0 ? 1 : 0, format_number(1.15 * low, 3).c_str());
  }
  case_table.commit();
}

// The report's Figures 2-7: which run each shows, and its caption.
void write_figures(const std::string& path) {
  const std::size_t cases = report_cases.size();
  OutputFile figures(path);
  std::fprintf(figures.get(), "# figure run caption  (the report's Figures 2-7)\n");
  for (const ReportFigure& rf : report_figures) {
    const auto m = static_cast<std::size_t>(std::find(methods.begin(), methods.end(), rf.method) - methods.begin());
    const ReportCase& c = report_cases[static_cast<std::size_t>(rf.report_case)];
    std::fprintf(figures.get(), "%d %zu %s\n", rf.number, m * cases + static_cast<std::size_t>(rf.report_case) + 1,
                 quoted("Figure " + std::to_string(rf.number) + ": " + rf.caption_method + " with K=" +
                        format_number(c.K) + " and D=" + format_number(c.D))
                     .c_str());
  }
  figures.commit();
}

// What plot.gp's loops need: the step, the horizons, and the numbers of methods, cases and instants.
void write_parameters(const std::string& path, const RunSettings& run, const Settings& settings,
                      const EnergyReference& reference) {
  OutputFile parameters(path);
  std::fprintf(parameters.get(),
               "# h[s] t_end[s] sweep_t_end_implicit[s] methods cases instants E_ref[J] E_ref_is_E0 (1: E_ref = E(0), "
               "the launch's kinetic energy; 0: W L, the cloth starts at rest)\n%g %g %g %zu %zu %zu %.6g %d\n",
               run.dt, run.t_end, settings.sweep_t_end_implicit, methods.size(), report_cases.size(),
               sheet_fractions.size(), reference.joules, reference.launch ? 1 : 0);
  parameters.commit();
}

}  // namespace

void write_figure_data(const std::vector<Run>& runs, const Options& opt, const Settings& settings,
                       const EnergyReference& reference) {
  const double h = opt.run.dt, T = opt.run.t_end;
  const std::string dir = opt.run.out_dir + "/";
  const std::size_t cases = report_cases.size(), figure_runs = methods.size() * cases;
  const auto stride = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(T / h * (1 - 1e-12))) / movie_frames);

  OutputFile summary(dir + "summary.dat");
  std::fprintf(summary.get(),
               "# method K D status t_stopped[s] energy_gain energy_final_change sag_T[m] min_z_run[m] "
               "max_strain_T newton_per_step wall[s]\n"
               "# status: ok, diverged, or the kind of the step that failed; t_stopped: NaN for a run that finished; "
               "energy_gain = max over s <= t of (E(t)-E(s))/E_ref, energy_final_change = (E(T)-E(0))/E_ref, over "
               "the sane part of a stopped run, E_ref = %s; sag_T = lowest z of the last sane state\n",
               reference.description().c_str());
  OutputFile table(dir + "runs.dat");
  std::fprintf(table.get(), "# run name method status mesh_blocks t_reached[s] xmin xmax ymin ymax zmin zmax  (run = "
                            "method * %zu + case + 1; the box is the animation's)\n", cases);
  OutputFile instants(dir + "instants.dat");
  std::fprintf(instants.get(), "# run instant mesh_block label  (the sheets' instants: t = %s T)\n", [] {
    std::string list;
    for (const double f : sheet_fractions) list += (list.empty() ? "" : ", ") + format_number(f);
    return list;
  }().c_str());
  // The page's table (summary.md): the same rows, as a reader reads them.
  const std::string ratio = reference.launch ? "E(0)" : "E_ref";
  MarkdownTable page_table({"method", "K", "D", "outcome", "energy gain", "stretch of the largest rise [s]",
                            reference.launch ? "E(T)/E(0) - 1" : "(E(T) - E(0))/E_ref", "lowest z over the run [m]"},
                           "lrrlrrrr");
  std::printf("\nEnergies relative to %s\n", reference.description().c_str());
  std::printf("%-17s %5s %4s  %-9s %8s %11s %11s %8s %8s %10s\n", "method", "K", "D", "status", "t_stop", "E gain",
              "E(T)-E(0)", "sag_T", "min z", "max strain");
  for (std::size_t r = 0; r < figure_runs; ++r) {
    const Run& run = runs[r];
    const RunResult& res = run.result;
    const std::string name = run_name(run);
    const Scene scene(with_K_and_D(opt.scene, run.K, run.D));
    Vector last(3 * scene.particle_count());
    scene.all_positions(res.x, last);
    const EnergyMeasures e = energy_measures(res.energy, reference);
    double min_z = 0;
    for (const Frame& f : res.frames) min_z = std::min(min_z, lowest_z(scene, f.positions));
    const std::string status =
        res.status == RunStatus::step_failed ? step_failure_name(res.failure) : run_status_name(res.status);
    std::fprintf(summary.get(), "%s %g %g %s %.4g %.6g %.6g %.6g %.6g %.4g %.3g %.3f\n", run.method.c_str(), run.K,
                 run.D, status.c_str(), stop_time(res, h), e.gain, e.final_change, lowest_z(scene, last), min_z,
                 max_abs_strain(scene, last), res.newton_iterations_per_step(), res.wall_seconds);
    std::printf("%-17s %5g %4g  %-9s %8s %11.4g %11.4g %8.4g %8.4g %10.4g\n", run.method.c_str(), run.K, run.D,
                status.c_str(), diverged(res) ? format_number(stop_time(res, h), 4).c_str() : "-", e.gain,
                e.final_change, lowest_z(scene, last), min_z, max_abs_strain(scene, last));

    const bool bounded = !diverged(res);
    const std::string rise =
        bounded && e.gain > 0 ? format_number(e.rise_from, 3) + " to " + format_number(e.rise_to, 3) : "";
    page_table.add_row({title_of(run.method), format_number(run.K), format_number(run.D),
                        bounded ? outcome(res) : ended(res, h), bounded ? format_number(e.gain, 3) : "", rise,
                        bounded ? format_number(e.final_change, 3) : "", bounded ? format_number(min_z, 3) : ""});

    write_series(dir + "series_" + name + ".dat", run, scene, reference);
    const MeshBox box = write_mesh(dir + "mesh_" + name + ".dat", res, scene, last, stride);
    const std::string ending =
        diverged(res) ? ended(res, h) : "bounded, max E/" + ratio + " = " + format_number(e.peak, 3);
    write_run_row(table.get(), r + 1, run, ending, box);
    write_instants(instants.get(), r + 1, res, box.blocks, stride, h, T);
  }
  summary.commit();
  table.commit();
  write_text_fragment(dir + "summary.md", "Energies relative to " + reference.description() + ".\n\n" +
                                             page_table.markdown() + "\n" + measured_by_line(settings.command));
  instants.commit();

  write_cases(dir + "cases.dat", runs, opt.scene, reference);
  write_figures(dir + "figures.dat");
  write_parameters(dir + "parameters.dat", opt.run, settings, reference);
}

}  // namespace ch05
