// Chapter 12's real fabrics: the standard's 41.5 degree reading done on simulated strips of measured fabrics, against
// the bending length their measured rigidity implies (fabrics.md), and each strip beside its elastica (fabrics.dat).
#include "report.hpp"

#include "analysis/cantilever.hpp"
#include "analysis/elastica.hpp"
#include "base/format_number.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"
#include "program/output.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

using namespace cloth;

namespace {

// A fabric of the ClothDrapeTester data set, dataset/dataset.csv: areal density in kg/m^2 and the linear part of
// the cantilever-measured warp bending stiffness in 1e-9 N m (the header's "SI*1e9"). That this is B per unit
// width, in N m, the authors' own code says: their cantilever check (bending_validation/Main.m) plots against
// rho_A g L^3 / B with rho_A in kg/m^2 and L in m, and their hinge force (DihedralBendingHessianForce.m) is
// B |e| kappa dtheta/dx, the gradient of B kappa^2 / 2 per area. Rows are counted after the header.
struct Fabric {
  const char* name;
  double areal_density;     // [kg/m^2]
  double bending_rigidity;  // [N m], warp
};

constexpr Fabric fabrics[] = {
    {"light (row 1)", 0.0673, 1779.9e-9},
    {"medium (row 6)", 0.1972, 9183.1e-9},
    {"stiff (row 3)", 0.1834, 61211.1e-9},
    {"heavy (row 4)", 0.2776, 68681.4e-9},
};

// The hinge strip of length L, 20 spacings along it, 2.5 cm wide.
CantileverParams fabric_strip(const Fabric& f, double L) {
  CantileverParams p;
  p.model = BendingModel::hinge;
  p.overhang = L;
  p.spacing = L / 20;
  p.width = 0.025;
  p.areal_density = f.areal_density;
  p.bending_rigidity = f.bending_rigidity;
  return p;
}

// The strip at rest, from the elastica's shape.
CantileverRest at_rest(Cantilever& strip) {
  throw_if_interrupted();
  const CantileverRest rest = strip.rest_shape(CantileverStart::elastica, 1e-9, 300, &interrupt_flag());
  throw_if_interrupted();
  return rest;
}

// The tip chord's angle of the strip of length L at rest.
double chord_angle(const Fabric& f, double L) {
  Cantilever strip(fabric_strip(f, L));
  return at_rest(strip).chord_angle;
}

// The overhang at which the simulated strip's tip chord reaches 41.5 degrees, by bisection on L: the standard's
// reading done on the simulated fabric.
double simulated_reading(const Fabric& f) {
  const double standard_angle = 41.5 * std::numbers::pi / 180;
  const double c = std::cbrt(f.bending_rigidity / (f.areal_density * 9.81));
  double low = 1.5 * c, high = 2.5 * c;
  while (high - low > 1e-4 * c) {
    const double L = 0.5 * (low + high);
    if (chord_angle(f, L) < standard_angle) low = L;
    else high = L;
  }
  return 0.5 * (low + high);
}

}  // namespace

// fabrics.dat: per fabric, two gnuplot index blocks, the elastica at the reading's lambda and the simulated strip at
// rest, as centre lines (x, z) in cm from the clamp; the strip's block opens with its title for the figure's key.
void write_fabrics(const std::string& dir, const std::string& command) {
  MarkdownTable table({"fabric", "rho_A [kg/m^2]", "B [1e-6 N m]", "c = (B / (rho_A g))^(1/3) [cm]",
                       "overhang at 41.5 degrees, hinge [cm]", "bending length read, L / 2 [cm]", "difference"},
                      "lrrrrrr");
  OutputFile file(dir + "/fabrics.dat");
  std::FILE* out = file.get();
  std::fprintf(out, "# the standard's reading on each fabric: x [cm] along the clamp's direction, z [cm] up\n");
  for (const Fabric& f : fabrics) {
    const double c = std::cbrt(f.bending_rigidity / (f.areal_density * 9.81));
    const double L = simulated_reading(f);
    table.add_row({f.name, format_number(f.areal_density, 4), format_significant(1e6 * f.bending_rigidity, 4),
                   format_fixed(100 * c, 3), format_fixed(100 * L, 3), format_fixed(50 * L, 3),
                   format_significant(100 * (L / 2 / c - 1), 2) + " %"});
    Cantilever strip(fabric_strip(f, L));
    const CantileverRest rest = at_rest(strip);
    const ElasticaShape exact = heavy_elastica(strip.lambda(), 200);
    std::fprintf(out, "# %s: the heavy elastica, lambda = %.6g, L = %.6g cm\n", f.name, strip.lambda(), 100 * L);
    for (std::size_t k = 0; k < exact.x.size(); ++k)
      std::fprintf(out, "%.8g %.8g\n", 100 * L * exact.x[k], -100 * L * exact.y[k]);
    std::fprintf(out, "\n\n\"%s, c = %s cm\" \"\"\n", f.name, format_fixed(100 * c, 2).c_str());
    write_centre_line(out, strip, rest.x, 0.01);
    std::fprintf(out, "\n\n");
  }
  file.commit();
  write_table_fragment(dir + "/fabrics.md", table, command);
}
