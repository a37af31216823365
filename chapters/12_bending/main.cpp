// Chapter 12: bending that holds a shape. One strip in the cantilever test of textile laboratories, clamped level
// and bent by its own weight, with a chosen bending model; its rest shape against the heavy elastica. With
// --report-runs, the chapter's figures and tables (report.cpp, cost.cpp); with --drape-runs, the curtain with and
// without bending (drape.cpp).
#include "report.hpp"

#include "analysis/cantilever.hpp"
#include "analysis/elastica.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "program/command_line.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

using namespace cloth;

namespace {

// The outputs of one strip: its rest shape and what it measured.
OutputList single_outputs() {
  return {{"final.dat", OutputKind::data, "the strip's rest shape, final.dat's format (model page)"},
          {"run.txt", OutputKind::data, "the strip, its model, how close to rest, and its tip against the elastica"}};
}

// The flags the cantilever's own geometry replaces: its grid follows from --overhang, --spacing and the width,
// and its clamp is the pin set. Refused when given at all, whatever their value.
void refuse_scene_flags(int argc, char** argv) {
  for (int k = 1; k < argc; ++k) {
    const std::string flag = argv[k];
    if (flag == "--grid")
      throw InputError("--grid: the cantilever's grid follows from --overhang, --spacing and its 2.5 cm width: "
                       "expected no --grid with --scene cantilever");
    if (flag == "--pins")
      throw InputError("--pins: the cantilever is held by its clamp, its first two rows of particles: expected no "
                       "--pins with --scene cantilever");
  }
}

// One strip: its rest shape from the elastica start, final.dat, and run.txt with what a reader needs to check it
// against an elastica of their own. Exit status 3 when Newton's method did not reach rest, 128 + the signal
// when a signal stopped it (the shape reached so far is written).
int single_strip(const CantileverParams& params, const std::string& dir, const std::string& program) {
  Cantilever strip(params);
  const CantileverRest rest = strip.rest_shape(CantileverStart::elastica, 1e-9, 300, &interrupt_flag());
  const Scene& scene = strip.scene();
  write_final(dir + "/final.dat", scene, rest.x, Vector::Zero(scene.dof_count()));
  const ElasticaShape exact = heavy_elastica(strip.lambda());
  const double deg = 180 / std::numbers::pi;
  const auto num = [](double x) { return format_number(x, 10); };
  const Grid& g = scene.grid();
  write_key_values(dir + "/run.txt", {
      {"scene", "cantilever"},
      {"bending", bending_models().name(params.model)},
      {"grid", std::to_string(g.M) + "x" + std::to_string(g.N)},
      {"spacing", num(params.spacing)},
      {"mass", num(params.areal_density * params.spacing * params.spacing)},
      {"K", num(params.stiffness)},
      {"overhang", num(params.overhang)},
      {"width", num((g.N - 1) * params.spacing)},
      {"areal_density", num(params.areal_density)},
      {"bending_rigidity", num(params.bending_rigidity)},
      {"gravity", num(params.gravity)},
      {"bending_length", num(std::cbrt(params.bending_rigidity / (params.areal_density * params.gravity)))},
      {"lambda", num(strip.lambda())},
      {"method", "static_equilibrium"},
      {"start", "elastica"},
      {"iterations", std::to_string(rest.iterations)},
      {"residual", num(rest.residual)},
      {"residual_per_weight", num(rest.residual / rest.weight)},
      {"tip_deflection", num(rest.tip_deflection)},
      {"tip_x", num(rest.tip_x)},
      {"chord_angle_degrees", num(rest.chord_angle * deg)},
      {"elastica_tip_deflection", num(exact.tip_deflection * params.overhang)},
      {"elastica_chord_angle_degrees", num(exact.chord_angle * deg)},
      {"status", rest.interrupted ? "interrupted" : rest.converged ? "ok" : "not_at_rest"},
  });
  // Interrupted: the shape reached so far is kept, and run_program exits with 128 + the signal.
  if (rest.interrupted) throw Interrupted{interrupt_signal()};
  if (!rest.converged) {
    std::cerr << program << ": static equilibrium not reached in " << rest.iterations << " Newton iterations: the "
              << "largest force left is " << format_number(rest.residual, 3) << " N, "
              << format_number(rest.residual / rest.weight, 3) << " particle weights\n";
    return 3;
  }
  std::printf("%s: %s strip, L = %g m, rest in %d Newton iterations: tip %.6g m below the clamp (elastica %.6g m), "
              "tip chord %.4g degrees\n", program.c_str(), bending_models().name(params.model), params.overhang,
              rest.iterations, rest.tip_deflection, exact.tip_deflection * params.overhang, rest.chord_angle * deg);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CantileverParams params;
  bool report = false, full = false, drape = false;
  CommandLine cli("ch12_bending",
                  "Chapter 12: a strip in the cantilever test, clamped level and bent by its own weight, with a\n"
                  "bending model; its rest shape against the heavy elastica.");
  cli.use_common({"--grid", "--spacing", "--mass", "--K", "--pins", "--bending", "--bending-rigidity", "--out"});
  cli.set_default("--spacing", "0.0025");
  cli.set_default("--mass", "1.25e-6");
  cli.set_default("--K", "1e4");
  cli.set_default("--bending", "hinge");
  cli.add_value("--scene", "cantilever", "the scene: the cantilever strip (the only one)", [](const std::string& s) {
    if (s != "cantilever") throw InputError("unknown scene '" + s + "': expected cantilever");
  });
  params.overhang = 0.05;
  cli.add_value("--overhang", "L", "length of the strip beyond the clamp [m], a whole number of spacings "
                                   "(default 0.05)", [&](const std::string& s) {
    params.overhang = parse_number(s);
    if (!(params.overhang > 0)) throw InputError("expected a number > 0, got " + s);
  });
  cli.add_switch("--report-runs", "the chapter's figures and tables: shapes, convergence, fabrics, cost",
                 [&] { report = true; });
  cli.add_switch("--drape-runs", "the curtain of Chapter 10 hanging with and without bending, and its cost",
                 [&] { drape = true; });
  cli.add_switch("--full", "with --report-runs: the convergence study down to L/160, the flexion strip's to L/80 (about a minute)", [&] { full = true; });
  cli.declare_outputs([&](const Options&) {
    return drape ? drape_outputs() : report ? report_outputs() : single_outputs();
  });
  return run_program(cli.program(), [&] {
    const Options opt = cli.parse(argc, argv);
    if (full && !report) throw InputError("--full: it widens --report-runs: expected --report-runs with it");
    refuse_scene_flags(argc, argv);
    params.spacing = opt.scene.grid.d;
    params.areal_density = opt.scene.mass / (params.spacing * params.spacing);
    params.stiffness = opt.scene.stiffness;
    params.model = opt.scene.bending;
    params.bending_rigidity = opt.scene.bending_rigidity;
    if (report && drape) throw InputError("--drape-runs: expected either --report-runs or --drape-runs, not both");
    if (drape) {
      prepare_declared_outputs(opt.run.out_dir, drape_outputs(), single_outputs() + report_outputs());
      return drape_runs(opt.run.out_dir, reader_command(argc, argv));
    }
    if (report) {
      prepare_declared_outputs(opt.run.out_dir, report_outputs(), single_outputs() + drape_outputs());
      return report_runs(opt.run.out_dir, full, reader_command(argc, argv));
    }
    try {
      cantilever_grid(params);  // the strip's size is checked before anything is written
    } catch (const InputError& e) {
      throw InputError(std::string("--overhang, --spacing: ") + e.what());
    }
    prepare_declared_outputs(opt.run.out_dir, single_outputs(), report_outputs() + drape_outputs());
    return single_strip(params, opt.run.out_dir, cli.program());
  });
}
