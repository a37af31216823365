// Chapter 6's peer comparison with Boost.Odeint, RK4 at fixed h on the report scene:
//  1. the whole ch03_runge_kutta process, with its default outputs, against the program a reader would write with
//     odeint alone (odeint's runge_kutta4, Ahnert & Mulansky 2011, on the plain force loop of plain_fabric.hpp),
//     each timed as a process;
//  2. the integrators alone on the same forces: odeint's runge_kutta4 driving cloth::ForceField against the
//     core's generic Butcher-tableau engine, timed in one process;
//  3. what a program costs beyond its integration: one step of each single-run program of Chapters 2 to 4.
// `--program plain` runs only the reader's program (what part 1 times). Writes odeint_comparison.md (a table for
// the book) and odeint_comparison.txt to --out; the timed programs write theirs into a scratch folder there, removed
// once they have been timed.
#include "odeint_timings.hpp"

#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/output.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

using namespace cloth;
using namespace ch06;

namespace {

// The files the program writes into --out, declared once (program/output_spec.hpp).
OutputList outputs() {
  return {{"odeint_comparison.md", OutputKind::fragment, "both comparisons' tables and the cost of one step"},
          {"odeint_comparison.txt", OutputKind::data, "the fastest CPU times, their ratios and where each run ends"}};
}
// Where the timed programs write their own outputs, removed once they have been timed.
const char* const scratch_folder = "timed_runs";

// The program's own flags.
struct PeerSettings {
  bool plain_only = false;  ///< `--program plain`
  int runs = 3;
  std::string ch03;  ///< the ch03_runge_kutta program to time
};

// A row of the two comparison tables: seconds of wall and CPU time, and the CPU time as a ratio to `ref`'s.
std::vector<std::string> row(const char* what, const Timings& t, const Timings& ref) {
  return {what, format_fixed(t.best.wall, 3), format_fixed(t.best.cpu, 3), format_fixed(t.slowest_cpu, 3),
          format_fixed(t.best.cpu / ref.best.cpu, 2)};
}

// What the three parts measured.
struct Comparison {
  Programs programs;
  Integrators integrators;
  MarkdownTable one_step;
  int runs = 0, process_runs = 0;  ///< timed runs of each side of a comparison; of each single-run program
};

// odeint_comparison.md (the page's tables) and odeint_comparison.txt; the tables are also printed.
void write_comparison(const std::string& dir, const Options& opt, const Comparison& c, const std::string& command) {
  const SceneParams& s = opt.scene;
  const Programs& p = c.programs;
  const Integrators& in = c.integrators;
  MarkdownTable programs({"program", "wall [s]", "CPU, fastest [s]", "CPU, slowest [s]", "ratio"}, "lrrrr");
  programs.add_row(row("written with Boost.Odeint alone (process)", p.plain, p.plain));
  programs.add_row(row("ch03_runge_kutta with its outputs (process)", p.ch03, p.plain));
  MarkdownTable integrators({"integrator, on the project's forces", "wall [s]", "CPU, fastest [s]",
                             "CPU, slowest [s]", "ratio"},
                            "lrrrr");
  integrators.add_row(row("odeint runge_kutta4", in.odeint, in.odeint));
  integrators.add_row(row("generic Butcher-tableau engine, rk4", in.engine, in.odeint));
  const std::string table =
      "RK4, h = " + format_number(opt.run.dt) + " s over T = " + format_number(opt.run.t_end) + " s on the " +
      std::to_string(s.grid.M) + " x " + std::to_string(s.grid.N) + " cloth with K = " + format_number(s.stiffness) +
      " N/m, D = " + format_number(s.damping) + " N s/m; each side one configuration, timed " + std::to_string(c.runs) +
      " times alternately with the other: the fastest and the slowest CPU time, and the ratio of the fastest.\n\n" +
      programs.markdown() + "\n" + integrators.markdown() + "\nOn the same cloth, the fastest of " +
      std::to_string(c.process_runs) + " runs:\n\n" + c.one_step.markdown();
  write_text_fragment(dir + "/odeint_comparison.md", table + "\n" + measured_by_line(command));
  std::fputs(table.c_str(), stdout);
  write_key_values(dir + "/odeint_comparison.txt",
                   {{"plain_process_cpu_seconds", format_number(p.plain.best.cpu)},
                    {"ch03_process_cpu_seconds", format_number(p.ch03.best.cpu)},
                    {"ch03_over_plain", format_number(p.ch03.best.cpu / p.plain.best.cpu, 3)},
                    {"plain_in_process_cpu_seconds", format_number(in.plain.best.cpu)},
                    {"odeint_core_forces_cpu_seconds", format_number(in.odeint.best.cpu)},
                    {"engine_cpu_seconds", format_number(in.engine.best.cpu)},
                    {"engine_over_odeint", format_number(in.engine.best.cpu / in.odeint.best.cpu, 3)},
                    {"lowest_z_plain", format_number(in.z_plain, 9)},
                    {"lowest_z_odeint_core", format_number(in.z_odeint, 9)},
                    {"lowest_z_engine", format_number(in.z_engine, 9)}});
  std::printf("lowest z at T: odeint alone %.9g m, odeint on the core's forces %.9g m, core engine %.9g m\n",
              in.z_plain, in.z_odeint, in.z_engine);
}

void add_flags(CommandLine& cli, PeerSettings& settings) {
  cli.add_value("--program", "plain", "run only the program written with odeint alone (for timing it as a process)",
                [&](const std::string& s) {
                  if (s != "plain") throw InputError("expected 'plain'");
                  settings.plain_only = true;
                });
  cli.add_value("--runs", "N", "timed runs of each program, the fastest kept (default 3)", [&](const std::string& s) {
    const long long n = parse_integer(s);
    if (n < 1 || n > 100) throw InputError("expected a whole number from 1 to 100");
    settings.runs = static_cast<int>(n);
  });
  cli.add_value("--ch03", "PATH", "the ch03_runge_kutta program to time (default: beside this one)",
                [&](const std::string& s) { settings.ch03 = s; });
}

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch06_odeint_peer",
                  "Chapter 6: RK4 on the report scene against Boost.Odeint, as whole programs and as integrators\n"
                  "on the same forces. The book's figures use --K 200 --damping 20 --dt 1e-4 --t-end 1.");
  // The straightforward program models the report scene alone (corners pinned, projected damper, every spring
  // family, one stiffness): the flags that would change it are not taken.
  cli.use_common({"--grid", "--spacing", "--mass", "--K", "--damping", "--v0", "--dt", "--t-end", "--out"});
  PeerSettings settings;
  settings.ch03 = (std::filesystem::path(argv[0]).parent_path() / "ch03_runge_kutta").string();
  add_flags(cli, settings);
  cli.declare_outputs([&](const Options&) { return settings.plain_only ? OutputList{} : outputs(); });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const SceneParams& s = opt.scene;
    const double h = opt.run.dt, T = opt.run.t_end;
    if (settings.plain_only) {
      const PlainFabric fabric = plain_fabric(s);
      const std::vector<double> y = plain_rk4(fabric, h, T);
      std::printf("lowest z at T = %g s: %.9g m\n", T, lowest_z(y.data(), 3L * fabric.particles()));
      return 0;
    }
    prepare_declared_outputs(opt.run.out_dir, outputs());
    const std::string dir = opt.run.out_dir, scratch = dir + "/" + scratch_folder;
    const std::string bin = std::filesystem::path(settings.ch03).parent_path().string();
    const std::vector<std::string> scene_args = scene_arguments(s, h, T);
    const int process_runs = std::max(settings.runs, 5);
    const Comparison measured{
        .programs = time_programs(argv[0], settings.ch03, settings.runs, scene_args, scratch),  // 1. whole programs
        .integrators = time_integrators(s, h, T, settings.runs),             // 2. the integrators alone
        .one_step = one_step_table(bin, scene_args, scratch, process_runs),  // 3. around the integration
        .runs = settings.runs,
        .process_runs = process_runs};
    std::filesystem::remove_all(scratch);
    write_comparison(dir, opt, measured, reader_command(argc, argv));
    return 0;
  });
}
