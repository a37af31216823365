// Chapter 12's real fabrics: the standard's 41.5 degree reading done on simulated strips of measured fabrics, against
// the bending length their measured rigidity implies (fabrics.md).
#include "report.hpp"

#include "analysis/cantilever.hpp"
#include "base/format_number.hpp"
#include "program/fragment.hpp"
#include "program/interrupt.hpp"

#include <cmath>
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

// The tip chord's angle of the hinge strip of length L at rest, 20 spacings along it, 2.5 cm wide.
double chord_angle(const Fabric& f, double L) {
  throw_if_interrupted();
  CantileverParams p;
  p.model = BendingModel::hinge;
  p.overhang = L;
  p.spacing = L / 20;
  p.width = 0.025;
  p.areal_density = f.areal_density;
  p.bending_rigidity = f.bending_rigidity;
  Cantilever strip(p);
  const CantileverRest rest = strip.rest_shape(CantileverStart::elastica, 1e-9, 300, &interrupt_flag());
  throw_if_interrupted();
  return rest.chord_angle;
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

void write_fabrics(const std::string& dir, const std::string& command) {
  MarkdownTable table({"fabric", "rho_A [kg/m^2]", "B [1e-6 N m]", "c = (B / (rho_A g))^(1/3) [cm]",
                       "overhang at 41.5 degrees, hinge [cm]", "bending length read, L / 2 [cm]", "difference"},
                      "lrrrrrr");
  for (const Fabric& f : fabrics) {
    const double c = std::cbrt(f.bending_rigidity / (f.areal_density * 9.81));
    const double L = simulated_reading(f);
    table.add_row({f.name, format_number(f.areal_density, 4), format_number(1e6 * f.bending_rigidity, 4),
                   format_fixed(100 * c, 3), format_fixed(100 * L, 3), format_fixed(50 * L, 3),
                   format_number(100 * (L / 2 / c - 1), 2) + " %"});
  }
  write_table_fragment(dir + "/fabrics.md", table, command);
}
