// The bending energies of Chapter 12 against independent truth: the dihedral angle's gradient and Hessian and
// both models' forces and Hessians against central differences; zero energy and force on a flat sheet and
// invariance under rigid motion; a sheet bent uniformly into a cylinder against the continuum energy
// B kappa^2 / 2 per area about a grid line, and the multiples the page derives about the diagonals and in twist,
// for one triangulation and for both.
#include <doctest/doctest.h>

#include "model/bending.hpp"
#include "random_state.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <random>

using namespace cloth;
using cloth::testing::random_state;

namespace {

// A hinge near the flat rest of a right-angled one, each coordinate moved by up to 0.3.
Vector12 random_hinge(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Vector12 x;
  x << 0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0;
  for (int k = 0; k < 12; ++k) x[k] += 0.3 * unit(rng);
  return x;
}

SceneParams free_sheet(int M, int N, double d) {
  SceneParams p;
  p.grid = Grid{M, N, d};
  p.pins = PinSet::none;
  p.gravity = 0;
  return p;
}

// Every particle of the sheet mapped onto a cylinder of curvature kappa whose axis lies along `axis` (a unit
// vector in the plane): the arc length along the in-plane direction c normal to the axis is kept, so the map is
// an isometry and each hinge bends by what the continuum surface does.
Vector cylinder(const Scene& scene, Eigen::Vector2d axis, double kappa) {
  const Eigen::Vector2d c(axis.y(), -axis.x());
  Vector x = scene.initial_positions();
  for (int s = 0; s < scene.free_count(); ++s) {
    const Eigen::Vector2d p = x.segment<2>(3 * s);
    const double u = c.dot(p), v = axis.dot(p), R = 1 / kappa;
    const Eigen::Vector2d in_plane = v * axis + R * std::sin(u / R) * c;
    x.segment<3>(3 * s) << in_plane.x(), in_plane.y(), R * (1 - std::cos(u / R));
  }
  return x;
}

}  // namespace

TEST_CASE("the dihedral angle's gradient and Hessian agree with central differences of the angle and the gradient") {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const Vector12 x = random_hinge(rng);
    const Vector12 g = hinge_angle_gradient(x);
    const Matrix12 H = hinge_angle_hessian(x);
    const double h = 1e-6;
    for (int k = 0; k < 12; ++k) {
      Vector12 xp = x, xm = x;
      xp[k] += h;
      xm[k] -= h;
      // Central differences: truncation O(h^2) times third derivatives of order 1 here, rounding u / h.
      CHECK(g[k] == doctest::Approx((hinge_angle(xp) - hinge_angle(xm)) / (2 * h)).epsilon(1e-7));
      const Vector12 column = (hinge_angle_gradient(xp) - hinge_angle_gradient(xm)) / (2 * h);
      CHECK((H.col(k) - column).norm() <= 1e-6 * (1 + column.norm()));
    }
    CHECK((H - H.transpose()).norm() == 0.0);
  }
}

TEST_CASE("the closed-form Hessian of the dihedral angle equals its forward-mode derivative, far from flat too") {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    Vector12 x = random_hinge(rng);
    if (trial >= 25)  // folded hinges: the second apex anywhere
      for (int k = 9; k < 12; ++k) x[k] = unit(rng);
    const Matrix12 closed = hinge_angle_hessian(x), forward = hinge_angle_hessian_forward_mode(x);
    // Two evaluations of one formula's derivative, in different orders: they agree to rounding.
    CHECK((closed - forward).norm() <= 1e-11 * forward.norm());
  }
}

TEST_CASE("the hinge energy's Hessian grad theta grad theta^T + theta d^2 theta is indefinite at every fold, "
          "however small: four negative eigenvalues, the smallest -3.2 theta for a unit grid-line hinge") {
  // The grid-line hinge of Chapter 12 (edge (0,0)-(1,0), apices at (1,1) and (0,-1)), each wing turned by theta/2.
  // d^2 theta has eigenvalues of both signs (-3.24 and 3.24 when flat); the rank-one Gauss-Newton term lifts one
  // direction only, so theta d^2 theta leaves negative ones at any theta != 0, not only once theta is large.
  for (const double theta : {1e-3, 1e-2, 0.1}) {
    CAPTURE(theta);
    Vector12 x;
    x << 0, 0, 0, 1, 0, 0, 1, std::cos(theta / 2), -std::sin(theta / 2), 0, -std::cos(theta / 2), -std::sin(theta / 2);
    REQUIRE(hinge_angle(x) == doctest::Approx(theta).epsilon(1e-12));
    const Vector12 g = hinge_angle_gradient(x);
    const Matrix12 H = g * g.transpose() + theta * hinge_angle_hessian(x);
    const Eigen::SelfAdjointEigenSolver<Matrix12> eigen(H);
    int negative = 0;
    for (int k = 0; k < 12; ++k) negative += eigen.eigenvalues()[k] < -1e-6 * theta ? 1 : 0;
    CHECK(negative == 4);
    CHECK(eigen.eigenvalues().minCoeff() / theta == doctest::Approx(-3.24).epsilon(0.05));
    CHECK(eigen.eigenvalues().maxCoeff() == doctest::Approx(4.0).epsilon(0.01));  // |grad theta|^2: four unit rows
  }
}

TEST_CASE("a hinge folded by a known angle: hinge_angle returns it, with the documented sign") {
  for (const double theta : {-2.5, -0.3, 1e-9, 0.7, 3.0}) {
    // Edge along x; apex x2 at +y in the plane z = 0, apex x3 turned by theta about the edge away from N1 = +z.
    Vector12 x;
    x << 0, 0, 0, 1, 0, 0, 0.4, 1, 0, 0.6, -std::cos(theta), -std::sin(theta);
    CHECK(hinge_angle(x) == doctest::Approx(theta).epsilon(1e-14));
  }
}

TEST_CASE("a degenerate hinge (an edge collapsed to a point, a triangle of zero area) gives 0, not NaN") {
  Vector12 ok;
  ok << 0, 0, 0, 1, 0, 0, 0.4, 1, 0, 0.6, -1, 0.2;
  CHECK_FALSE(hinge_degenerate(ok));
  Vector12 flat_apex = ok, collapsed_edge = ok, one_point = Vector12::Zero();
  flat_apex.segment<3>(6) << 0.3, 0, 0;          // x2 on the edge's line: triangle (x0, x1, x2) has no area
  collapsed_edge.segment<3>(3) = ok.segment<3>(0);  // x1 = x0
  for (const Vector12& x : {flat_apex, collapsed_edge, one_point}) {
    CHECK(hinge_degenerate(x));
    CHECK(hinge_angle(x) == 0.0);
    CHECK(hinge_angle_gradient(x).norm() == 0.0);
    CHECK(hinge_angle_hessian(x).norm() == 0.0);
    CHECK(hinge_angle_hessian_forward_mode(x).norm() == 0.0);
  }
  // An apex a hair off the line (height 1e-12 |e|) is not degenerate: its angle and gradient are finite.
  Vector12 thin = ok;
  thin.segment<3>(6) << 0.3, 1e-12, 0;
  CHECK_FALSE(hinge_degenerate(thin));
  CHECK(std::isfinite(hinge_angle_gradient(thin).norm()));
  // A sheet with one cell crushed (a particle moved onto its neighbour): energy, forces and Hessian stay finite.
  const Scene scene(free_sheet(4, 4, 0.1));
  Vector x = scene.initial_positions();
  const int a = scene.slot(scene.grid().particle(1, 1)), b = scene.slot(scene.grid().particle(1, 2));
  x.segment<3>(3 * a) = x.segment<3>(3 * b);
  x[3 * scene.slot(scene.grid().particle(2, 2)) + 2] = 0.03;  // and a bend elsewhere, so something is nonzero
  BendingEnergy bending(scene, BendingModel::hinge, 1e-3);
  Vector f = Vector::Zero(scene.dof_count());
  bending.add_forces(x, f);
  const double E = bending.energy(x);
  CHECK(std::isfinite(E));
  CHECK(E > 0);
  CHECK(f.allFinite());
  CHECK(Eigen::MatrixXd(bending.hessian(x, false)).allFinite());
}

TEST_CASE("both bending models: forces are minus the energy's gradient and the Hessian its derivative") {
  for (const BendingModel model : {BendingModel::hinge, BendingModel::quadratic}) {
    CAPTURE(bending_models().name(model));
    SceneParams p = free_sheet(5, 4, 0.1);
    p.pins = PinSet::corner;
    const Scene scene(p);
    BendingEnergy bending(scene, model, 2e-3);
    std::mt19937 rng(7);
    const Vector x = random_state(scene, rng, 1.0, 0.2, 0).x;
    Vector f = Vector::Zero(scene.dof_count());
    bending.add_forces(x, f);
    const SparseMatrix H = bending.hessian(x, false);
    const double h = 1e-7, scale = f.lpNorm<Eigen::Infinity>();
    for (int k = 0; k < scene.dof_count(); ++k) {
      Vector xp = x, xm = x;
      xp[k] += h;
      xm[k] -= h;
      CHECK(-f[k] == doctest::Approx((bending.energy(xp) - bending.energy(xm)) / (2 * h)).epsilon(1e-6).scale(scale));
      Vector fp = Vector::Zero(scene.dof_count()), fm = fp;
      bending.add_forces(xp, fp);
      bending.add_forces(xm, fm);
      const Vector column = -(fp - fm) / (2 * h);
      CHECK((Vector(H.col(k)) - column).norm() <= 1e-5 * (1 + Eigen::MatrixXd(H).norm()));
    }
    // The definite part is positive semi-definite; for the quadratic model it is the whole constant Hessian.
    const Eigen::MatrixXd D = bending.hessian(x, true);
    CHECK(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(D).eigenvalues().minCoeff() >= -1e-12 * D.norm());
    if (model == BendingModel::quadratic) CHECK((D - Eigen::MatrixXd(H)).norm() == 0.0);
  }
}

TEST_CASE("a flat sheet has no bending energy or force, and a rigid motion of a bent one changes neither") {
  for (const BendingModel model : {BendingModel::hinge, BendingModel::quadratic}) {
    CAPTURE(bending_models().name(model));
    const Scene scene(free_sheet(6, 5, 0.05));
    BendingEnergy bending(scene, model, 1e-4);
    // Flat, and flat after an in-plane rotation and a lift: no energy, no force.
    Vector flat = scene.initial_positions();
    const Eigen::Matrix3d Rz = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (int s = 0; s < scene.free_count(); ++s) flat.segment<3>(3 * s) = Rz * flat.segment<3>(3 * s) + Eigen::Vector3d(1, 2, 3);
    CHECK(bending.energy(flat) <= 1e-30);
    Vector f = Vector::Zero(scene.dof_count());
    bending.add_forces(flat, f);
    // Rounding only: angles of order u give forces of order u B / d.
    CHECK(f.lpNorm<Eigen::Infinity>() <= 1e-12 * 1e-4 / 0.05);
    // A random bent sheet, then rotated about a tilted axis and moved.
    std::mt19937 rng(3);
    const Vector bent = random_state(scene, rng, 1.0, 0.3, 0).x;
    Vector moved = bent;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(1.1, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
    for (int s = 0; s < scene.free_count(); ++s) moved.segment<3>(3 * s) = R * bent.segment<3>(3 * s) + Eigen::Vector3d(-0.4, 0.2, 7);
    const double E = bending.energy(bent);
    CHECK(E > 0);
    CHECK(bending.energy(moved) == doctest::Approx(E).epsilon(1e-11));
    Vector f_bent = Vector::Zero(scene.dof_count()), f_moved = f_bent;
    bending.add_forces(bent, f_bent);
    bending.add_forces(moved, f_moved);
    for (int s = 0; s < scene.free_count(); ++s)
      CHECK((f_moved.segment<3>(3 * s) - R * f_bent.segment<3>(3 * s)).norm() <= 1e-10 * f_bent.norm());
  }
}

TEST_CASE("a sheet bent into a cylinder about a grid line has the continuum energy B kappa^2 / 2 per area, about "
          "the diagonals and twisted it has the multiples the hinges' weights predict") {
  // 201 x 201 particles, kappa d = 0.01: the hinges of the sheet's last row of cells along the bend are on its
  // boundary, so the sum misses about 1 / 200 of the area.
  const double d = 0.005, B = 3e-6, kappa = 2.0;
  const Scene scene(free_sheet(201, 201, d));
  const double area = 200.0 * 200.0 * d * d, continuum = 0.5 * B * kappa * kappa * area;
  const double s = 1 / std::sqrt(2.0);
  struct Case {
    Eigen::Vector2d axis;
    double uniform, both;  // the energy over the continuum's, derived on the Chapter 12 page
  };
  for (const BendingModel model : {BendingModel::hinge, BendingModel::quadratic})
    for (const GridSplit split : {GridSplit::uniform, GridSplit::both}) {
      CAPTURE(bending_models().name(model));
      CAPTURE(grid_splits().name(split));
      BendingEnergy bending(scene, model, B, split);
      for (const Case& c : {Case{{1, 0}, 1, 1}, Case{{0, 1}, 1, 1}, Case{{s, s}, 1, 2}, Case{{s, -s}, 3, 2}}) {
        CAPTURE(c.axis.transpose());
        const double ratio = bending.energy(cylinder(scene, c.axis, kappa)) / continuum;
        CHECK(ratio == doctest::Approx(split == GridSplit::uniform ? c.uniform : c.both).epsilon(0.01));
      }
      // Twist z = tau x y: the continuum (Poisson ratio 0) stores (B/2) 2 tau^2 per area, either split three times
      // that (tau small: the surface is not developable, and the derivation is to leading order).
      Vector x = scene.initial_positions();
      const double tau = 0.01;
      for (int p = 0; p < scene.free_count(); ++p) x[3 * p + 2] = tau * x[3 * p] * x[3 * p + 1];
      const double twist = bending.energy(x) / (0.5 * B * 2 * tau * tau * area);
      CHECK(twist == doctest::Approx(3.0).epsilon(0.01));
    }
}
