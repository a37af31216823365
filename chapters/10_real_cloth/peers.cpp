// Chapter 10's peer comparison on the stiff fabric (20 x 20, 5 cm, m = 6.25e-4 kg, K = 1e5 N/m, D = 0.01, from
// rest, corners pinned, T = 0.5 s): the programs a reader would write with Boost.Odeint (RK4 at its largest stable
// step, controlled Dormand-Prince) and with SUNDIALS (CVODE's BDF, ARKODE's backward Euler, both with KLU on the
// analytic Jacobian), each once with a plain loop over the springs (plain_fabric.hpp) and once driving the book's
// own force routine, against the book's methods from the registry. Every run's error is the chapter's: the
// largest distance of a particle at T from where the reference (RK4 at a quarter of its stable step) puts it.
// Writes peers.md (the table), peers_ratio.md (the sentence that compares the fastest of each side),
// peers_check.md (the plain loop against the book's forces) and peers.dat to --out.
#include "peer_systems.hpp"
#include "study.hpp"

#include "analysis/lattice_frequency.hpp"
#include "analysis/trajectory_measures.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/timing.hpp"
#include "program/output.hpp"
#include "program/sundials.hpp"

#include <arkode/arkode_arkstep.h>
#include <boost/numeric/odeint.hpp>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace cloth;
using ch10::format;
using ch10::OdeSystem;
using ch10::PlainSystem;
using ch10::CoreSystem;
using ch10::rhs_callback;
using ch10::jacobian_callback;
using ch10::check;
using ch10::failure_note;

namespace {

constexpr double T = 0.5;

// ---------------------------------------------------------------------------------------------------------------
// The peers.

struct Outcome {
  bool ok = true;
  std::string note;           // why a run failed, or what a tolerance-controlled run did
  long long steps = 0;
  std::vector<double> y;
};

// [odeint_peers]
// Boost.Odeint: classical RK4 at a fixed step, or Dormand-Prince 5(4) with odeint's step-size controller
// (absolute and relative tolerance tol) from a first step of 1e-5 s.
Outcome odeint_rk4(OdeSystem& system, long long steps) {
  Outcome out{true, "", steps, system.initial_state()};
  const auto f = [&](const std::vector<double>& y, std::vector<double>& dydt, double /*t*/) {
    throw_if_interrupted();  // odeint is C++: the exception passes through it
    system.rhs(y.data(), dydt.data());
  };
  boost::numeric::odeint::runge_kutta4<std::vector<double>> rk4;
  const double h = T / static_cast<double>(steps);
  for (long long k = 0; k < steps; ++k) rk4.do_step(f, out.y, static_cast<double>(k) * h, h);
  return out;
}

Outcome odeint_dopri5(OdeSystem& system, double tol) {
  namespace odeint = boost::numeric::odeint;
  Outcome out{true, "", 0, system.initial_state()};
  const auto f = [&](const std::vector<double>& y, std::vector<double>& dydt, double /*t*/) {
    throw_if_interrupted();
    system.rhs(y.data(), dydt.data());
  };
  auto stepper = odeint::make_controlled(tol, tol, odeint::runge_kutta_dopri5<std::vector<double>>());
  out.steps = static_cast<long long>(odeint::integrate_adaptive(stepper, f, out.y, 0.0, T, 1e-5));
  return out;
}
// [odeint_peers]


// [sundials_peers]
enum class Sundials { cvode_bdf, arkode_newton, arkode_linear };

// SUNDIALS: CVODE's variable-order, variable-step BDF with tolerances rtol = atol = tol, or ARKODE with the
// one-stage backward Euler table (c = A = b = 1; SUNDIALS 6.4 has none built in) at the fixed step T / steps.
// Both solve their Newton systems with KLU on the analytic Jacobian. ARKODE's backward Euler evaluates the
// Jacobian at the start of every step and runs either its Newton iteration on it, allowed 20 iterations (its
// default of 3 fails at frame steps, and a fixed step cannot shrink instead), or declared linearly implicit
// (ARKStepSetLinear): one Newton iteration, which is Baraff and Witkin's step.
Outcome sundials_run(OdeSystem& system, Sundials peer, double tol, long long steps) {
  SUNContext context = nullptr;
  check(SUNContext_Create(nullptr, &context), "SUNContext_Create");
  Outcome out{true, "", 0, system.initial_state()};
  N_Vector y = N_VMake_Serial(system.size(), out.y.data(), context);
  SUNMatrix A = SUNSparseMatrix(system.size(), system.size(), system.nonzeros(), CSC_MAT, context);
  SUNLinearSolver klu = SUNLinSol_KLU(y, A, context);
  realtype t = 0;
  long steps_taken = 0;
  if (peer == Sundials::cvode_bdf) {
    void* mem = CVodeCreate(CV_BDF, context);
    check(CVodeSetErrFile(mem, nullptr), "CVodeSetErrFile");  // a failure is reported with the run's results
    check(CVodeInit(mem, rhs_callback, 0.0, y), "CVodeInit");
    check(CVodeSStolerances(mem, tol, tol), "CVodeSStolerances");
    check(CVodeSetUserData(mem, &system), "CVodeSetUserData");
    check(CVodeSetLinearSolver(mem, klu, A), "CVodeSetLinearSolver");
    check(CVodeSetJacFn(mem, jacobian_callback), "CVodeSetJacFn");
    check(CVodeSetMaxNumSteps(mem, 1000000), "CVodeSetMaxNumSteps");
    const int flag = CVode(mem, T, y, &t, CV_NORMAL);
    CVodeGetNumSteps(mem, &steps_taken);
    if (flag < 0) out = {false, failure_note(sundials_end(flag, true, true), steps_taken, t), 0, {}};
    CVodeFree(&mem);
  } else {
    void* mem = ARKStepCreate(nullptr, rhs_callback, 0.0, y, context);
    check(ARKStepSetErrFile(mem, nullptr), "ARKStepSetErrFile");
    check(ARKStepSetUserData(mem, &system), "ARKStepSetUserData");
    check(ARKStepSetLinearSolver(mem, klu, A), "ARKStepSetLinearSolver");
    check(ARKStepSetJacFn(mem, jacobian_callback), "ARKStepSetJacFn");
    realtype c[] = {1}, a[] = {1}, b[] = {1};
    ARKodeButcherTable euler = ARKodeButcherTable_Create(1, 1, 0, c, a, b, nullptr);
    check(ARKStepSetTables(mem, 1, 0, euler, nullptr), "ARKStepSetTables");
    check(ARKStepSetFixedStep(mem, T / static_cast<double>(steps)), "ARKStepSetFixedStep");
    // ARKODE keeps a Jacobian for up to 51 steps by default: at a frame step that is the whole run on the
    // Jacobian of the flat sheet, which has no stiffness across it. Both forms evaluate it at every step.
    check(ARKStepSetJacEvalFrequency(mem, 1), "ARKStepSetJacEvalFrequency");
    check(ARKStepSetLSetupFrequency(mem, 1), "ARKStepSetLSetupFrequency");
    if (peer == Sundials::arkode_linear)
      check(ARKStepSetLinear(mem, 1), "ARKStepSetLinear");
    else
      check(ARKStepSetMaxNonlinIters(mem, 20), "ARKStepSetMaxNonlinIters");
    check(ARKStepSetMaxNumSteps(mem, 1000000), "ARKStepSetMaxNumSteps");
    // Step by step to T: the last step's own value, not ARKODE's interpolant (program/sundials.hpp).
    const int flag = arkode_fixed_steps_to(mem, T, T / static_cast<double>(steps), y, t);
    ARKStepGetNumSteps(mem, &steps_taken);
    if (flag < 0) out = {false, failure_note(sundials_end(flag, false, true), steps_taken, t), 0, {}};
    ARKStepFree(&mem);
    ARKodeButcherTable_Free(euler);
  }
  out.steps = steps_taken;
  SUNLinSolFree(klu);
  SUNMatDestroy(A);
  N_VDestroy(y);
  SUNContext_Free(&context);
  return out;
}
// [sundials_peers]

// ---------------------------------------------------------------------------------------------------------------
// Measuring.

struct Row {
  std::string program, side, setting;  // side: "odeint", "SUNDIALS" or "book"
  bool ok = true;
  std::string note;
  long long steps = 0;
  double seconds = 0, error = NAN;
};

// Runs `body` at least once and until `runs` runs or `budget` CPU seconds are spent; keeps the fastest time.
template <class Body>
double best_time(int runs, double budget, Body&& body) {
  double best = INFINITY, spent = 0;
  for (int k = 0; k < runs && (k == 0 || spent < budget); ++k) {
    const double t0 = thread_cpu_seconds();
    body();
    const double t = thread_cpu_seconds() - t0;
    best = std::min(best, t);
    spent += t;
    throw_if_interrupted();
  }
  return best;
}

std::string step_text(long long steps) {
  const double per_second = static_cast<double>(steps) / T;
  if (std::abs(per_second - std::round(per_second)) < 1e-9 * per_second) return format("1/%.0f", per_second);
  return format("%.3g", T / static_cast<double>(steps));
}

// The fastest row of the book's methods (book) or of the peers (!book) whose error at T is at most tol.
const Row* fastest(const std::vector<Row>& rows, bool book, double tol) {
  const Row* best = nullptr;
  for (const Row& r : rows)
    if ((r.side == "book") == book && r.ok && r.error <= tol && (best == nullptr || r.seconds < best->seconds))
      best = &r;
  return best;
}

// The plain loop and the book's forces must be the same model: compare the right-hand sides and the
// Jacobians at a perturbed, moving state (pinned rows excepted, which the core does not have).
void check_same_model(const Scene& scene, PlainSystem& plain, CoreSystem& core, const std::string& dir) {
  std::vector<double> yp = plain.initial_state(), yc = core.initial_state();
  const int P = scene.particle_count(), n = scene.dof_count();
  for (int particle = 0; particle < P; ++particle) {
    const int s = scene.slot(particle);
    for (int k = 0; k < 3; ++k) {
      const double dx = 1e-3 * std::sin(1.3 * (3 * particle + k)), dv = 0.1 * std::cos(0.7 * (3 * particle + k));
      if (s < scene.free_count()) {
        yp[3 * particle + k] += dx, yc[3 * s + k] += dx;
        yp[3 * (P + particle) + k] += dv, yc[n + 3 * s + k] += dv;
      }
    }
  }
  std::vector<double> fp(yp.size()), fc(yc.size());
  plain.rhs(yp.data(), fp.data());
  core.rhs(yc.data(), fc.data());
  double rhs_difference = 0, scale = 0;
  for (int particle = 0; particle < P; ++particle) {
    const int s = scene.slot(particle);
    if (s >= scene.free_count()) continue;
    for (int k = 0; k < 3; ++k) {
      rhs_difference = std::max(rhs_difference, std::abs(fp[3 * (P + particle) + k] - fc[n + 3 * s + k]));
      scale = std::max(scale, std::abs(fc[n + 3 * s + k]));
    }
  }
  // Jacobians as dense matrices over the free coordinates (1200 x 1200 doubles each half: 46 MB in all).
  const auto dense = [](OdeSystem& sys, const std::vector<double>& y) {
    std::vector<sunindextype> starts(static_cast<std::size_t>(sys.size()) + 1), rows(static_cast<std::size_t>(sys.nonzeros()));
    std::vector<double> values(rows.size());
    sys.jacobian(y.data(), starts.data(), rows.data(), values.data());
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(sys.size(), sys.size());
    for (int c = 0; c < sys.size(); ++c)
      for (sunindextype k = starts[c]; k < starts[c + 1]; ++k) J(rows[k], c) += values[k];
    return J;
  };
  const Eigen::MatrixXd Jp = dense(plain, yp), Jc = dense(core, yc);
  double jacobian_difference = 0, jacobian_scale = 0;
  for (int a = 0; a < P; ++a)
    for (int b = 0; b < P; ++b) {
      const int sa = scene.slot(a), sb = scene.slot(b);
      if (sa >= scene.free_count() || sb >= scene.free_count()) continue;
      for (int half = 0; half < 2; ++half)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            const double vp = Jp(3 * (P + a) + i, half * 3 * P + 3 * b + j);
            const double vc = Jc(n + 3 * sa + i, half * n + 3 * sb + j);
            jacobian_difference = std::max(jacobian_difference, std::abs(vp - vc));
            jacobian_scale = std::max(jacobian_scale, std::abs(vc));
          }
    }
  const double rhs_relative = rhs_difference / scale, jacobian_relative = jacobian_difference / jacobian_scale;
  std::printf("plain loop against the book's forces: right-hand side %.1e, Jacobian %.1e (relative)\n",
              rhs_relative, jacobian_relative);
  if (!(rhs_relative < 1e-12 && jacobian_relative < 1e-12))
    throw std::logic_error("ch10_peers: the plain loop and the book's force routine disagree");
  write_text_fragment(dir + "/peers_check.md",
                      format("At a perturbed, moving state the plain loop's accelerations agree with the book's "
                             "to %.0e and its Jacobian to %.0e, relative to their largest entries.",
                             std::max(rhs_relative, 1e-16), std::max(jacobian_relative, 1e-16)));
}

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
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    const std::string dir = opt.run.out_dir;
    prepare_outputs(dir, {"peers.md", "peers_ratio.md", "peers_check.md", "peers.dat"});
    if (quick) runs = std::min(runs, 2);
    const std::string command = reader_command(argc, argv);

    const SceneParams p = ch10::fabric(20, 1e5);
    const Scene scene(p);
    PlainSystem plain(p);
    CoreSystem core(scene);

    check_same_model(scene, plain, core, dir);

    // The reference: as in the chapter's study, RK4 at a quarter of its stable step.
    const double omega = lattice_fastest_frequency({p.stiffness, p.stiffness, p.stiffness, p.mass});
    const auto reference_steps = static_cast<long long>(std::ceil(T / (2 * std::sqrt(2.0) / omega / 4)));
    double agreement = -1;
    Vector reference(3 * scene.particle_count());
    scene.all_positions(ch10::reference(scene, T, reference_steps, false, agreement), reference);
    std::printf("reference: RK4 with %lld steps\n", reference_steps);

    // Explicit methods at 95 % of the lattice's stable step, as in the chapter's sweep.
    const auto stable_steps = [&](double reach) { return static_cast<long long>(std::ceil(T / (0.95 * reach / omega))); };
    const long long rk4_steps = stable_steps(2 * std::sqrt(2.0)), se_steps = stable_steps(2.0);

    std::vector<Row> rows;
    const double budget = quick ? 0.3 : 2.0;  // repeat a configuration while its runs have cost less than this
    const auto record = [&](Row row, const std::function<Outcome()>& run, OdeSystem& system) {
      Outcome out;
      row.seconds = best_time(runs, budget, [&] { out = run(); });
      throw_if_interrupted();
      row.ok = out.ok;
      row.note = out.note;
      if (row.steps == 0) row.steps = out.steps;
      if (out.ok) {
        const Vector x = system.positions(out.y);
        if (x.allFinite() && x.cwiseAbs().maxCoeff() < 100)
          row.error = largest_distance(x, reference);
        else
          row.ok = false, row.note = "diverged";
      }
      std::printf("  %-34s %-18s %7lld steps %8.4f s  error %.2e %s\n", row.program.c_str(), row.setting.c_str(),
                  row.steps, row.seconds, row.error, row.note.c_str());
      rows.push_back(row);
    };
    struct Forces {
      const char* name;
      OdeSystem* system;
    };
    const Forces forces[] = {{"plain loop", &plain}, {"book's forces", &core}};

    // [peer_runs]
    // The quick run keeps the runs that decide the comparison, and of the plain loop's only RK4 and backward
    // Euler.
    for (const Forces& f : forces) {
      const bool plain_loop = f.system == &plain;
      record({format("odeint RK4, %s", f.name), "odeint", "h = " + step_text(rk4_steps), true, "", rk4_steps},
             [&] { return odeint_rk4(*f.system, rk4_steps); }, *f.system);
      for (double tol : quick ? std::vector<double>{1e-3} : std::vector<double>{1e-2, 1e-4, 1e-6})
        if (!quick || !plain_loop)
          record({format("odeint Dormand-Prince, %s", f.name), "odeint", "tol = " + format_number(tol), true, "", 0},
                 [&] { return odeint_dopri5(*f.system, tol); }, *f.system);
      // CVODE grows costly fast as the tolerance tightens (at 1e-4 it takes some 17000 steps): two tolerances
      // show it.
      for (double tol : quick ? std::vector<double>{1e-2} : std::vector<double>{1e-2, 1e-3})
        if (!quick || !plain_loop)
          record({format("CVODE BDF + KLU, %s", f.name), "SUNDIALS", "tol = " + format_number(tol), true, "", 0},
                 [&] { return sundials_run(*f.system, Sundials::cvode_bdf, tol, 0); }, *f.system);
      for (long long steps : quick ? std::vector<long long>{30} : std::vector<long long>{15, 30, 60, 120, 240, 480})
        record({format("ARKODE backward Euler + KLU, %s", f.name), "SUNDIALS", "h = " + step_text(steps), true, "",
                steps},
               [&] { return sundials_run(*f.system, Sundials::arkode_newton, 0, steps); }, *f.system);
      for (long long steps : quick ? std::vector<long long>{30} : std::vector<long long>{15, 30, 60, 120, 240})
        if (!quick || !plain_loop)
          record({format("ARKODE linearly implicit Euler + KLU, %s", f.name), "SUNDIALS", "h = " + step_text(steps),
                  true, "", steps},
                 [&] { return sundials_run(*f.system, Sundials::arkode_linear, 0, steps); }, *f.system);
    }
    // [peer_runs]
    // [book_runs]
    // The book's methods, from the registry (ch10::make_method), on the same scene.
    const auto book = [&](const std::string& method, long long steps) {
      Row row{"book: " + ch10::label(method), "book", "h = " + step_text(steps), true, "", steps};
      const ch10::Run r = ch10::run_to(scene, method, T, steps, quick ? 0.05 : 0.5);
      throw_if_interrupted();
      row.seconds = r.seconds;
      row.ok = r.ok;
      row.note = r.message;
      if (r.ok) {
        Vector all(3 * scene.particle_count());
        scene.all_positions(r.x, all);
        row.error = largest_distance(all, reference);
      }
      std::printf("  %-34s %-18s %7lld steps %8.4f s  error %.2e %s\n", row.program.c_str(), row.setting.c_str(),
                  row.steps, row.seconds, row.error, row.note.c_str());
      rows.push_back(row);
    };
    book("symplectic_euler", se_steps);
    book("rk4", rk4_steps);
    for (long long steps : quick ? std::vector<long long>{30} : std::vector<long long>{15, 30, 60})
      book("implicit_euler/one/cg", steps);
    // [book_runs]

    // The table, and the comparison of the fastest run of each side at each accuracy.
    MarkdownTable table({"program", "setting", "steps", "CPU time [s]", "error at T [m]"}, "llrrr");
    std::string dat = "# side program setting steps cpu_seconds error_at_T\n";
    for (const Row& r : rows) {
      table.add_row({r.program, r.setting, r.ok ? std::to_string(r.steps) : "-", format("%.3g", r.seconds),
                     r.ok ? format("%.2g", r.error) : r.note});
      dat += format("\"%s\" \"%s\" \"%s\" %lld %.6e %.6e\n", r.side.c_str(), r.program.c_str(), r.setting.c_str(),
                    r.steps, r.seconds, r.ok ? r.error : NAN);
    }
    write_table_fragment(dir + "/peers.md", table, command);
    write_text(dir + "/peers.dat", dat);
    std::string ratio;
    for (double tol : {1e-2, 1e-3}) {
      const Row* mine = fastest(rows, true, tol);
      const Row* peer = fastest(rows, false, tol);
      const std::string accuracy = tol == 1e-2 ? "1 cm" : "1 mm";
      if (mine == nullptr || peer == nullptr) {
        ratio += "To " + accuracy + (mine == nullptr ? ", no run of the book's methods" : ", no peer run") +
                 " got there. ";
        continue;
      }
      ratio += format("To %s the fastest peer is %s (%s), %.3g s; the book's fastest is %s (%s), %.3g s: %.2f times "
                      "the peer's time. ",
                      accuracy.c_str(), peer->program.c_str(), peer->setting.c_str(), peer->seconds,
                      mine->program.substr(6).c_str(), mine->setting.c_str(), mine->seconds, mine->seconds / peer->seconds);
      std::printf("%s: book %.4f s (%s %s), peer %.4f s (%s %s), ratio %.3f\n", accuracy.c_str(), mine->seconds,
                  mine->program.c_str(), mine->setting.c_str(), peer->seconds, peer->program.c_str(),
                  peer->setting.c_str(), mine->seconds / peer->seconds);
    }
    write_text_fragment(dir + "/peers_ratio.md", ratio + "\n");
    return 0;
  });
}
