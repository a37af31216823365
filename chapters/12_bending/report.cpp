// Chapter 12's measurements, each a function writing its data file or its table fragment.
#include "report.hpp"

#include "analysis/cantilever.hpp"
#include "analysis/elastica.hpp"
#include "base/format_number.hpp"
#include "model/bending.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"
#include "program/output_kinds.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

using namespace cloth;

namespace {

constexpr double deg = std::numbers::pi / 180;
constexpr BendingModel all_models[] = {BendingModel::hinge, BendingModel::quadratic, BendingModel::flexion};

// The book's test strip: L = 0.1 m, rho_A = 0.2 kg/m^2, B set by lambda = (L / c)^3, `cells` spacings along it.
CantileverParams test_strip(BendingModel model, double lambda, int cells) {
  CantileverParams p;
  p.model = model;
  p.overhang = 0.1;
  p.spacing = p.overhang / cells;
  p.areal_density = 0.2;
  p.bending_rigidity = p.areal_density * p.gravity * std::pow(p.overhang, 3) / lambda;
  return p;
}


// The flexion strip is solved to 1e-4 particle weights, not 1e-9: its Newton iteration converges linearly (the
// springs' bending energy is quartic in the angle, flat at the straight tip) and then stalls where a step's change
// of the energy is below the energy's rounding and the line search can no longer tell a better shape from a worse
// one: near 4e-7 weights at L/40, 3e-5 at L/80. What is left is the stiff springs' stretch: the tip at 30 weights
// already agrees with the one at 3e-5 to one part in 1e7 (L/80), far below the tens of percent the table shows.
CantileverRest measure(const CantileverParams& p) {
  throw_if_interrupted();
  Cantilever strip(p);
  const bool flexion = p.model == BendingModel::flexion;
  const CantileverRest rest = strip.rest_shape(CantileverStart::elastica, flexion ? 1e-4 : 1e-9,
                                               flexion ? 4000 : 300, &interrupt_flag());
  throw_if_interrupted();
  return rest;
}

// shapes.dat: per lambda, the elastica and each model's strip at L/20, as the centre line (x / L, z / L); one
// gnuplot index block per curve, four per lambda in the order elastica, hinge, quadratic, flexion. shapes.md: the
// same strips' tip deflection w / L and tip chord angle beside the elastica's.
void write_shapes(const std::string& dir, const std::string& command) {
  OutputFile file(dir + "/shapes.dat");
  std::FILE* out = file.get();
  std::fprintf(out, "# the strip's centre line at rest, x / L along the clamp's direction, z / L (up); L/20\n");
  MarkdownTable table({"lambda", "elastica: w / L, chord", "hinge", "quadratic", "flexion springs"}, "rllll");
  const auto cell = [](double w, double chord) {
    return format_fixed(w, 4) + ", " + format_fixed(chord / deg, 2) + " degrees";
  };
  for (const double lambda : {1.0, 8.0, 40.0}) {
    const ElasticaShape exact = heavy_elastica(lambda, 200);
    std::vector<std::string> row = {format_number(lambda), cell(exact.tip_deflection, exact.chord_angle)};
    std::fprintf(out, "# lambda %g elastica\n", lambda);
    for (std::size_t k = 0; k < exact.x.size(); ++k) std::fprintf(out, "%.8g %.8g\n", exact.x[k], -exact.y[k]);
    for (const BendingModel model : all_models) {
      const CantileverParams p = test_strip(model, lambda, 20);
      const CantileverRest rest = measure(p);
      row.push_back(rest.converged ? cell(rest.tip_deflection / p.overhang, rest.chord_angle) : "not at rest");
      std::fprintf(out, "\n\n# lambda %g %s (%s)\n", lambda, bending_models().name(model),
                   rest.converged ? "at rest" : "not at rest");
      write_centre_line(out, Cantilever(p), rest.x, p.overhang);
    }
    std::fprintf(out, "\n\n");
    table.add_row(row);
  }
  file.commit();
  write_table_fragment(dir + "/shapes.md", table, command);
}

// convergence.dat and convergence.md: the tip deflection's relative error against the elastica at lambda = 8 as
// the spacing halves, for each model, with the Newton iterations each rest shape took (no times: one run of each
// strip, on a shared machine, would be a timing without its spread).
void write_convergence(const std::string& dir, bool full, const std::string& command) {
  const double lambda = 8;
  const double exact = heavy_elastica(lambda).tip_deflection * 0.1;
  std::vector<int> cells = {5, 10, 20, 40};
  if (full) cells.insert(cells.end(), {80, 160});
  OutputFile file(dir + "/convergence.dat");
  std::FILE* out = file.get();
  std::fprintf(out, "# lambda = 8, L = 0.1 m: cells d/L then |relative tip error| and Newton iterations for hinge, "
                    "quadratic, flexion, and hinge with springs 100 times stiffer (nan: not at rest)\n");
  MarkdownTable table({"spacing", "hinge: tip error", "quadratic: tip error", "flexion springs: tip error",
                       "hinge, K x 100: tip error", "hinge: Newton iterations", "flexion: Newton iterations"},
                      "lrrrrrr");
  const auto percent = [&](const CantileverRest& rest) {
    return rest.converged ? format_significant(100 * (rest.tip_deflection / exact - 1), 3) + " %" : "not at rest";
  };
  for (const int n : cells) {
    std::fprintf(out, "%d %.6g", n, 1.0 / n);
    std::vector<std::string> row = {"L/" + std::to_string(n)};
    std::string hinge_work, flexion_work;
    for (const BendingModel model : all_models) {
      // The flexion strip converges linearly, 1662 Newton iterations at L/80, each several times dearer at L/160:
      // it stops at L/80, where its error has long stopped falling.
      if (model == BendingModel::flexion && n > 80) {
        std::fprintf(out, " nan 0");
        row.push_back("not run");
        flexion_work = "not run";
        continue;
      }
      const CantileverRest rest = measure(test_strip(model, lambda, n));
      std::fprintf(out, " %.6e %d", rest.converged ? std::abs(rest.tip_deflection / exact - 1) : NAN,
                   rest.iterations);
      row.push_back(percent(rest));
      if (model == BendingModel::hinge) hinge_work = std::to_string(rest.iterations);
      if (model == BendingModel::flexion) flexion_work = std::to_string(rest.iterations);
    }
    // The same hinge strip with springs 100 times stiffer: the stretch under its own weight, a part of the error
    // that does not fall with d, shrinks with it.
    CantileverParams stiff = test_strip(BendingModel::hinge, lambda, n);
    stiff.stiffness *= 100;
    const CantileverRest rest = measure(stiff);
    std::fprintf(out, " %.6e %d\n", rest.converged ? std::abs(rest.tip_deflection / exact - 1) : NAN,
                 rest.iterations);
    row.push_back(percent(rest));
    row.push_back(hinge_work);
    row.push_back(flexion_work);
    table.add_row(row);
  }
  file.commit();
  write_table_fragment(dir + "/convergence.md", table, command);
}

// split.md: one triangulation against both, on the same strip: the coupling of bending to twist.
void write_split(const std::string& dir, const std::string& command) {
  const double lambda = 1;
  const double exact = heavy_elastica(lambda).tip_deflection * 0.1;
  MarkdownTable table({"spacing", "one triangulation: tip error", "both, at half weight: tip error"}, "lrr");
  for (const int n : {20, 40}) {
    std::vector<std::string> row = {"L/" + std::to_string(n)};
    for (const GridSplit split : {GridSplit::uniform, GridSplit::both}) {
      CantileverParams p = test_strip(BendingModel::hinge, lambda, n);
      p.split = split;
      row.push_back(format_significant(100 * (measure(p).tip_deflection / exact - 1), 3) + " %");
    }
    table.add_row(row);
  }
  write_table_fragment(dir + "/split.md", table, command);
}

// peirce.md: the tip chord's angle against lambda, from the elastica and from Peirce's formula.
void write_peirce(const std::string& dir, const std::string& command) {
  MarkdownTable table({"tip chord [degrees]", "lambda, elastica", "lambda, Peirce", "c / L, elastica",
                       "c / L, Peirce"}, "rrrrr");
  for (const double angle : {5.0, 15.0, 30.0, 41.5, 50.0, 60.0}) {
    const double exact = elastica_lambda_for_chord(angle * deg), peirce = peirce_lambda(angle * deg);
    table.add_row({format_number(angle), format_fixed(exact, 4), format_fixed(peirce, 4),
                   format_fixed(std::cbrt(1 / exact), 4), format_fixed(std::cbrt(1 / peirce), 4)});
  }
  write_table_fragment(dir + "/peirce.md", table, command);
}

}  // namespace

void write_centre_line(std::FILE* out, const Cantilever& strip, const Vector& x, double unit) {
  const Grid& g = strip.scene().grid();
  std::fprintf(out, "0 0\n");  // the clamp line, row 1: row 0 behind it holds the slope
  for (int i = 2; i < g.M; ++i) {
    double xi = 0, zi = 0;
    for (int j = 0; j < g.N; ++j) {
      const int s = strip.scene().slot(g.particle(i, j));
      xi += x[3 * s] / g.N;
      zi += x[3 * s + 2] / g.N;
    }
    std::fprintf(out, "%.8g %.8g\n", (xi - g.d) / unit, zi / unit);
  }
}

OutputList report_outputs() {
  using namespace cloth::output_kinds;
  return {{"shapes.dat", figure, "the strips' centre lines at rest against the elastica, per lambda and model"},
          {"shapes.md", fragment, "the same strips' tip deflection and tip chord angle beside the elastica's"},
          {"convergence.dat", figure, "the tip deflection's error against the elastica as the spacing halves"},
          {"convergence.md", fragment, "the same errors per model, with the hinge and flexion strips' Newton iterations"},
          {"split.md", fragment, "one triangulation against both superposed, tip errors"},
          {"peirce.md", fragment, "lambda for each tip chord angle, elastica against Peirce's formula"},
          {"fabrics.md", fragment, "the standard's 41.5 degree reading on simulated real fabrics"},
          {"fabrics.dat", figure, "each fabric's strip at the reading's overhang and its elastica, in cm"},
          {"cost.md", fragment, "one force and one Hessian evaluation of each bending term beside the springs'"},
          {"stable_step.md", fragment, "the fastest bending mode against the springs' as the spacing halves"},
          {"rolled.md", fragment, "a rolled sheet released: XPBD and local/global with bending against implicit Euler"}};
}

int report_runs(const std::string& dir, bool full, const std::string& command) {
  write_shapes(dir, command);                 // 1. the shapes against the elastica
  write_convergence(dir, full, command);      // 2. convergence with the spacing, per model
  write_split(dir, command);                  // 3. one triangulation or both
  write_peirce(dir, command);                 // 4. Peirce's formula against the elastica
  write_fabrics(dir, command);                // 5. the standard's reading on real fabrics
  write_cost(dir, command);                   // 6. what bending costs beside the springs
  write_stable_step(dir, command);            // 7. and what it does to the explicit step
  write_rolled(dir, command);                 // 8. bending in XPBD and local/global
  return 0;
}
