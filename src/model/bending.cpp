// The hinge and quadratic bending energies on the split grid (the derivations are on the Chapter 12 page).
#include "model/bending.hpp"

#include "base/input_error.hpp"

#include <Eigen/Geometry>
#include <unsupported/Eigen/AutoDiff>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace cloth {

const NameTable<BendingModel>& bending_models() {
  static const NameTable<BendingModel> table("bending model", {{BendingModel::flexion, "flexion"},
                                                               {BendingModel::hinge, "hinge"},
                                                               {BendingModel::quadratic, "quadratic"}});
  return table;
}

const NameTable<GridSplit>& grid_splits() {
  static const NameTable<GridSplit> table("grid split", {{GridSplit::uniform, "uniform"},
                                                         {GridSplit::both, "both"}});
  return table;
}

namespace {

// A hinge from its four grid particles (i, j) pairs: the edge (a, b), the apices c and d on either side.
Hinge make_hinge(const Grid& g, std::array<std::array<int, 2>, 4> ij) {
  Hinge h;
  std::array<Eigen::Vector2d, 4> X;
  for (int k = 0; k < 4; ++k) {
    h.particle[k] = g.particle(ij[k][0], ij[k][1]);
    X[k] = {ij[k][0] * g.d, ij[k][1] * g.d};
  }
  const Eigen::Vector2d e = X[1] - X[0];
  const double length = e.norm();
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); };
  const double h2 = std::abs(cross(e, X[2] - X[0])) / length, h3 = std::abs(cross(e, X[3] - X[0])) / length;
  h.area = 0.5 * length * (h2 + h3);
  h.shape = length * length / h.area;
  // Apex weights |e| / h, then the edge weights from sum w = 0 and sum w (X . e) = 0 (the apices' feet on the edge).
  const double w2 = length / h2, w3 = length / h3;
  const double s2 = (X[2] - X[0]).dot(e) / (length * length), s3 = (X[3] - X[0]).dot(e) / (length * length);
  const double w1 = -(w2 * s2 + w3 * s3);
  h.weight = {-(w1 + w2 + w3), w1, w2, w3};
  return h;
}

// d theta / dx on any scalar type (double, or AutoDiff for its derivative). With e = x1 - x0 and the area-weighted
// normals N1 = e x (x2 - x0), N2 = (x3 - x0) x e (equal directions when the hinge is flat), an apex moving by
// delta along its normal turns its triangle about the edge by delta / h: d theta / dx2 = -|e| N1 / |N1|^2, and
// likewise x3. Moving the edge's ends moves each apex's foot, at s = (x_apex - x0) . e / |e|^2 along the edge:
// d theta / dx0 = -(1 - s2) d theta / dx2 - (1 - s3) d theta / dx3 and d theta / dx1 = -s2 ... - s3 ...; the four
// sum to zero (translation leaves theta as it is).
template <class T>
Eigen::Matrix<T, 12, 1> angle_gradient(const Eigen::Matrix<T, 12, 1>& x) {
  using V3 = Eigen::Matrix<T, 3, 1>;
  const V3 x0 = x.template segment<3>(0), x1 = x.template segment<3>(3), x2 = x.template segment<3>(6),
           x3 = x.template segment<3>(9);
  const V3 e = x1 - x0;
  const T e2 = e.squaredNorm();
  const T length = sqrt(e2);
  const V3 N1 = e.cross(x2 - x0), N2 = (x3 - x0).cross(e);
  const V3 g2 = -length / N1.squaredNorm() * N1, g3 = -length / N2.squaredNorm() * N2;
  const T s2 = (x2 - x0).dot(e) / e2, s3 = (x3 - x0).dot(e) / e2;
  Eigen::Matrix<T, 12, 1> g;
  g.template segment<3>(0) = -(T(1) - s2) * g2 - (T(1) - s3) * g3;
  g.template segment<3>(3) = -s2 * g2 - s3 * g3;
  g.template segment<3>(6) = g2;
  g.template segment<3>(9) = g3;
  return g;
}

}  // namespace

bool hinge_degenerate(const Vector12& x) {
  const Eigen::Vector3d x0 = x.segment<3>(0), e = x.segment<3>(3) - x0;
  const double e2 = e.squaredNorm();
  // |N|^2 = (|e| h)^2 for an apex at height h over the edge: h <= eps |e| is below the positions' rounding.
  const double floor = std::numeric_limits<double>::epsilon() * e2;
  return !(e2 > 0) || !(e.cross(x.segment<3>(6) - x0).squaredNorm() > floor * floor) ||
         !((x.segment<3>(9) - x0).cross(e).squaredNorm() > floor * floor);
}

std::vector<Hinge> grid_hinges(const Grid& g, GridSplit split) {
  using IJ = std::array<int, 2>;
  // Every triangle's edges, keyed by their two particles: the first triangle to reach an edge leaves its apex,
  // the second makes the hinge (the two apices then lie on either side of the edge).
  std::map<std::pair<int, int>, std::array<IJ, 3>> open;
  std::vector<Hinge> hinges;
  hinges.reserve(static_cast<std::size_t>(6 * (g.M - 1) * (g.N - 1)));
  const auto add_triangle = [&](const std::array<IJ, 3>& t) {
    for (int k = 0; k < 3; ++k) {
      const IJ a = t[k], b = t[(k + 1) % 3], apex = t[(k + 2) % 3];
      const int pa = g.particle(a[0], a[1]), pb = g.particle(b[0], b[1]);
      const auto key = std::minmax(pa, pb);
      const auto found = open.find(key);
      if (found == open.end()) {
        open.emplace(key, std::array<IJ, 3>{a, b, apex});
        continue;
      }
      const auto& [e0, e1, first_apex] = found->second;
      Hinge h = make_hinge(g, {e0, e1, first_apex, apex});
      if (split == GridSplit::both) {
        h.weight_factor = 0.5;
        h.shape *= 0.5;
      }
      hinges.push_back(h);
      open.erase(found);
    }
  };
  // The cells along the diagonal from (i, j) to (i+1, j+1), then (for both) along the other one; an edge shared
  // by the two triangulations is a hinge of each, with its own apices.
  for (int pass = 0; pass < (split == GridSplit::both ? 2 : 1); ++pass) {
    open.clear();
    for (int i = 0; i + 1 < g.M; ++i)
      for (int j = 0; j + 1 < g.N; ++j) {
        const IJ a{i, j}, b{i + 1, j}, c{i + 1, j + 1}, d{i, j + 1};
        if (pass == 0) {
          add_triangle({a, b, c});
          add_triangle({a, c, d});
        } else {
          add_triangle({a, b, d});
          add_triangle({b, c, d});
        }
      }
  }
  return hinges;
}

double hinge_angle(const Vector12& x) {
  if (hinge_degenerate(x)) return 0;
  const Eigen::Vector3d x0 = x.segment<3>(0), x1 = x.segment<3>(3), x2 = x.segment<3>(6), x3 = x.segment<3>(9);
  const Eigen::Vector3d e = x1 - x0;
  const Eigen::Vector3d N1 = e.cross(x2 - x0), N2 = (x3 - x0).cross(e);
  // sin theta |N1| |N2| = (N1 x N2) . e / |e| and cos theta |N1| |N2| = N1 . N2: atan2 needs no normalisation.
  return std::atan2(N1.cross(N2).dot(e) / e.norm(), N1.dot(N2));
}

Vector12 hinge_angle_gradient(const Vector12& x) {
  return hinge_degenerate(x) ? Vector12::Zero() : angle_gradient<double>(x);
}

namespace {

// theta and d theta / dx together, for the force and Hessian loops: hinge_angle's formula, then the gradient. The
// atan2 is called here, inside the loop's own code, not through hinge_angle: GCC 12 with AVX (-march=native) does
// not clear the vector registers' upper halves before calling a function of this file that ends by jumping to the
// math library, whose SSE code then pays a state transition on every call; the sphere drape's forces took 260 ns
// a hinge that way instead of 45.
struct AngleAndGradient {
  double theta = 0;
  Vector12 gradient = Vector12::Zero();
};

AngleAndGradient angle_and_gradient(const Vector12& x) {
  if (hinge_degenerate(x)) return {};
  const Eigen::Vector3d x0 = x.segment<3>(0), e = x.segment<3>(3) - x0;
  const Eigen::Vector3d N1 = e.cross(x.segment<3>(6) - x0), N2 = (x.segment<3>(9) - x0).cross(e);
  const double theta = std::atan2(N1.cross(N2).dot(e) / e.norm(), N1.dot(N2));
  return {theta, angle_gradient<double>(x)};
}

}  // namespace

Matrix12 hinge_angle_hessian_forward_mode(const Vector12& x) {
  if (hinge_degenerate(x)) return Matrix12::Zero();
  using Dual = Eigen::AutoDiffScalar<Vector12>;
  Eigen::Matrix<Dual, 12, 1> ad;
  for (int k = 0; k < 12; ++k) ad[k] = Dual(x[k], 12, k);
  const Eigen::Matrix<Dual, 12, 1> g = angle_gradient<Dual>(ad);
  Matrix12 H;
  for (int k = 0; k < 12; ++k) H.row(k) = g[k].derivatives().transpose();
  return 0.5 * (H + H.transpose());  // symmetric up to rounding; made exactly so for the factorizations
}

// [hinge_hessian]
// The derivative of angle_gradient's formula, term by term. With e = x1 - x0, a = x2 - x0, b = x3 - x0 and
// L = |e|: an apex term g = -L N / |N|^2 changes by dg = -(N / |N|^2) dL - (L / |N|^2) (I - 2 N N^T / |N|^2) dN,
// where dL = e^T de / L, dN1 = d(e x a) = -[a]x de + [e]x da and dN2 = d(b x e) = -[e]x db + [b]x de ([v]x w is
// v x w); the feet s = (a . e) / |e|^2 change by ds = (e^T da + a^T de) / |e|^2 - 2 (a . e) e^T de / |e|^4. The
// edge terms g0 = -(1 - s2) g2 - (1 - s3) g3 and g1 = -s2 g2 - s3 g3 then follow by the product rule. Every
// piece is a 3 x 3 block or a 1 x 3 row per particle, and the zero ones are never multiplied.
Matrix12 hinge_angle_hessian(const Vector12& x) {
  if (hinge_degenerate(x)) return Matrix12::Zero();
  using V3 = Eigen::Vector3d;
  using M3 = Eigen::Matrix3d;
  using R3 = Eigen::RowVector3d;
  const V3 x0 = x.segment<3>(0), e = x.segment<3>(3) - x0, a = x.segment<3>(6) - x0, b = x.segment<3>(9) - x0;
  const double e2 = e.squaredNorm(), L = std::sqrt(e2);
  const M3 I = M3::Identity();
  const auto skew = [](const V3& v) {
    M3 S;
    S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
    return S;
  };
  const M3 Se = skew(e), Sa = skew(a), Sb = skew(b);
  // Per particle k = 0..3, the 3 x 3 blocks d N / d x_k (dN1 = -[a]x de + [e]x da, dN2 = -[e]x db + [b]x de with
  // de = dx1 - dx0, da = dx2 - dx0, db = dx3 - dx0) and the rows d L / d x_k, d s / d x_k.
  const std::array<M3, 4> dN1 = {Sa - Se, -Sa, Se, M3::Zero()}, dN2 = {Se - Sb, Sb, M3::Zero(), -Se};
  const std::array<R3, 4> dL = {-e.transpose() / L, e.transpose() / L, R3::Zero(), R3::Zero()};
  const auto foot_rows = [&](const V3& c, int apex) {  // d s / d x_k for the apex at x0 + c
    const double t = 2 * c.dot(e) / (e2 * e2);
    std::array<R3, 4> ds = {(-e - c).transpose() / e2 + t * e.transpose(), c.transpose() / e2 - t * e.transpose(),
                            R3::Zero(), R3::Zero()};
    ds[static_cast<std::size_t>(apex)] = e.transpose() / e2;
    return ds;
  };
  const std::array<R3, 4> ds2 = foot_rows(a, 2), ds3 = foot_rows(b, 3);
  // An apex term g = -L N / |N|^2 and its blocks dg_k = -(N / |N|^2) dL_k - (L / |N|^2) (I - 2 N N^T / |N|^2) dN_k.
  const auto apex = [&](const V3& N, const std::array<M3, 4>& dN, V3& g, std::array<M3, 4>& dg) {
    const double q = N.squaredNorm();
    g = -L / q * N;
    const M3 P = (L / q) * (I - 2 / q * N * N.transpose());
    for (std::size_t k = 0; k < 4; ++k) dg[k] = -(N / q) * dL[k] - P * dN[k];
  };
  V3 g2, g3;
  std::array<M3, 4> dg2, dg3;
  apex(e.cross(a), dN1, g2, dg2);
  apex(b.cross(e), dN2, g3, dg3);
  const double s2 = a.dot(e) / e2, s3 = b.dot(e) / e2;
  Matrix12 H;
  for (std::size_t k = 0; k < 4; ++k) {
    const auto c = static_cast<Eigen::Index>(3 * k);
    H.block<3, 3>(0, c) = g2 * ds2[k] - (1 - s2) * dg2[k] + g3 * ds3[k] - (1 - s3) * dg3[k];
    H.block<3, 3>(3, c) = -g2 * ds2[k] - s2 * dg2[k] - g3 * ds3[k] - s3 * dg3[k];
    H.block<3, 3>(6, c) = dg2[k];
    H.block<3, 3>(9, c) = dg3[k];
  }
  return 0.5 * (H + H.transpose());  // symmetric up to rounding; made exactly so for the factorizations
}
// [hinge_hessian]

BendingEnergy::BendingEnergy(const Scene& scene, BendingModel model, double bending_rigidity, GridSplit split)
    : scene_(scene), model_(model), B_(bending_rigidity), all_(3 * scene.particle_count()) {
  if (!(std::isfinite(bending_rigidity) && bending_rigidity > 0))
    throw InputError("bending rigidity B = " + std::to_string(bending_rigidity) + ": expected a finite number > 0");
  if (model != BendingModel::flexion) hinges_ = grid_hinges(scene.grid(), split);
  // A hinge on the edge of a pinned region (a clamp) bends on its free side only: its angle accumulates over the
  // free triangle, half the hinge's area, so its weight c doubles (a clamped strip then bends from the clamp
  // line, not half a spacing behind it). Hinges with all four particles pinned never change and are dropped.
  std::erase_if(hinges_, [&](const Hinge& h) {
    return std::all_of(h.particle.begin(), h.particle.end(), [&](int p) { return scene.is_pinned(p); });
  });
  for (Hinge& h : hinges_)
    if (scene.is_pinned(h.particle[0]) && scene.is_pinned(h.particle[1]) &&
        scene.is_pinned(h.particle[2]) != scene.is_pinned(h.particle[3])) {
      h.shape *= 2;
      h.weight_factor *= 2;
    }
}

Vector12 BendingEnergy::gather(const Hinge& h) const {
  Vector12 x;
  for (int k = 0; k < 4; ++k) x.segment<3>(3 * k) = all_.segment<3>(3 * h.particle[k]);
  return x;
}

double BendingEnergy::energy(const ConstVectorRef& x) {
  scene_.all_positions(x, all_);
  double E = 0;
  for (const Hinge& h : hinges_) {
    const Vector12 y = gather(h);
    if (model_ == BendingModel::hinge) {
      const double theta = hinge_angle(y);
      E += 0.5 * B_ * h.shape * theta * theta;
    } else {
      Eigen::Vector3d Kx = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k) Kx += h.weight[k] * y.segment<3>(3 * k);
      E += 0.5 * B_ * h.weight_factor / h.area * Kx.squaredNorm();
    }
  }
  return E;
}

void BendingEnergy::add_forces(const ConstVectorRef& x, VectorRef f) {
  scene_.all_positions(x, all_);
  for (const Hinge& h : hinges_) {
    const Vector12 y = gather(h);
    Vector12 grad;
    if (model_ == BendingModel::hinge) {
      const AngleAndGradient a = angle_and_gradient(y);
      grad = B_ * h.shape * a.theta * a.gradient;
    } else {
      Eigen::Vector3d Kx = Eigen::Vector3d::Zero();
      for (int k = 0; k < 4; ++k) Kx += h.weight[k] * y.segment<3>(3 * k);
      for (int k = 0; k < 4; ++k) grad.segment<3>(3 * k) = B_ * h.weight_factor / h.area * h.weight[k] * Kx;
    }
    for (int k = 0; k < 4; ++k) {
      const int s = scene_.slot(h.particle[k]);
      if (s < scene_.free_count()) f.segment<3>(3 * s) -= grad.segment<3>(3 * k);
    }
  }
}

void BendingEnergy::add_pattern_blocks(std::vector<Eigen::Triplet<double>>& triplets) const {
  for (const Hinge& h : hinges_)
    for (int a : h.particle)
      for (int b : h.particle) {
        const int sa = scene_.slot(a), sb = scene_.slot(b);
        if (sa >= scene_.free_count() || sb >= scene_.free_count()) continue;
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) triplets.emplace_back(3 * sa + r, 3 * sb + c, 0.0);
      }
}

void BendingEnergy::bind(const SparseMatrix& pattern) {
  block_start_.resize(hinges_.size());
  for (std::size_t k = 0; k < hinges_.size(); ++k)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 3; ++c) {
          const int sa = scene_.slot(hinges_[k].particle[a]), sb = scene_.slot(hinges_[k].particle[b]);
          int& start = block_start_[k][(4 * a + b) * 3 + c];
          start = -1;
          if (sa >= scene_.free_count() || sb >= scene_.free_count()) continue;
          // Rows are sorted within a column: the block's first row by bisection.
          const int column = 3 * sb + c;
          const int* rows = pattern.innerIndexPtr();
          const int* first = rows + pattern.outerIndexPtr()[column];
          const int* last = rows + pattern.outerIndexPtr()[column + 1];
          const int* found = std::lower_bound(first, last, 3 * sa);
          if (found == last || *found != 3 * sa)
            throw std::logic_error("BendingEnergy::bind: the pattern lacks a hinge block");
          start = static_cast<int>(found - rows);
        }
  // The quadratic model's Hessian does not depend on the positions: its values in this pattern, once.
  constant_values_.clear();
  if (model_ == BendingModel::quadratic) {
    constant_values_.assign(static_cast<std::size_t>(pattern.nonZeros()), 0.0);
    add_hinge_hessians(Vector(), false, 1.0, constant_values_.data());
  }
}

const SparseMatrix& BendingEnergy::hessian(const ConstVectorRef& x, bool definite) {
  if (H_.rows() != scene_.dof_count()) {
    std::vector<Eigen::Triplet<double>> triplets;
    add_pattern_blocks(triplets);
    H_.resize(scene_.dof_count(), scene_.dof_count());
    H_.setFromTriplets(triplets.begin(), triplets.end());
    H_.makeCompressed();
    bind(H_);
  }
  H_.coeffs().setZero();
  add_hessian(x, definite, 1.0, H_.valuePtr());
  return H_;
}

void BendingEnergy::add_hessian(const ConstVectorRef& x, bool definite, double scale, double* values) {
  if (model_ == BendingModel::quadratic) {
    for (std::size_t k = 0; k < constant_values_.size(); ++k) values[k] += scale * constant_values_[k];
    return;
  }
  add_hinge_hessians(x, definite, scale, values);
}

void BendingEnergy::add_hinge_hessians(const ConstVectorRef& x, bool definite, double scale, double* values) {
  if (model_ == BendingModel::hinge) scene_.all_positions(x, all_);
  for (std::size_t k = 0; k < hinges_.size(); ++k) {
    const Hinge& h = hinges_[k];
    Matrix12 He;
    if (model_ == BendingModel::hinge) {
      // E = (B/2) shape theta^2: H = B shape (grad theta grad theta^T + theta d^2 theta).
      const Vector12 y = gather(h);
      const AngleAndGradient a = angle_and_gradient(y);
      He = (scale * B_ * h.shape) * a.gradient * a.gradient.transpose();
      if (!definite) He += (scale * B_ * h.shape * a.theta) * hinge_angle_hessian(y);
    } else {
      // E = (B / 2A) |sum w_i x_i|^2: H = (B / A) w w^T (x) I3, the same at every x.
      He.setZero();
      const double c = scale * B_ * h.weight_factor / h.area;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          He.block<3, 3>(3 * a, 3 * b).diagonal().setConstant(c * h.weight[a] * h.weight[b]);
    }
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 3; ++c) {
          const int start = block_start_[k][(4 * a + b) * 3 + c];
          if (start < 0) continue;
          for (int r = 0; r < 3; ++r) values[start + r] += He(3 * a + r, 3 * b + c);
        }
  }
}

}  // namespace cloth
