// What particle repulsion leaves out (Chapter 11): two edges of a cloth, each a pair of particles d apart, cross
// at right angles through one another; the response keeps their particles a thickness apart, and yet the edges
// pass through each other when d is large enough beside the thickness.
#include "studies.hpp"

#include "base/format_number.hpp"
#include "contact/self_collision.hpp"
#include "program/fragment.hpp"

#include <Eigen/Geometry>
#include <cmath>

using namespace cloth;

namespace ch11 {

namespace {

struct Crossing {
  double closest;  // least distance between a particle of one edge and one of the other [m]
  bool crossed;    // whether the edges passed through each other
};

// [edge_crossing]
// Edge a = (x0, x1) along x, at height +z0, falls at speed w; edge b = (x2, x3) along y, at -z0, rises at w. The
// response is applied after every step to the four pairs that join the edges, and each edge is then given back
// its length d (its two ends moved alike along it): the edges are rigid, as stiff cloth springs make them. The
// edges have crossed when the signed distance between their lines, (x0 - x2) . (e_a x e_b) / |e_a x e_b|, has
// changed sign while the point where their projections cross lies inside both (Bridson et al. 2002's edge-edge
// test, sampled per step rather than solved in time).
Crossing cross_edges(double d, double thickness) {
  const double z0 = 2 * thickness, w = 1.0, h = 1e-4;
  Eigen::VectorXd x(12), v(12);
  x << -d / 2, 0, z0, d / 2, 0, z0, 0, -d / 2, -z0, 0, d / 2, -z0;
  v << 0, 0, -w, 0, 0, -w, 0, 0, w, 0, 0, w;
  const std::vector<std::pair<int, int>> pairs = {{0, 2}, {0, 3}, {1, 2}, {1, 3}};
  const auto side = [&] {
    const Eigen::Vector3d ea = x.segment<3>(3) - x.segment<3>(0), eb = x.segment<3>(9) - x.segment<3>(6);
    return (x.segment<3>(0) - x.segment<3>(6)).dot(ea.cross(eb).normalized());
  };
  const double start = side();
  Crossing c{1e300, false};
  for (int k = 0; k < static_cast<int>(4 * z0 / (w * h)); ++k) {
    x += h * v;
    resolve_self_contacts(pairs, thickness, x, v);
    for (const int e : {0, 2}) {
      const Eigen::Vector3d along = x.segment<3>(3 * e + 3) - x.segment<3>(3 * e);
      const Eigen::Vector3d fix = 0.5 * (along.norm() - d) * along.normalized();
      x.segment<3>(3 * e) += fix;
      x.segment<3>(3 * e + 3) -= fix;
    }
    for (const auto& [p, q] : pairs) c.closest = std::min(c.closest, (x.segment<3>(3 * p) - x.segment<3>(3 * q)).norm());
  }
  c.crossed = side() * start < 0;
  return c;
}
// [edge_crossing]

}  // namespace

void edge_crossing_study(const Study& study) {
  const double thickness = 0.01;
  MarkdownTable table({"edge length d / thickness", "closest particles [% of thickness]", "edges crossed"}, "rrl");
  for (const double ratio : {1.0, 1.2, 1.4, 1.5, 2.0, 5.0}) {
    const Crossing c = cross_edges(ratio * thickness, thickness);
    table.add_row({format_fixed(ratio, 1), format_fixed(100 * c.closest / thickness, 1), c.crossed ? "yes" : "no"});
  }
  write_table_fragment(study.dir + "/edge_crossing.md", table, study.command);
}

}  // namespace ch11
