// Chapter 1: the spring model. Counts each family's springs, tabulates force against extension and the energy of
// a uniformly stretched sheet, and checks that the forces are minus the gradient of the energy.
#include "program/command_line.hpp"
#include "base/format_number.hpp"
#include "base/input_error.hpp"
#include "model/force_field.hpp"
#include "program/fragment.hpp"
#include "program/limits.hpp"
#include "program/output.hpp"
#include "program/output_spec.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

using namespace cloth;

namespace {

// The files the program writes into --out, declared once (program/output_spec.hpp).
OutputList outputs() {
  return {{"spring_counts.md", OutputKind::fragment, "each family's springs beside the closed forms"},
          {"gradient_check.md", OutputKind::fragment, "f against -grad E on a randomly perturbed sheet"},
          {"gradient_check.txt", OutputKind::data, "the largest relative difference of that check"},
          {"force_extension.dat", OutputKind::figure_input, "force and energy of one spring per family against l"},
          {"stretch_energy.dat", OutputKind::figure_input, "energy of the uniformly stretched sheet, per family"},
          {"springs.dat", OutputKind::figure_input, "one segment (flexion: an arc) per spring of the rest mesh"}};
}

// [gradient_check]
// Largest relative difference between f(x) and -grad E(x), the gradient taken by central differences
// (E - E)/(2 eps) per coordinate. With D = 0 the forces are conservative, so the two must agree to O(eps^2).
double gradient_check(ForceField& field, const Vector& x) {
  const Vector v = Vector::Zero(x.size());
  Vector f(x.size());
  field.forces(x, v, f);
  const double eps = 1e-6;
  Vector xp = x;
  double worst = 0;
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    xp[k] = x[k] + eps;
    const double e_plus = field.energy(xp, v).total();
    xp[k] = x[k] - eps;
    const double e_minus = field.energy(xp, v).total();
    xp[k] = x[k];
    const double minus_grad = -(e_plus - e_minus) / (2 * eps);
    worst = std::max(worst, std::abs(f[k] - minus_grad) / std::max(1.0, std::abs(f[k])));
  }
  return worst;
}
// [gradient_check]

// The springs of each family, printed and as the page's table beside the closed forms of cloth::spring_count.
void spring_counts(const Scene& scene, const std::string& dir, const std::string& command) {
  const Grid& g = scene.grid();
  std::printf("grid %dx%d, spacing %g m: %d particles, %d free\n", g.M, g.N, g.d, scene.particle_count(),
              scene.free_count());
  for (SpringFamily f : all_spring_families)
    std::printf("  %-10s springs: %4d (closed form %d), rest length %.6g m\n", family_name(f),
                scene.springs().count(f), spring_count(f, g.M, g.N),
                scene.springs().count(f) ? scene.springs().springs[static_cast<std::size_t>(
                                               scene.springs().family[static_cast<int>(f)].begin)].rest_length
                                         : 0.0);
  std::printf("  total      springs: %4d\n", scene.springs().size());
  MarkdownTable counts({"family", "springs built", "closed form", "rest length [m]"}, "lrrr");
  for (SpringFamily f : all_spring_families) {
    const SpringRange r = scene.springs().family[static_cast<int>(f)];
    const std::string rest_length =
        r.end > r.begin ? format_number(scene.springs().springs[static_cast<std::size_t>(r.begin)].rest_length)
                        : "(none)";
    counts.add_row({family_name(f), std::to_string(scene.springs().count(f)),
                    std::to_string(spring_count(f, g.M, g.N)), rest_length});
  }
  counts.add_row({"all", std::to_string(scene.springs().size()), "", ""});
  write_table_fragment(dir + "spring_counts.md", counts, command);
}

// Force along the spring, K (L0 - l), and its energy, for one spring of each family, l from 0 to 2 L0.
void force_extension(const Scene& scene, const std::string& dir) {
  const Grid& g = scene.grid();
  OutputFile file(dir + "force_extension.dat");
  std::FILE* out = file.get();
  std::fprintf(out, "# family(0 structural,1 shear,2 flexion) L0 l l/L0 force_along_u energy\n");
  for (SpringFamily f : all_spring_families) {
    const double L0 = f == SpringFamily::structural ? g.d : f == SpringFamily::shear ? g.d * std::sqrt(2.0) : 2 * g.d;
    const double K = scene.stiffness(f);
    for (int k = 0; k <= 200; ++k) {
      const double l = 2.0 * L0 * k / 200;
      std::fprintf(out, "%d %.10g %.10g %.10g %.10g %.10g\n", static_cast<int>(f), L0, l, l / L0, K * (L0 - l),
                   0.5 * K * (l - L0) * (l - L0));
    }
    std::fprintf(out, "\n\n");
  }
  file.commit();
}

// Spring energy of the sheet stretched uniformly by s in x and y: every spring is s L0 long, so
// E(s) = 1/2 K (s - 1)^2 sum L0^2, a parabola per family; the program measures it through the model.
void stretch_energy(const Scene& scene, const SceneParams& params, const std::string& dir) {
  OutputFile file(dir + "stretch_energy.dat");
  std::FILE* out = file.get();
  std::fprintf(out, "# s E_structural E_shear E_flexion E_total E_closed_form\n");
  double sum_L0_squared = 0;
  for (const Spring& s : scene.springs().springs) sum_L0_squared += s.rest_length * s.rest_length;
  for (int k = 0; k <= 100; ++k) {
    const double s = 0.5 + k / 100.0;
    std::fprintf(out, "%.6g", s);
    double total = 0;
    for (SpringFamily f : all_spring_families) {
      // One family alone, with nothing pinned, so that every spring is stretched to exactly s L0.
      SceneParams sheet = params;
      sheet.families = FamilySet::only(f);
      sheet.pins = PinSet::none;
      const Scene one(sheet);
      ForceField one_field(one);
      Vector x = one.initial_positions();
      for (Eigen::Index i = 0; i < x.size(); i += 3) x[i] *= s, x[i + 1] *= s;
      const double e = one_field.energy(x, Vector::Zero(x.size())).spring;
      total += e;
      std::fprintf(out, " %.10g", e);
    }
    std::fprintf(out, " %.10g %.10g\n", total, 0.5 * params.stiffness * (s - 1) * (s - 1) * sum_L0_squared);
  }
  file.commit();
}

// The rest mesh for the figure of the three families: one line segment per spring. Flexion springs would lie
// on top of each other ((i,j)-(i+2,j) overlaps (i+1,j)-(i+3,j)), so they are drawn as shallow arcs bulging
// to alternate sides; the figure is a picture of the topology, not of positions.
void spring_mesh(const Scene& scene, const std::string& dir) {
  const Grid& g = scene.grid();
  OutputFile file(dir + "springs.dat");
  std::FILE* out = file.get();
  for (SpringFamily f : all_spring_families) {
    std::fprintf(out, "# %s\n", family_name(f));
    const SpringRange r = scene.springs().family[static_cast<int>(f)];
    for (int k = r.begin; k < r.end; ++k) {
      const Spring& s = scene.springs().springs[static_cast<std::size_t>(k)];
      const Eigen::Vector3d p = scene.rest_positions().segment<3>(3 * s.p);
      const Eigen::Vector3d q = scene.rest_positions().segment<3>(3 * s.q);
      if (f != SpringFamily::flexion) {
        std::fprintf(out, "%g %g\n%g %g\n\n", p[0], p[1], q[0], q[1]);
        continue;
      }
      const int particle = scene.particle_of_slot(s.p);
      const double side = (particle / g.N + particle % g.N) % 2 == 0 ? 1.0 : -1.0;
      const Eigen::Vector3d normal(-(q - p)[1] / (q - p).norm(), (q - p)[0] / (q - p).norm(), 0.0);
      for (int t = 0; t <= 16; ++t) {
        const double a = t / 16.0;
        const Eigen::Vector3d point = p + a * (q - p) + side * 0.25 * g.d * 4 * a * (1 - a) * normal;
        std::fprintf(out, "%g %g\n", point[0], point[1]);
      }
      std::fprintf(out, "\n");
    }
    std::fprintf(out, "\n");
  }
  file.commit();
}

// f = -grad E on a random configuration: rest positions perturbed by up to 30% of d, so that some springs are
// stretched and some compressed. Returns the largest relative difference.
double check_gradient(const Scene& scene, const std::string& dir, const std::string& command) {
  const Grid& g = scene.grid();
  ForceField field(scene);
  std::mt19937 rng(2019);
  std::uniform_real_distribution<double> jitter(-0.3 * g.d, 0.3 * g.d);
  Vector x = scene.initial_positions();
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] += jitter(rng);
  const double worst = gradient_check(field, x);
  const Energy e = field.energy(x, Vector::Zero(x.size()));
  std::printf("randomly perturbed sheet (every coordinate moved by up to 0.3 d): spring energy %.3g J, "
              "gravity energy %.3g J\n", e.spring, e.gravity);
  std::printf("f = -grad E by central differences (eps = 1e-6) on a randomly perturbed sheet: largest relative "
              "error %.2e\n", worst);
  char line[64];
  std::snprintf(line, sizeof line, "largest_relative_error = %.3e\n", worst);
  write_text(dir + "gradient_check.txt", line);
  MarkdownTable check({"randomly perturbed sheet (every coordinate moved by up to 0.3 d)", "measured"}, "lr");
  check.add_row({"spring energy", format_number(e.spring, 3) + " J"});
  check.add_row({"gravity energy", format_number(e.gravity, 3) + " J"});
  check.add_row({"largest relative difference between f and -grad E (central differences, eps = 1e-6)",
                 format_number(worst, 3)});
  write_table_fragment(dir + "gradient_check.md", check, command);
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  CommandLine cli("ch01_springs",
                  "Chapter 1: the report's mass-spring cloth. Counts springs, tabulates force against extension and\n"
                  "the energy of a uniformly stretched sheet, and checks f = -grad E by central differences.");
  // An experiment program: the scene flags it builds its sheet from, no damping (the check needs conservative
  // forces) and no run flags.
  cli.use_common({"--grid", "--spacing", "--mass", "--K", "--springs", "--pins", "--out"});
  cli.declare_outputs([](const Options&) { return outputs(); });
  return run_program(cli.program(), [&] {
    Options opt = cli.parse(argc, argv);
    opt.scene.damping = 0;  // the gradient check needs conservative forces
    // The gradient check evaluates the whole energy twice per coordinate: its time grows as (M N)^2.
    constexpr long long largest_checked_grid = 40'000;
    if (static_cast<long long>(opt.scene.grid.M) * opt.scene.grid.N > largest_checked_grid)
      throw InputError("--grid: the gradient check takes time growing as (M N)^2; expected at most " +
                       std::to_string(largest_checked_grid) + " particles (200x200)");
    require_memory(static_cast<double>(opt.scene.grid.M) * opt.scene.grid.N * explicit_bytes_per_particle(), "--grid",
                   "the scene");
    const Scene scene(opt.scene);
    prepare_declared_outputs(opt.run.out_dir, outputs());
    const std::string dir = opt.run.out_dir + "/";
    const std::string command = reader_command(argc, argv);
    spring_counts(scene, dir, command);             // how many springs of each family: spring_counts.md
    force_extension(scene, dir);                    // force against length, one spring per family
    stretch_energy(scene, opt.scene, dir);          // the energy of the uniformly stretched sheet
    spring_mesh(scene, dir);                        // the three families drawn on the rest mesh
    const double worst = check_gradient(scene, dir, command);  // f = -grad E: gradient_check.md
    if (worst >= 1e-6) {  // the forces are not the energy's gradient: a bug in the model, so an internal error
      std::fprintf(stderr, "ch01_springs: internal error: f = -grad E fails by %.2e (expected < 1e-6)\n", worst);
      return 1;
    }
    return 0;
  });
}
