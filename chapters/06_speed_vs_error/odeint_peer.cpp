// Chapter 6's peer comparison with Boost.Odeint, RK4 at fixed h on the report scene:
//  1. the whole ch03_runge_kutta process, with its default outputs, against the program a reader would write with
//     odeint alone (plain_odeint_cloth.hpp), each timed as a process;
//  2. the integrators alone on the same forces: odeint's runge_kutta4 driving cloth::ForceField against the
//     core's generic Butcher-tableau engine, timed in one process.
// `--program plain` runs only the reader's program (what part 1 times). Writes odeint_comparison.md (a table for
// the book) and odeint_comparison.txt to --out.
#include "plain_odeint_cloth.hpp"
#include "process_timing.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "integrators/method_registry.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"
#include "program/timing.hpp"

#include <boost/numeric/odeint.hpp>

#include <cstdio>
#include <filesystem>
#include <functional>

using namespace cloth;
using ch06::best_of;
using ch06::Seconds;
using ch06::time_process;
using ch06::Timings;

namespace {

// The files the program writes into --out, in one list.
const std::vector<std::string> outputs = {"odeint_comparison.md", "odeint_comparison.txt"};

ch06::PlainOdeintCloth plain_cloth(const SceneParams& s) {
  return {s.grid.M, s.grid.N, s.grid.d, s.stiffness, s.damping, s.mass, s.gravity, s.initial_velocity_z};
}

// odeint's runge_kutta4 driving the core's forces: the state is (x, v) of the free particles in one
// std::vector, the right-hand side (v, M^{-1} f(x, v)) from ForceField::acceleration.
Vector odeint_on_core_forces(ForceField& field, double h, double T) {
  const int n = field.dof_count();
  std::vector<double> y(2 * static_cast<std::size_t>(n));
  Eigen::Map<Vector>(y.data(), n) = field.scene().initial_positions();
  Eigen::Map<Vector>(y.data() + n, n) = field.scene().initial_velocities();
  const auto system = [&](const std::vector<double>& s, std::vector<double>& dsdt, double /*t*/) {
    const Eigen::Map<const Vector> x(s.data(), n), v(s.data() + n, n);
    Eigen::Map<Vector>(dsdt.data(), n) = v;
    Eigen::Map<Vector> a(dsdt.data() + n, n);
    field.acceleration(x, v, a);
  };
  boost::numeric::odeint::runge_kutta4<std::vector<double>> rk4;
  const long steps = std::lround(T / h);
  for (long k = 0; k < steps; ++k) rk4.do_step(std::cref(system), y, static_cast<double>(k) * h, h);
  return Eigen::Map<Vector>(y.data(), n);
}

// The core's generic Butcher-tableau engine with the rk4 tableau, the same steps, no driver and no outputs.
Vector core_engine(ForceField& field, double h, double T) {
  auto stepper = make_stepper("rk4", field);
  Vector x = field.scene().initial_positions(), v = field.scene().initial_velocities();
  const long steps = std::lround(T / h);
  for (long k = 0; k < steps; ++k) stepper->step(h, x, v);
  return x;
}

double lowest_z(const Vector& x) {
  double z = INFINITY;
  for (Eigen::Index k = 2; k < x.size(); k += 3) z = std::min(z, x[k]);
  return z;
}

// One run in this process (program/timing.hpp: the thread's processor time beside the wall clock).
Seconds time_in_process(const std::function<void()>& body) {
  const Timing t = time_runs(body, {1});
  return {t.fastest_wall, t.fastest_cpu};
}

// The flags that give another program this scene, step and horizon (--dt and --t-end last).
std::vector<std::string> scene_arguments(const SceneParams& s, double h, double T) {
  return {"--grid", std::to_string(s.grid.M) + "x" + std::to_string(s.grid.N), "--spacing", format_number(s.grid.d),
          "--mass", format_number(s.mass), "--v0", format_number(s.initial_velocity_z), "--K",
          format_number(s.stiffness), "--damping", format_number(s.damping), "--dt", format_number(h), "--t-end",
          format_number(T)};
}

// The second comparison: odeint's runge_kutta4 and the core's tableau engine on the same forces, alternately, and
// the reader's program in this process; where each ends (the lowest particle) shows that they solve one problem.
struct Integrators {
  Timings odeint, engine, plain;
  double z_odeint = 0, z_engine = 0, z_plain = 0;
};
Integrators time_integrators(const SceneParams& s, double h, double T, int runs) {
  const Scene scene(s);
  ForceField field(scene);
  Vector x_odeint, x_core;
  ch06::PlainOdeintCloth::State y_plain;
  const ch06::PlainOdeintCloth plain = plain_cloth(s);
  Integrators out;
  for (int k = 0; k < runs; ++k) {  // alternated, so that a busy spell of the machine hits both
    out.odeint.add(time_in_process([&] { x_odeint = odeint_on_core_forces(field, h, T); }));
    out.engine.add(time_in_process([&] { x_core = core_engine(field, h, T); }));
  }
  out.plain = best_of(runs, [&] { return time_in_process([&] { y_plain = plain.run(h, T); }); });
  out.z_odeint = lowest_z(x_odeint), out.z_engine = lowest_z(x_core), out.z_plain = plain.lowest_z(y_plain);
  return out;
}

// What a program costs beyond its integration: one step of h = 0.01 s of each single-run program of the chapters
// before this one on the same scene, as a whole process (start-up, the scene, the fastest rates for run.txt,
// every output). A later chapter's program is timed on its own page.
MarkdownTable one_step_table(const std::filesystem::path& bin, const std::vector<std::string>& scene_args,
                             const std::string& dir, int runs) {
  MarkdownTable one_step({"one step of h = 0.01 s, whole process", "wall [ms]", "CPU [ms]"}, "lrr");
  for (const char* program : {"ch02_explicit_euler", "ch03_runge_kutta", "ch04_implicit_euler"}) {
    std::vector<std::string> args = {(bin / program).string()};
    args.insert(args.end(), scene_args.begin(), scene_args.end() - 4);  // the scene, without --dt and --t-end
    args.insert(args.end(), {"--dt", "0.01", "--t-end", "0.01", "--out", dir + "/one_step_" + program});
    const Seconds t = best_of(runs, [&] { return time_process(args); }).best;
    one_step.add_row({std::string("`") + program + "`", format_fixed(1e3 * t.wall, 1), format_fixed(1e3 * t.cpu, 1)});
  }
  return one_step;
}

// A row of the two comparison tables: seconds of wall and CPU time, and the CPU time as a ratio to `ref`'s.
std::vector<std::string> row(const char* what, const Timings& t, const Timings& ref) {
  return {what, format_fixed(t.best.wall, 3), format_fixed(t.best.cpu, 3), format_fixed(t.slowest_cpu, 3),
          format_fixed(t.best.cpu / ref.best.cpu, 2)};
}

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch06_odeint_peer",
                  "Chapter 6: RK4 on the report scene against Boost.Odeint, as whole programs and as integrators\n"
                  "on the same forces. The book's figures use --K 200 --damping 20 --dt 1e-4 --t-end 1.");
  // The straightforward program models the report scene alone (corners pinned, projected damper, every spring
  // family, one stiffness): the flags that would change it are not taken.
  cli.use_common({"--grid", "--spacing", "--mass", "--K", "--damping", "--v0", "--dt", "--t-end", "--out"});
  bool plain_only = false;
  int runs = 3;
  std::string ch03 = (std::filesystem::path(argv[0]).parent_path() / "ch03_runge_kutta").string();
  cli.add_value("--program", "plain", "run only the program written with odeint alone (for timing it as a process)",
                [&](const std::string& s) {
                  if (s != "plain") throw InputError("expected 'plain'");
                  plain_only = true;
                });
  cli.add_value("--runs", "N", "timed runs of each program, the fastest kept (default 3)", [&](const std::string& s) {
    const long long n = parse_integer(s);
    if (n < 1 || n > 100) throw InputError("expected a whole number from 1 to 100");
    runs = static_cast<int>(n);
  });
  cli.add_value("--ch03", "PATH", "the ch03_runge_kutta program to time (default: beside this one)",
                [&](const std::string& s) { ch03 = s; });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const SceneParams& s = opt.scene;
    const double h = opt.run.dt, T = opt.run.t_end;
    if (plain_only) {
      const ch06::PlainOdeintCloth cloth = plain_cloth(s);
      std::printf("lowest z at T = %g s: %.9g m\n", T, cloth.lowest_z(cloth.run(h, T)));
      return 0;
    }
    prepare_outputs(opt.run.out_dir, outputs);
    const std::string dir = opt.run.out_dir;
    const std::vector<std::string> scene_args = scene_arguments(s, h, T);

    // 1. Whole programs, each as a process, alternately: one configuration on each side, as many runs.
    std::vector<std::string> plain_args = {argv[0], "--program", "plain"}, ch03_args = {ch03};
    plain_args.insert(plain_args.end(), scene_args.begin(), scene_args.end());
    ch03_args.insert(ch03_args.end(), scene_args.begin(), scene_args.end());
    ch03_args.insert(ch03_args.end(), {"--out", dir + "/ch03_run"});
    Timings plain, ch03_run;
    for (int k = 0; k < runs; ++k) plain.add(time_process(plain_args)), ch03_run.add(time_process(ch03_args));
    MarkdownTable programs({"program", "wall [s]", "CPU, fastest [s]", "CPU, slowest [s]", "ratio"}, "lrrrr");
    programs.add_row(row("written with Boost.Odeint alone (process)", plain, plain));
    programs.add_row(row("ch03_runge_kutta with its outputs (process)", ch03_run, plain));

    // 2. The integrators alone on the core's forces.
    const Integrators in = time_integrators(s, h, T, runs);
    MarkdownTable integrators({"integrator, on the project's forces", "wall [s]", "CPU, fastest [s]",
                               "CPU, slowest [s]", "ratio"},
                              "lrrrr");
    integrators.add_row(row("odeint runge_kutta4", in.odeint, in.odeint));
    integrators.add_row(row("generic Butcher-tableau engine, rk4", in.engine, in.odeint));

    // 3. What the program around the integration costs.
    const int process_runs = std::max(runs, 5);
    const MarkdownTable one_step = one_step_table(std::filesystem::path(ch03).parent_path(), scene_args, dir, process_runs);

    const std::string table =
        "RK4, h = " + format_number(h) + " s over T = " + format_number(T) + " s on the " + std::to_string(s.grid.M) +
        " x " + std::to_string(s.grid.N) + " cloth with K = " + format_number(s.stiffness) + " N/m, D = " +
        format_number(s.damping) + " N s/m; each side one configuration, timed " + std::to_string(runs) +
        " times alternately with the other: the fastest and the slowest CPU time, and the ratio of the fastest.\n\n" +
        programs.markdown() + "\n" + integrators.markdown() + "\nOn the same cloth, the fastest of " +
        std::to_string(process_runs) + " runs:\n\n" + one_step.markdown();
    write_text_fragment(dir + "/odeint_comparison.md", table + "\n" + measured_by_line(reader_command(argc, argv)));
    std::fputs(table.c_str(), stdout);
    write_key_values(dir + "/odeint_comparison.txt",
                     {{"plain_process_cpu_seconds", format_number(plain.best.cpu)},
                      {"ch03_process_cpu_seconds", format_number(ch03_run.best.cpu)},
                      {"ch03_over_plain", format_number(ch03_run.best.cpu / plain.best.cpu, 3)},
                      {"plain_in_process_cpu_seconds", format_number(in.plain.best.cpu)},
                      {"odeint_core_forces_cpu_seconds", format_number(in.odeint.best.cpu)},
                      {"engine_cpu_seconds", format_number(in.engine.best.cpu)},
                      {"engine_over_odeint", format_number(in.engine.best.cpu / in.odeint.best.cpu, 3)},
                      {"lowest_z_plain", format_number(in.z_plain, 9)},
                      {"lowest_z_odeint_core", format_number(in.z_odeint, 9)},
                      {"lowest_z_engine", format_number(in.z_engine, 9)}});
    std::printf("lowest z at T: odeint alone %.9g m, odeint on the core's forces %.9g m, core engine %.9g m\n",
                in.z_plain, in.z_odeint, in.z_engine);
    return 0;
  });
}
