// Spring, damping and gravity forces (docs/model.md), their energies, and their analytic Jacobians refilled in a
// sparsity pattern built once. The spring loops are the hot loops of every chapter: they read springs
// contiguously, branch on the damping law once per family (a template), and allocate nothing.
#include "model/force_field.hpp"

#include "model/bending.hpp"

#include <algorithm>
#include <cmath>
#include <Eigen/Dense>
#if defined(__AVX2__)
#include <immintrin.h>
#endif

namespace cloth {

const NameTable<StiffnessTreatment>& stiffness_treatments() {
  static const NameTable<StiffnessTreatment> table("Jacobian treatment", {{StiffnessTreatment::exact, "exact"},
                                                                          {StiffnessTreatment::symmetric, "symmetric"},
                                                                          {StiffnessTreatment::definite, "definite"}});
  return table;
}

namespace {

// The frozen laws are the dampers of the incremental potential (freeze_dampers): projected_frozen acts along the
// direction u0 and report_frozen with the length l0 of the start of the step.
enum class DampingLaw { none, projected, report, projected_frozen, report_frozen };

// The two sums the frozen pass returns: sum (l - L0)^2, and sum ((v_p - v_q).u0)^2 or sum l0 |v_p - v_q|^2.
struct SpringSums {
  double stretch = 0;
  double dissipation = 0;
};

// The dot products a_k . b_k of a batch of 4-vectors. Eigen sums one 4-vector's products in halves,
// (a0 b0 + a2 b2) + (a1 b1 + a3 b3); with AVX2 the four products are added in that same order across registers,
// without a horizontal sum per spring, so each lane has the same bits for a third of the instructions.
template <int lanes>
[[gnu::always_inline]] inline Eigen::Array<double, lanes, 1> batch_dots(const Eigen::Vector4d* a,
                                                                      const Eigen::Vector4d* b) {
  Eigen::Array<double, lanes, 1> dots;
#if defined(__AVX2__)
  if constexpr (lanes == 4) {
    __m256d m[4];
    for (int k = 0; k < 4; ++k) m[k] = _mm256_mul_pd(_mm256_load_pd(a[k].data()), _mm256_load_pd(b[k].data()));
    // Each half sum of springs 0 and 1, then of 2 and 3: (m0[0] + m0[2], m0[1] + m0[3], m1[0] + m1[2], ...).
    const auto half_sums = [](__m256d m0, __m256d m1) {
      return _mm256_add_pd(_mm256_permute2f128_pd(m0, m1, 0x20), _mm256_permute2f128_pd(m0, m1, 0x31));
    };
    const __m256d h01 = half_sums(m[0], m[1]), h23 = half_sums(m[2], m[3]);
    // The horizontal add completes every sum, in the lane order (0, 2, 1, 3), which the permutation puts right.
    _mm256_storeu_pd(dots.data(), _mm256_permute4x64_pd(_mm256_hadd_pd(h01, h23), 0xD8));
    return dots;
  }
#endif
  for (int k = 0; k < lanes; ++k) dots[k] = a[k].dot(b[k]);
  return dots;
}

// Adds the spring and damping forces of the `lanes` springs starting at s to F. For a spring (p, q) with
// d = x_p - x_q, l = |d|, u = d / l: spring K (L0 - l) u; projected damper -D ((v_p - v_q) . u) u; report damper
// -D (v_p - v_q) l. q receives the opposite force. U0 and L0f hold the batch's frozen directions and lengths
// (read by the frozen laws only); with `sums`, the batch's terms of the potentials are added to *sums.
//
// Two choices make this loop fast (Chapter 6 measures them). X, V and F hold four numbers per particle slot,
// (x, y, z, 0), so that a particle is read or updated with whole-vector loads and stores rather than three
// scalars each. And springs go `lanes` at a time: the square root and the division cost more than all the rest
// of a spring's arithmetic when done one spring at a time, while for a batch each is one vector instruction
// (Eigen's Array packets) and the processor overlaps the springs' independent work. The batch's lengths and
// velocity projections are formed together as well (batch_dots). And the batch is always inlined into its loop:
// with five damping laws it sits at the edge of GCC 12's inlining limits, small edits made GCC call it instead,
// and a call per batch made the explicit steps half as slow again.
// F is written through the Eigen::Map views below, which clang-tidy does not see; the directive stays outside
// the listing Chapter 1 shows.
// NOLINTBEGIN(readability-non-const-parameter)
// [spring_force_loop]
template <DampingLaw law, bool sums, int lanes>
[[gnu::always_inline]] inline void add_spring_batch(const Spring* s, double K, double D, const double* X,
                                                    const double* V, double* F, const double* U0, const double* L0f,
                                                    SpringSums* totals) {
  using Slot = Eigen::Map<Eigen::Vector4d, Eigen::Aligned16>;
  using ConstSlot = Eigen::Map<const Eigen::Vector4d, Eigen::Aligned16>;
  using Batch = Eigen::Array<double, lanes, 1>;
  std::ptrdiff_t p[lanes], q[lanes];  // where the two particles' columns start
  Eigen::Vector4d d[lanes], w[lanes];
  Batch L0, wd;
  for (int k = 0; k < lanes; ++k) {
    p[k] = 4 * std::ptrdiff_t{s[k].p}, q[k] = 4 * std::ptrdiff_t{s[k].q};
    d[k] = ConstSlot(X + p[k]) - ConstSlot(X + q[k]);  // the padding stays 0
    L0[k] = s[k].rest_length;
    if constexpr (law != DampingLaw::none) {
      w[k] = ConstSlot(V + p[k]) - ConstSlot(V + q[k]);
      if constexpr (law == DampingLaw::projected_frozen) wd[k] = w[k].dot(ConstSlot(U0 + 4 * k));
      if constexpr (law == DampingLaw::report_frozen) wd[k] = L0f[k] * D;  // the frozen D l0
    }
  }
  const Batch l2 = batch_dots<lanes>(d, d);  // |d|^2
  if constexpr (law == DampingLaw::projected) wd = batch_dots<lanes>(w, d);
  // A coincident pair makes c infinite or NaN here; the guard below discards it.
  const Batch l = l2.sqrt();
  Batch c = K * (L0 / l - 1.0);  // K (L0 - l) / l: the spring force is c d
  if constexpr (law == DampingLaw::projected) c -= D * wd / l2;
  Batch Dl;
  if constexpr (law == DampingLaw::report) Dl = D * l;
  if constexpr (sums) totals->stretch += (l - L0).square().sum();
  for (int k = 0; k < lanes; ++k) {
    if constexpr (sums && law == DampingLaw::projected_frozen) totals->dissipation += wd[k] * wd[k];
    if constexpr (sums && law == DampingLaw::report_frozen) totals->dissipation += L0f[k] * w[k].squaredNorm();
    if (l[k] <= degenerate_length_fraction * L0[k]) continue;  // no direction: no force (Chapter 7)
    Eigen::Vector4d f = c[k] * d[k];
    if constexpr (law == DampingLaw::report) f -= Dl[k] * w[k];
    if constexpr (law == DampingLaw::projected_frozen) f -= (D * wd[k]) * ConstSlot(U0 + 4 * k);
    if constexpr (law == DampingLaw::report_frozen) f -= wd[k] * w[k];
    Slot(F + p[k]) += f;
    Slot(F + q[k]) -= f;
  }
}

// All springs of [first, last): four at a time (one AVX register, two SSE2 registers), then the remainder. U0
// and L0f point at the frozen data of `first`.
template <DampingLaw law, bool sums = false>
void add_spring_forces(const Spring* first, const Spring* last, double K, double D, const double* X, const double* V,
                       double* F, const double* U0 = nullptr, const double* L0f = nullptr,
                       SpringSums* totals = nullptr) {
  constexpr int lanes = 4;
  constexpr bool frozen = law == DampingLaw::projected_frozen || law == DampingLaw::report_frozen;
  for (; last - first >= lanes; first += lanes) {
    add_spring_batch<law, sums, lanes>(first, K, D, X, V, F, U0, L0f, totals);
    if constexpr (frozen) U0 += 4 * lanes, L0f += lanes;
  }
  for (; first != last; ++first) {
    add_spring_batch<law, sums, 1>(first, K, D, X, V, F, U0, L0f, totals);
    if constexpr (frozen) U0 += 4, L0f += 1;
  }
}
// [spring_force_loop]
// NOLINTEND(readability-non-const-parameter)

}  // namespace

ForceField::ForceField(const Scene& scene)
    : scene_(scene),
      X_(SlotMatrix::Zero(4, scene.particle_count())),
      V_(SlotMatrix::Zero(4, scene.particle_count())),
      F_(SlotMatrix::Zero(4, scene.particle_count())) {
  X_.topRows<3>() = scene.rest_positions().reshaped(3, scene.particle_count());
  // The pattern: a 3x3 block on the diagonal of every free particle and, for every spring joining two free
  // particles, the blocks (p, q) and (q, p). Built once; every later fill writes values in place.
  const int n_free = scene.free_count();
  const auto& springs = scene.springs().springs;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(9 * (static_cast<std::size_t>(n_free) + 2 * springs.size()));
  const auto add_block = [&](int r, int c) {
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) triplets.emplace_back(3 * r + a, 3 * c + b, 0.0);
  };
  for (int s = 0; s < n_free; ++s) add_block(s, s);
  for (const Spring& s : springs)
    if (s.p < n_free && s.q < n_free) {
      add_block(s.p, s.q);
      add_block(s.q, s.p);
    }
  // A hinge couples its four particles: its apices lie two cells apart, beyond any spring.
  if (scene.params().bending != BendingModel::flexion) {
    bending_ = std::make_unique<BendingEnergy>(scene, scene.params().bending, scene.params().bending_rigidity,
                                               scene.params().bending_split);
    bending_->add_pattern_blocks(triplets);
  }
  pattern_.resize(3 * n_free, 3 * n_free);
  pattern_.setFromTriplets(triplets.begin(), triplets.end());
  pattern_.makeCompressed();
  if (bending_) bending_->bind(pattern_);

  // Rows of a block are consecutive in each of its columns, so a block is found by three column starts.
  const auto entry = [&](int row, int col) {
    const int* rows = pattern_.innerIndexPtr();
    const int* begin = rows + pattern_.outerIndexPtr()[col];
    const int* end = rows + pattern_.outerIndexPtr()[col + 1];
    return static_cast<int>(std::lower_bound(begin, end, row) - rows);
  };
  const auto block = [&](int r, int c) {
    std::array<int, 3> start{-1, -1, -1};
    if (r < n_free && c < n_free)
      for (int b = 0; b < 3; ++b) start[static_cast<std::size_t>(b)] = entry(3 * r, 3 * c + b);
    return start;
  };
  spring_blocks_.reserve(springs.size());
  for (const Spring& s : springs)
    spring_blocks_.push_back({{block(s.p, s.p), block(s.q, s.q), block(s.p, s.q), block(s.q, s.p)}});
  diagonal_entry_.resize(static_cast<std::size_t>(3 * n_free));
  for (int k = 0; k < 3 * n_free; ++k) diagonal_entry_[static_cast<std::size_t>(k)] = entry(k, k);
  diagonal_blocks_.reserve(static_cast<std::size_t>(n_free));
  for (int s = 0; s < n_free; ++s) diagonal_blocks_.push_back(block(s, s));
  if (scene.has_damping()) {
    frozen_direction_ = SlotMatrix::Zero(4, static_cast<Eigen::Index>(springs.size()));
    frozen_length_.assign(springs.size(), 0.0);
  }
}

ForceField::~ForceField() = default;

void ForceField::scatter_state(const ConstVectorRef& x, const ConstVectorRef& v) {
  const int n = scene_.free_count();
  X_.topLeftCorner(3, n) = x.reshaped(3, n);
  if (scene_.has_damping()) V_.topLeftCorner(3, n) = v.reshaped(3, n);
}

void ForceField::spring_pass(bool frozen, Potentials* potentials) {
  F_.setZero();
  // Each family's springs run through the grid row by row. On a large grid one family's sweep would push the
  // first rows' positions and forces out of the cache before the next family came back to them, so the three
  // families advance together, a band of rows at a time: band b takes the same fraction b / bands of every
  // family. A 20 x 20 cloth is a single band.
  const auto& set = scene_.springs();
  const Spring* springs = set.springs.data();
  const bool projected = scene_.params().damping_model == DampingModel::projected;
  constexpr int springs_per_band = 4096;
  int bands = 1;
  for (const SpringRange& r : set.family) bands = std::max(bands, (r.size() + springs_per_band - 1) / springs_per_band);
  for (int b = 0; b < bands; ++b) {
    for (SpringFamily family : all_spring_families) {
      const SpringRange r = set.family[static_cast<int>(family)];
      if (r.size() == 0) continue;
      const double K = scene_.stiffness(family);
      const double D = scene_.damping(family);
      const auto at = [&](int band) { return r.begin + static_cast<std::ptrdiff_t>(r.size()) * band / bands; };
      const Spring* first = springs + at(b);
      const Spring* last = springs + at(b + 1);
      if (!frozen) {
        if (D == 0.0)
          add_spring_forces<DampingLaw::none>(first, last, K, D, X_.data(), V_.data(), F_.data());
        else if (projected)
          add_spring_forces<DampingLaw::projected>(first, last, K, D, X_.data(), V_.data(), F_.data());
        else
          add_spring_forces<DampingLaw::report>(first, last, K, D, X_.data(), V_.data(), F_.data());
        continue;
      }
      SpringSums sums;
      if (D == 0.0) {
        add_spring_forces<DampingLaw::none, true>(first, last, K, D, X_.data(), V_.data(), F_.data(), nullptr,
                                                  nullptr, &sums);
      } else {
        const double* U0 = frozen_direction_.data() + 4 * at(b);
        const double* L0f = frozen_length_.data() + at(b);
        if (projected)
          add_spring_forces<DampingLaw::projected_frozen, true>(first, last, K, D, X_.data(), V_.data(), F_.data(),
                                                                U0, L0f, &sums);
        else
          add_spring_forces<DampingLaw::report_frozen, true>(first, last, K, D, X_.data(), V_.data(), F_.data(), U0,
                                                             L0f, &sums);
      }
      potentials->spring += 0.5 * K * sums.stretch;
      potentials->dissipation += 0.5 * D * sums.dissipation;
      potentials->terms += static_cast<int>(last - first) * (D == 0.0 ? 1 : 2);
    }
  }
}

void ForceField::forces(const ConstVectorRef& x, const ConstVectorRef& v, VectorRef f) {
  scatter_state(x, v);
  spring_pass(false, nullptr);
  const int n = scene_.free_count();
  f.reshaped(3, n) = F_.topLeftCorner(3, n);
  if (bending_) bending_->add_forces(x, f);
  if (scene_.has_gravity()) {
    const double weight = scene_.params().mass * scene_.params().gravity;
    for (int s = 0; s < n; ++s) f[3 * s + 2] -= weight;
  }
}

void ForceField::freeze_dampers(const ConstVectorRef& x0) {
  if (!scene_.has_damping()) return;
  const int n = scene_.free_count();
  X_.topLeftCorner(3, n) = x0.reshaped(3, n);
  const auto& springs = scene_.springs().springs;
  for (std::size_t k = 0; k < springs.size(); ++k) {
    const Eigen::Vector4d d = X_.col(springs[k].p) - X_.col(springs[k].q);
    const double l = d.norm();
    // A spring with no direction gets none: its frozen damper then exerts no force, as the current one does not.
    const bool degenerate = l <= degenerate_length_fraction * springs[k].rest_length;
    frozen_direction_.col(static_cast<Eigen::Index>(k)) = degenerate ? Eigen::Vector4d::Zero() : Eigen::Vector4d(d / l);
    frozen_length_[k] = l;
  }
}

ForceField::Potentials ForceField::frozen_forces(const ConstVectorRef& x, const ConstVectorRef& v, VectorRef f) {
  scatter_state(x, v);
  Potentials potentials;
  spring_pass(true, &potentials);
  const int n = scene_.free_count();
  f.reshaped(3, n) = F_.topLeftCorner(3, n);
  if (bending_) {
    bending_->add_forces(x, f);
    potentials.spring += bending_->energy(x);
    potentials.terms += static_cast<int>(bending_->hinges().size());
  }
  if (scene_.has_gravity()) {
    const double weight = scene_.params().mass * scene_.params().gravity;
    for (int s = 0; s < n; ++s) f[3 * s + 2] -= weight;
  }
  return potentials;
}

void ForceField::acceleration(const ConstVectorRef& x, const ConstVectorRef& v, VectorRef a) {
  const double inverse_mass = 1.0 / scene_.params().mass;
  if (bending_) {
    forces(x, v, a);
    a *= inverse_mass;
    return;
  }
  // forces() and the scaling by 1/m in one pass over the particles instead of three (copy, gravity, scale): the
  // explicit methods call nothing else, and with the spring loop this fast the passes are a fifth of a step.
  // Each number takes the same operations in the same order, so the bits are those of forces(x, v, a) * (1/m).
  scatter_state(x, v);
  spring_pass(false, nullptr);
  const double weight = scene_.has_gravity() ? scene_.params().mass * scene_.params().gravity : 0.0;
  const int n = scene_.free_count();
  a.reshaped(3, n) = (F_.topLeftCorner(3, n).colwise() - Eigen::Vector3d(0.0, 0.0, weight)) * inverse_mass;
}

Energy ForceField::energy(const ConstVectorRef& x, const ConstVectorRef& v) {
  X_.topLeftCorner(3, scene_.free_count()) = x.reshaped(3, scene_.free_count());
  const double m = scene_.params().mass;
  Energy e;
  e.kinetic = 0.5 * m * v.squaredNorm();
  for (int s = 0; s < scene_.particle_count(); ++s) e.gravity += X_(2, s);
  e.gravity *= m * scene_.params().gravity;
  const auto& set = scene_.springs();
  for (SpringFamily family : all_spring_families) {
    const SpringRange r = set.family[static_cast<int>(family)];
    // The lengths four springs at a time (one vector square root, as in the force loop), the squared stretches
    // then summed one by one in the springs' order: the bits of the plain loop, at a fraction of its cost (the
    // drivers record the energy after every step).
    double sum = 0;
    int k = r.begin;
    for (; r.end - k >= 4; k += 4) {
      Eigen::Vector4d d[4];
      Eigen::Array4d L0;
      for (int j = 0; j < 4; ++j) {
        const Spring& s = set.springs[static_cast<std::size_t>(k + j)];
        d[j] = X_.col(s.p) - X_.col(s.q);
        L0[j] = s.rest_length;
      }
      const Eigen::Array4d stretch = batch_dots<4>(d, d).sqrt() - L0;
      for (int j = 0; j < 4; ++j) sum += stretch[j] * stretch[j];
    }
    for (; k < r.end; ++k) {
      const Spring& s = set.springs[static_cast<std::size_t>(k)];
      const double stretch = (X_.col(s.p) - X_.col(s.q)).norm() - s.rest_length;
      sum += stretch * stretch;
    }
    e.spring += 0.5 * scene_.stiffness(family) * sum;
  }
  if (bending_) e.spring += bending_->energy(x);
  return e;
}

// Calls add(blocks, Bx, Bv) for every spring, with Bx = df_p/dx_p and Bv = df_p/dv_p. Every force of a spring
// depends on x_p - x_q and v_p - v_q only, so its four blocks are +B at (p,p), (q,q) and -B at (p,q), (q,p).
// Expects scatter_state() to have run.
template <class AddBlocks>
void ForceField::for_each_spring_block(StiffnessTreatment treatment, AddBlocks&& add) {
  using Eigen::Matrix3d;
  using Eigen::Vector3d;
  const auto& set = scene_.springs();
  const DampingModel model = scene_.params().damping_model;
  const bool exact = treatment == StiffnessTreatment::exact;
  const bool definite = treatment == StiffnessTreatment::definite;
  const Matrix3d I = Matrix3d::Identity();
  for (SpringFamily family : all_spring_families) {
    const SpringRange r = set.family[static_cast<int>(family)];
    const double K = scene_.stiffness(family);
    const double D = scene_.damping(family);
    for (int k = r.begin; k < r.end; ++k) {
      const Spring& s = set.springs[static_cast<std::size_t>(k)];
      const Vector3d d = X_.col(s.p).head<3>() - X_.col(s.q).head<3>();
      const double l = d.norm();
      if (l <= degenerate_length_fraction * s.rest_length) continue;
      const Vector3d u = d / l;
      const Matrix3d uu = u * u.transpose();
      // Spring: df_p/dx_p = -K [u u^T + (1 - L0/l)(I - u u^T)]. A compressed spring (l < L0) makes the
      // transverse coefficient negative, so the block is indefinite; `definite` drops it, as Choi & Ko
      // (2002) do for their compressed (buckling) springs, whose Jacobian keeps only the u u^T term.
      double transverse = 1.0 - s.rest_length / l;
      if (definite) transverse = std::max(transverse, 0.0);
      Matrix3d Bx = -K * (uu + transverse * (I - uu));
      Matrix3d Bv = Matrix3d::Zero();
      if (D != 0.0) {
        const Vector3d w = V_.col(s.p).head<3>() - V_.col(s.q).head<3>();
        if (model == DampingModel::projected) {
          // f_p = -D (w.u) u: df/dv = -D u u^T; df/dx = -(D/l) [u w^T P + (w.u) P], P = I - u u^T.
          Bv = -D * uu;
          if (exact) {
            const Matrix3d P = I - uu;
            Bx -= (D / l) * (u * (P * w).transpose() + w.dot(u) * P);
          }
        } else {
          // f_p = -D w l: df/dv = -D l I; df/dx = -D w u^T.
          Bv = -D * l * I;
          if (exact) Bx -= D * w * u.transpose();
        }
      }
      add(spring_blocks_[static_cast<std::size_t>(k)], Bx, Bv);
    }
  }
}

namespace {

// values[block column starts + row] += sign * B, for one 3x3 block; start[0] < 0 means the block is absent.
inline void add_block(double* values, const std::array<int, 3>& start, const Eigen::Matrix3d& B, double sign) {
  if (start[0] < 0) return;
  for (int b = 0; b < 3; ++b) {
    double* column = values + start[static_cast<std::size_t>(b)];
    column[0] += sign * B(0, b);
    column[1] += sign * B(1, b);
    column[2] += sign * B(2, b);
  }
}

}  // namespace

void ForceField::jacobians(const ConstVectorRef& x, const ConstVectorRef& v, SparseMatrix& dfdx, SparseMatrix& dfdv) {
  scatter_state(x, v);
  std::fill_n(dfdx.valuePtr(), dfdx.nonZeros(), 0.0);
  std::fill_n(dfdv.valuePtr(), dfdv.nonZeros(), 0.0);
  double* Jx = dfdx.valuePtr();
  double* Jv = dfdv.valuePtr();
  for_each_spring_block(StiffnessTreatment::exact,
                        [&](const SpringBlocks& blocks, const Eigen::Matrix3d& Bx, const Eigen::Matrix3d& Bv) {
                          const auto& c = blocks.column_start;
                          add_block(Jx, c[0], Bx, 1), add_block(Jx, c[1], Bx, 1);
                          add_block(Jx, c[2], Bx, -1), add_block(Jx, c[3], Bx, -1);
                          add_block(Jv, c[0], Bv, 1), add_block(Jv, c[1], Bv, 1);
                          add_block(Jv, c[2], Bv, -1), add_block(Jv, c[3], Bv, -1);
                        });
  if (bending_) bending_->add_hessian(x, false, -1.0, Jx);  // df/dx = -d^2E_bending/dx^2
}

namespace {

// A symmetric 3x3 block given by its three columns, added to or assigned (negated) in place; start[0] < 0
// means the block is absent (it touches a pinned particle).
using Block = std::array<std::array<double, 3>, 3>;
inline void add_block(double* values, const std::array<int, 3>& start, const Block& B) {
  if (start[0] < 0) return;
  for (std::size_t b = 0; b < 3; ++b) {
    double* column = values + start[b];
    column[0] += B[b][0], column[1] += B[b][1], column[2] += B[b][2];
  }
}
inline void assign_negated_block(double* values, const std::array<int, 3>& start, const Block& B) {
  if (start[0] < 0) return;
  for (std::size_t b = 0; b < 3; ++b) {
    double* column = values + start[b];
    column[0] = -B[b][0], column[1] = -B[b][1], column[2] = -B[b][2];
  }
}

}  // namespace

// [lean_refill]
// The Newton matrix when every spring block has the shape alpha u u^T + beta I: no damping, or projected damping
// without its d/dx (the symmetric and definite treatments). With t = 1 - L0/l (clamped at 0 for definite),
//   -h^2 df_p/dx_p = h^2 K [u u^T + t (I - u u^T)],   -h df_p/dv_p = h D u u^T,
// so alpha = h^2 K (1 - t) + h D and beta = h^2 K t: six numbers per block instead of two 3x3 matrix products.
// The frozen dampers of the incremental potential add h D u0 u0^T (projected, along the frozen direction) or
// h D l0 I (report) instead of the h D u u^T in alpha.
void ForceField::refill_symmetric(double h, bool definite, bool frozen, double* values) {
  const bool projected = scene_.params().damping_model == DampingModel::projected;
  const auto& set = scene_.springs();
  const double* X = X_.data();
  for (SpringFamily family : all_spring_families) {
    const SpringRange r = set.family[static_cast<int>(family)];
    const double h2K = h * h * scene_.stiffness(family);
    const double hD = h * scene_.damping(family);
    for (int k = r.begin; k < r.end; ++k) {
      const Spring& s = set.springs[static_cast<std::size_t>(k)];
      const int p = 4 * s.p, q = 4 * s.q;  // X_ holds four numbers per slot
      const double d[3] = {X[p] - X[q], X[p + 1] - X[q + 1], X[p + 2] - X[q + 2]};
      const double l = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      // A degenerate spring contributes nothing, but still writes its (zero) off-diagonal blocks.
      const bool degenerate = l <= degenerate_length_fraction * s.rest_length;
      const double inv_l = degenerate ? 0.0 : 1.0 / l;
      const double u[3] = {d[0] * inv_l, d[1] * inv_l, d[2] * inv_l};
      double t = 1.0 - s.rest_length * inv_l;
      if (definite) t = std::max(t, 0.0);
      const double alpha = degenerate ? 0.0 : h2K * (1.0 - t) + (frozen ? 0.0 : hD);
      double beta = degenerate ? 0.0 : h2K * t;
      // The block alpha u u^T + beta I, computed once: +B on the two diagonal blocks, -B off the diagonal.
      const double a0 = alpha * u[0], a1 = alpha * u[1], a2 = alpha * u[2];
      double B01 = a0 * u[1], B02 = a0 * u[2], B12 = a1 * u[2];
      double B00 = a0 * u[0], B11 = a1 * u[1], B22 = a2 * u[2];
      if (frozen && hD != 0.0 && !degenerate) {
        if (projected) {
          const double* u0 = frozen_direction_.col(k).data();
          const double b0 = hD * u0[0], b1 = hD * u0[1], b2 = hD * u0[2];
          B00 += b0 * u0[0], B11 += b1 * u0[1], B22 += b2 * u0[2];
          B01 += b0 * u0[1], B02 += b0 * u0[2], B12 += b1 * u0[2];
        } else {
          beta += hD * frozen_length_[static_cast<std::size_t>(k)];
        }
      }
      const Block B = {{{B00 + beta, B01, B02}, {B01, B11 + beta, B12}, {B02, B12, B22 + beta}}};
      const auto& c = spring_blocks_[static_cast<std::size_t>(k)].column_start;
      // Diagonal blocks collect every spring of their particle; an off-diagonal block belongs to one spring
      // alone, so it is assigned, and only the diagonal blocks had to be cleared.
      add_block(values, c[0], B);
      add_block(values, c[1], B);
      assign_negated_block(values, c[2], B);
      assign_negated_block(values, c[3], B);
    }
  }
}
// [lean_refill]

void ForceField::newton_matrix(const ConstVectorRef& x, const ConstVectorRef& v, double h,
                               StiffnessTreatment treatment, SparseMatrix& A) {
  scatter_state(x, v);
  double* values = A.valuePtr();
  const double m = scene_.params().mass;
  // Without damping, exact and symmetric are the same matrix; projected damping is symmetric once its d/dx goes.
  const bool lean = !scene_.has_damping() ||
                    (scene_.params().damping_model == DampingModel::projected && treatment != StiffnessTreatment::exact);
  const bool definite = treatment == StiffnessTreatment::definite;
  if (lean) {
    // Every off-diagonal block is assigned by its spring, so only the diagonal blocks are cleared; a hinge's
    // blocks between particles no spring joins are cleared with the rest.
    if (bending_)
      std::fill_n(values, A.nonZeros(), 0.0);
    else
      for (const auto& start : diagonal_blocks_)
        for (int b : start) std::fill_n(values + b, 3, 0.0);
    for (int k : diagonal_entry_) values[k] = m;
    refill_symmetric(h, definite, false, values);
  } else {
    std::fill_n(values, A.nonZeros(), 0.0);
    for (int k : diagonal_entry_) values[k] = m;
    for_each_spring_block(treatment, [&](const SpringBlocks& blocks, const Eigen::Matrix3d& Bx, const Eigen::Matrix3d& Bv) {
      // A = M - h df/dv - h^2 df/dx, block by block.
      const Eigen::Matrix3d C = -h * Bv - (h * h) * Bx;
      const auto& c = blocks.column_start;
      add_block(values, c[0], C, 1), add_block(values, c[1], C, 1);
      add_block(values, c[2], C, -1), add_block(values, c[3], C, -1);
    });
  }
  // The bending term's h^2 d^2E/dx^2; definite keeps the hinge's Gauss-Newton part (model/bending.hpp).
  if (bending_) bending_->add_hessian(x, definite, h * h, values);
}

void ForceField::frozen_newton_matrix(const ConstVectorRef& x, double h, StiffnessTreatment treatment,
                                      SparseMatrix& A) {
  // The frozen dampers do not depend on x, so the spring blocks keep the shape alpha u u^T + beta I of the lean
  // refill, whatever the damping law: the Hessian of the incremental potential is symmetric.
  X_.topLeftCorner(3, scene_.free_count()) = x.reshaped(3, scene_.free_count());
  double* values = A.valuePtr();
  if (bending_)
    std::fill_n(values, A.nonZeros(), 0.0);
  else
    for (const auto& start : diagonal_blocks_)
      for (int b : start) std::fill_n(values + b, 3, 0.0);
  for (int k : diagonal_entry_) values[k] = scene_.params().mass;
  const bool definite = treatment == StiffnessTreatment::definite;
  refill_symmetric(h, definite, scene_.has_damping(), values);
  if (bending_) bending_->add_hessian(x, definite, h * h, values);
}

}  // namespace cloth
