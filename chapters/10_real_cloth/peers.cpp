// Chapter 10's peer comparison on the stiff fabric (20 x 20, 5 cm, m = 6.25e-4 kg, K = 1e5 N/m, D = 0.01, from
// rest, corners pinned, T = 0.5 s): the programs a reader would write with Boost.Odeint (RK4 at its largest stable
// step, controlled Dormand-Prince) and with SUNDIALS (CVODE's BDF, ARKODE's backward Euler, both with KLU on the
// analytic Jacobian), each once with a plain loop over the springs (plain_fabric.hpp) and once driving the book's
// own force routine (peer_programs.cpp; same_model.cpp checks the two are one model), against the book's methods.
// A run's error: the largest distance of a particle at T from the reference (RK4 at 1/4 of its stable step).
#include "peer_programs.hpp"
#include "same_model.hpp"
#include "study.hpp"

#include "analysis/lattice_frequency.hpp"
#include "analysis/trajectory_measures.hpp"
#include "base/format_number.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/timing.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace cloth;
using namespace ch10;

namespace {

constexpr double T = 0.5;

struct Row {
  std::string program, side, setting;  // side: "odeint", "SUNDIALS" or "book"
  bool ok = true;
  std::string note;
  long long steps = 0;
  double seconds = 0, error = NAN;
};

// The step T / steps as the page writes it: "1/60" when a second holds a whole number of them.
std::string step_of(long long steps) {
  const double per_second = static_cast<double>(steps) / T;
  if (std::abs(per_second - std::round(per_second)) < 1e-9 * per_second) return format("1/%.0f", per_second);
  return format("%.3g", T / static_cast<double>(steps));
}

// The fastest row of the book's methods (book) or of the peers (!book) that reached tol, of a motion of size
// `motion`: none at a level the rest state meets (cloth::fastest_reaching).
const Row* fastest(const std::vector<Row>& rows, bool book, double motion, double tol) {
  std::vector<const Row*> side;
  std::vector<RunCost> costs;
  for (const Row& r : rows)
    if ((r.side == "book") == book) side.push_back(&r), costs.push_back({r.ok ? r.error : NAN, r.seconds});
  const int best = fastest_reaching(costs, motion, tol);
  return best < 0 ? nullptr : side[static_cast<std::size_t>(best)];
}

// The comparison's settings and what every run is measured against.
struct Bench {
  const Scene& scene;
  Vector reference;  ///< every particle's position at T (RK4 at a quarter of its stable step)
  long long rk4_steps = 0, se_steps = 0;  ///< 95 % of the lattice's stable step, as in the chapter's sweep
  bool quick = false;
  int runs = 3;  ///< timed runs of a configuration, the fastest kept
  std::vector<Row> rows;
};

void print_row(const Row& r) {
  std::printf("  %-34s %-18s %7lld steps %8.4f s  error %.2e %s\n", r.program.c_str(), r.setting.c_str(), r.steps,
              r.seconds, r.error, r.note.c_str());
}

// Times a peer's run of `system` and measures its error at T against the reference.
void record(Bench& b, Row row, const std::function<Outcome()>& run, OdeSystem& system) {
  const double budget = b.quick ? 0.3 : 2.0;  // repeat a configuration while its runs have cost less than this
  Outcome out;
  // Timed as every program of the book times (program/timing.hpp), the fastest run kept.
  row.seconds = time_runs(
                    [&] {
                      out = run();
                      throw_if_interrupted();
                    },
                    {.runs = b.runs, .budget = budget})
                    .fastest_cpu;
  row.ok = out.ok;
  row.note = out.note;
  if (row.steps == 0) row.steps = out.steps;
  if (out.ok) {
    const Vector x = system.positions(out.y);
    if (x.allFinite() && x.cwiseAbs().maxCoeff() < 100)
      row.error = largest_distance(x, b.reference);
    else
      row.ok = false, row.note = "diverged";
  }
  print_row(row);
  b.rows.push_back(row);
}

// [peer_runs]
// The peers, on the plain loop and on the book's forces. The quick run keeps the runs that decide the comparison,
// and of the plain loop's only RK4 and backward Euler.
void peer_runs(Bench& b, PlainSystem& plain, CoreSystem& core) {
  struct Forces {
    const char* name;
    OdeSystem* system;
  };
  for (const Forces& f : {Forces{"plain loop", &plain}, Forces{"book's forces", &core}}) {
    const bool plain_loop = f.system == &plain;
    record(b, {format("odeint RK4, %s", f.name), "odeint", "h = " + step_of(b.rk4_steps), true, "", b.rk4_steps},
           [&] { return odeint_rk4(*f.system, T, b.rk4_steps); }, *f.system);
    for (double tol : b.quick ? std::vector<double>{1e-3} : std::vector<double>{1e-2, 1e-4, 1e-6})
      if (!b.quick || !plain_loop)
        record(b, {format("odeint Dormand-Prince, %s", f.name), "odeint", "tol = " + format_number(tol), true, "", 0},
               [&] { return odeint_dopri5(*f.system, T, tol); }, *f.system);
    // CVODE grows costly fast as the tolerance tightens (at 1e-4 it takes some 17000 steps): two tolerances
    // show it.
    for (double tol : b.quick ? std::vector<double>{1e-2} : std::vector<double>{1e-2, 1e-3})
      if (!b.quick || !plain_loop)
        record(b, {format("CVODE BDF + KLU, %s", f.name), "SUNDIALS", "tol = " + format_number(tol), true, "", 0},
               [&] { return sundials_run(*f.system, Sundials::cvode_bdf, T, tol, 0); }, *f.system);
    for (long long steps : b.quick ? std::vector<long long>{30} : std::vector<long long>{15, 30, 60, 120, 240, 480})
      record(b, {format("ARKODE backward Euler + KLU, %s", f.name), "SUNDIALS", "h = " + step_of(steps), true, "",
                 steps},
             [&] { return sundials_run(*f.system, Sundials::arkode_newton, T, 0, steps); }, *f.system);
    for (long long steps : b.quick ? std::vector<long long>{30} : std::vector<long long>{15, 30, 60, 120, 240})
      if (!b.quick || !plain_loop)
        record(b, {format("ARKODE linearly implicit Euler + KLU, %s", f.name), "SUNDIALS", "h = " + step_of(steps),
                   true, "", steps},
               [&] { return sundials_run(*f.system, Sundials::arkode_linear, T, 0, steps); }, *f.system);
  }
}
// [peer_runs]

// [book_runs]
// The book's methods, from the registry (ch10::make_method), on the same scene.
void book_runs(Bench& b) {
  const auto book = [&](const std::string& method, long long steps) {
    Row row{"book: " + label(method), "book", "h = " + step_of(steps), true, "", steps};
    const Run r = run_to(b.scene, method, T, steps, b.quick ? 0.05 : 0.5);
    throw_if_interrupted();
    row.seconds = r.seconds;
    row.ok = r.ok;
    row.note = r.message;
    if (r.ok) {
      Vector all(3 * b.scene.particle_count());
      b.scene.all_positions(r.x, all);
      row.error = largest_distance(all, b.reference);
    }
    print_row(row);
    b.rows.push_back(row);
  };
  book("symplectic_euler", b.se_steps);
  book("rk4", b.rk4_steps);
  for (long long steps : b.quick ? std::vector<long long>{30} : std::vector<long long>{15, 30, 60})
    book("implicit_euler/one/cg", steps);
}
// [book_runs]

// The table of every run (peers.md, peers.dat), each error beside the size of the motion at T (the rest state's
// distance from the reference), and the comparison of the fastest run of each side at each accuracy
// (peers_ratio.md), where a level the rest state meets is said so and timed for neither side.
void write_comparison(const std::vector<Row>& rows, double motion, const std::string& dir,
                      const std::string& command) {
  MarkdownTable table({"program", "setting", "steps", "CPU time [s]", "error at T [m]",
                       format("error / motion (%.3g m)", motion)},
                      "llrrrr");
  std::string dat = format("# the motion at T: %.6e m\n# side program setting steps cpu_seconds error_at_T\n", motion);
  for (const Row& r : rows) {
    table.add_row({r.program, r.setting, r.ok ? std::to_string(r.steps) : "-", format("%.3g", r.seconds),
                   r.ok ? format("%.2g", r.error) : r.note, r.ok ? format("%.2g", r.error / motion) : ""});
    dat += format("\"%s\" \"%s\" \"%s\" %lld %.6e %.6e\n", r.side.c_str(), r.program.c_str(), r.setting.c_str(),
                  r.steps, r.seconds, r.ok ? r.error : NAN);
  }
  write_table_fragment(dir + "/peers.md", table, command);
  write_text(dir + "/peers.dat", dat);
  std::string ratio;
  for (double tol : {1e-2, 1e-3}) {
    const Row* mine = fastest(rows, true, motion, tol);
    const Row* peer = fastest(rows, false, motion, tol);
    const char* accuracy = tol == 1e-2 ? "1 cm" : "1 mm";
    if (accuracy_verdict(0, motion, tol) == AccuracyVerdict::met_by_rest)
      ratio += format("%s is %s: neither side is timed to it. ", accuracy, met_by_standing_still(motion).c_str());
    else if (mine == nullptr || peer == nullptr)
      ratio += format("To %s (the motion at T is %.3g m), no %s got there. ", accuracy, motion,
                      mine == nullptr ? "run of the book's methods" : "peer run");
    else
      ratio += format("To %s (the motion at T is %.3g m) the fastest peer is %s (%s), %.3g s; the book's fastest is "
                      "%s (%s), %.3g s: %.2f times the peer's time. ",
                      accuracy, motion, peer->program.c_str(), peer->setting.c_str(), peer->seconds,
                      mine->program.substr(6).c_str(), mine->setting.c_str(), mine->seconds,
                      mine->seconds / peer->seconds);
  }
  write_text_fragment(dir + "/peers_ratio.md", ratio + "\n");
}

const OutputList peers_outputs = {
    {"peers.md", OutputKind::fragment, "every run: program, setting, steps, CPU time and error at T"},
    {"peers_ratio.md", OutputKind::fragment, "the fastest peer against the book's fastest at 1 cm and 1 mm"},
    {"peers_check.md", OutputKind::fragment, "the plain loop against the book's forces"},
    {"peers.dat", OutputKind::figure_input, "every run of peers.md"}};

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch10_peers",
                  "Chapter 10: the stiff fabric (20 x 20, 5 cm, 6.25e-4 kg, K = 1e5 N/m, D = 0.01, from rest,\n"
                  "T = 0.5 s) integrated by Boost.Odeint and SUNDIALS, with a plain force loop and with the book's\n"
                  "force routine, against the book's methods: CPU time and largest position error at T.");
  cli.use_common({"--out"});
  bool quick = false;
  int runs = 3;
  cli.add_switch("--quick", "only the runs that decide the comparison, each timed once or twice (for the plots target)",
                 [&] { quick = true; });
  cli.add_value("--runs", "N", "timed runs of each configuration, the fastest kept (default 3)",
                [&](const std::string& s) { runs = static_cast<int>(parse_count(s, 1, 100)); });
  cli.declare_outputs([](const Options&) { return peers_outputs; });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const std::string& dir = opt.run.out_dir;
    prepare_declared_outputs(dir, peers_outputs);
    const SceneParams p = fabric(20, 1e5);
    const Scene scene(p);
    PlainSystem plain(p);
    CoreSystem core(scene);
    check_same_model(scene, plain, core, dir);  // peers_check.md
    // The reference: as in the chapter's study, RK4 at a quarter of its stable step; the explicit methods at 95 %
    // of the lattice's stable step, as in the chapter's sweep.
    const double omega = lattice_fastest_frequency({p.stiffness, p.stiffness, p.stiffness, p.mass});
    const auto stable_steps = [&](double reach) {
      return static_cast<long long>(std::ceil(T / (0.95 * reach / omega)));
    };
    Bench b{scene, Vector(3 * scene.particle_count()), stable_steps(2 * std::sqrt(2.0)), stable_steps(2.0), quick,
            quick ? std::min(runs, 2) : runs, {}};
    const long long reference_steps = static_cast<long long>(std::ceil(T / (2 * std::sqrt(2.0) / omega / 4)));
    double agreement = -1;
    scene.all_positions(reference(scene, T, reference_steps, false, agreement), b.reference);
    std::printf("reference: RK4 with %lld steps\n", reference_steps);

    peer_runs(b, plain, core);
    book_runs(b);
    Vector rest(3 * scene.particle_count());  // the size of the motion: the rest state's distance from the reference
    scene.all_positions(scene.initial_positions(), rest);
    write_comparison(b.rows, largest_distance(rest, b.reference), dir, reader_command(argc, argv));
    return 0;
  });
}
