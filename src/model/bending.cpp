// The hinge and quadratic bending energies on the split grid (the derivations are on the Chapter 12 page).
#include "model/bending.hpp"

#include "base/input_error.hpp"

#include <Eigen/Geometry>
#include <unsupported/Eigen/AutoDiff>

#include <algorithm>
#include <cmath>
#include <map>
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
  const Eigen::Vector3d x0 = x.segment<3>(0), x1 = x.segment<3>(3), x2 = x.segment<3>(6), x3 = x.segment<3>(9);
  const Eigen::Vector3d e = x1 - x0;
  const Eigen::Vector3d N1 = e.cross(x2 - x0), N2 = (x3 - x0).cross(e);
  // sin theta |N1| |N2| = (N1 x N2) . e / |e| and cos theta |N1| |N2| = N1 . N2: atan2 needs no normalisation.
  return std::atan2(N1.cross(N2).dot(e) / e.norm(), N1.dot(N2));
}

Vector12 hinge_angle_gradient(const Vector12& x) { return angle_gradient<double>(x); }

Matrix12 hinge_angle_hessian(const Vector12& x) {
  using Dual = Eigen::AutoDiffScalar<Vector12>;
  Eigen::Matrix<Dual, 12, 1> ad;
  for (int k = 0; k < 12; ++k) ad[k] = Dual(x[k], 12, k);
  const Eigen::Matrix<Dual, 12, 1> g = angle_gradient<Dual>(ad);
  Matrix12 H;
  for (int k = 0; k < 12; ++k) H.row(k) = g[k].derivatives().transpose();
  return 0.5 * (H + H.transpose());  // symmetric up to rounding; made exactly so for the factorizations
}

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
      grad = B_ * h.shape * hinge_angle(y) * hinge_angle_gradient(y);
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

void BendingEnergy::build_pattern() {
  const int n = scene_.dof_count();
  std::vector<Eigen::Triplet<double>> entries;
  for (const Hinge& h : hinges_)
    for (int a : h.particle)
      for (int b : h.particle) {
        const int sa = scene_.slot(a), sb = scene_.slot(b);
        if (sa >= scene_.free_count() || sb >= scene_.free_count()) continue;
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) entries.emplace_back(3 * sa + r, 3 * sb + c, 0.0);
      }
  pattern_.resize(n, n);
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();
  pattern_.coeffs().setZero();
  block_start_.resize(hinges_.size());
  for (std::size_t k = 0; k < hinges_.size(); ++k)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 3; ++c) {
          const int sa = scene_.slot(hinges_[k].particle[a]), sb = scene_.slot(hinges_[k].particle[b]);
          int& start = block_start_[k][(4 * a + b) * 3 + c];
          start = -1;
          if (sa >= scene_.free_count() || sb >= scene_.free_count()) continue;
          const int column = 3 * sb + c;
          for (int p = pattern_.outerIndexPtr()[column]; p < pattern_.outerIndexPtr()[column + 1]; ++p)
            if (pattern_.innerIndexPtr()[p] == 3 * sa) start = p;
        }
  H_ = pattern_;
}

const SparseMatrix& BendingEnergy::hessian(const ConstVectorRef& x, bool definite) {
  if (block_start_.size() != hinges_.size() || pattern_.rows() != scene_.dof_count()) build_pattern();
  scene_.all_positions(x, all_);
  H_.coeffs().setZero();
  double* values = H_.valuePtr();
  for (std::size_t k = 0; k < hinges_.size(); ++k) {
    const Hinge& h = hinges_[k];
    Matrix12 He;
    if (model_ == BendingModel::hinge) {
      // E = (B/2) shape theta^2: H = B shape (grad theta grad theta^T + theta d^2 theta).
      const Vector12 y = gather(h);
      const Vector12 g = hinge_angle_gradient(y);
      He = B_ * h.shape * g * g.transpose();
      if (!definite) He += B_ * h.shape * hinge_angle(y) * hinge_angle_hessian(y);
    } else {
      // E = (B / 2A) |sum w_i x_i|^2: H = (B / A) w w^T (x) I3, the same at every x.
      He.setZero();
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b)
          He.block<3, 3>(3 * a, 3 * b) = B_ * h.weight_factor / h.area * h.weight[a] * h.weight[b] * Eigen::Matrix3d::Identity();
    }
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int c = 0; c < 3; ++c) {
          const int start = block_start_[k][(4 * a + b) * 3 + c];
          if (start < 0) continue;
          for (int r = 0; r < 3; ++r) values[start + r] += He(3 * a + r, 3 * b + c);
        }
  }
  return H_;
}

}  // namespace cloth
