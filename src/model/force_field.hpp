// The forces of docs/model.md on the free particles (spring, damping, gravity), their energies, and their analytic
// Jacobians df/dx and df/dv assembled into sparse matrices whose pattern is built once per scene.
#pragma once

#include "base/name_table.hpp"
#include "model/scene.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <memory>
#include <vector>

namespace cloth {

using Vector = Eigen::VectorXd;
using ConstVectorRef = Eigen::Ref<const Eigen::VectorXd>;
using VectorRef = Eigen::Ref<Eigen::VectorXd>;
using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major (CSC), full storage of both triangles

/// The three parts of the energy E = kinetic + gravity + spring (docs/model.md), in joules.
struct Energy {
  double kinetic = 0;
  double gravity = 0;
  double spring = 0;  ///< the elastic energy: the springs', plus the bending term's when the scene has one
  [[nodiscard]] double total() const { return kinetic + gravity + spring; }
};

/// How the Newton matrix treats the two terms of df/dx that break symmetry or definiteness.
enum class StiffnessTreatment {
  exact,      ///< df/dx as it is: indefinite for compressed springs, non-symmetric when damping is on
  symmetric,  ///< the exact spring Hessian, but the damper's d/dx dropped (Baraff & Witkin 1998): symmetric,
              ///< possibly indefinite; identical to exact for an undamped cloth
  definite    ///< also Choi & Ko (2002): compressed springs lose their transverse term, so the matrix is
              ///< symmetric positive definite
};

/// The treatments by name: exact, symmetric, definite.
const NameTable<StiffnessTreatment>& stiffness_treatments();

/// Below this fraction of its rest length a spring has no defined direction u; it then exerts no force and
/// contributes nothing to the Jacobians (the guard for coincident particles, Chapter 7).
inline constexpr double degenerate_length_fraction = 1e-12;

class BendingEnergy;

/// Evaluates forces, energies and Jacobians of one scene, the bending term of its `bending` model included. Owns the scratch space and the sparsity pattern, so
/// nothing is allocated after construction. Not thread-safe: one ForceField per thread.
class ForceField {
 public:
  explicit ForceField(const Scene& scene);
  ~ForceField();
  ForceField(const ForceField&) = delete;
  ForceField& operator=(const ForceField&) = delete;

  [[nodiscard]] const Scene& scene() const { return scene_; }
  [[nodiscard]] int dof_count() const { return scene_.dof_count(); }

  /// f(x, v): the total force on every free particle (3 n_free values).
  void forces(const ConstVectorRef& x, const ConstVectorRef& v, VectorRef f);

  /// The acceleration M^{-1} f(x, v), the right-hand side of v' = M^{-1} f.
  void acceleration(const ConstVectorRef& x, const ConstVectorRef& v, VectorRef a);

  /// Kinetic, gravitational and spring energy of the state (pinned particles included, at rest).
  [[nodiscard]] Energy energy(const ConstVectorRef& x, const ConstVectorRef& v);

  /// The scene's bending energy (hinge or quadratic, Chapter 12), or nullptr when its model is flexion: its
  /// forces and Hessian are already in every force and matrix below; methods that do not use them (XPBD,
  /// local/global) add its forces themselves.
  [[nodiscard]] BendingEnergy* bending() { return bending_.get(); }

  /// An all-zero matrix with the sparsity pattern shared by df/dx, df/dv and the Newton matrix:
  /// a 3x3 block per free particle, per spring joining two free particles and, with a bending term, between
  /// the free particles of each hinge.
  [[nodiscard]] const SparseMatrix& pattern() const { return pattern_; }

  /// The exact analytic Jacobians df/dx and df/dv, refilled in place (they must have pattern()'s pattern).
  void jacobians(const ConstVectorRef& x, const ConstVectorRef& v, SparseMatrix& dfdx, SparseMatrix& dfdv);

  /// The Newton matrix of implicit Euler, A = M - h df/dv - h^2 df/dx, refilled in place in pattern().
  void newton_matrix(const ConstVectorRef& x, const ConstVectorRef& v, double h, StiffnessTreatment treatment,
                     SparseMatrix& A);

  /// Freezes every damper's geometry at the positions x0 (Chapter 4's incremental potential): the projected
  /// damper's direction u0 and the report damper's length l0. With them the damping force is -dR/dv of the
  /// quadratic dissipation potential R(v) = 1/2 sum D ((v_p - v_q).u0)^2 (projected) or
  /// 1/2 sum D l0 |v_p - v_q|^2 (report), which the current-geometry dampers are not. Kept until the next call.
  void freeze_dampers(const ConstVectorRef& x0);

  /// The two potentials of a state with frozen dampers, in joules and watts.
  struct Potentials {
    double spring = 0;       ///< E_spring(x) = 1/2 sum K (l - L0)^2 [J], plus the bending energy if any
    double dissipation = 0;  ///< R(v), the dissipation potential of the frozen dampers [W]
    int terms = 0;           ///< how many nonnegative terms the two sums added (their rounding bound)
  };
  /// f(x, v) with the dampers frozen by freeze_dampers(), and E_spring(x) and R(v) from the same pass over the
  /// springs: f = -dE_spring/dx - dR/dv - gravity's m g e_z. Without damping it is forces() plus the energy.
  Potentials frozen_forces(const ConstVectorRef& x, const ConstVectorRef& v, VectorRef f);

  /// The Newton matrix of the frozen-damper stage equation, A = M + h^2 d^2E_spring/dx^2 + h d^2R/dv^2, the
  /// Hessian of the incremental potential (symmetric for every damping law); `treatment` acts on the spring part:
  /// exact and symmetric keep it, definite drops compressed springs' transverse term. Refilled in pattern().
  void frozen_newton_matrix(const ConstVectorRef& x, double h, StiffnessTreatment treatment, SparseMatrix& A);

 private:
  // Where one spring's four 3x3 blocks (pp, qq, pq, qp) start in the value array, per block column; -1 when a
  // block touches a pinned particle (pinned particles are not unknowns, so those blocks do not exist).
  struct SpringBlocks {
    std::array<std::array<int, 3>, 4> column_start;
  };
  void scatter_state(const ConstVectorRef& x, const ConstVectorRef& v);
  template <class AddBlocks>
  void for_each_spring_block(StiffnessTreatment treatment, AddBlocks&& add);
  // The Newton matrix's spring blocks when each is alpha u u^T + beta I (see force_field.cpp), plus the frozen
  // damper's h D u0 u0^T or h D l0 I when `frozen`; expects scatter_state() to have run and the mass diagonal to
  // be in `values`.
  void refill_symmetric(double h, bool definite, bool frozen, double* values);
  // The spring and damping forces of every family into F_ (cleared first), with the dampers frozen or not; the
  // frozen pass also sums the potentials.
  void spring_pass(bool frozen, Potentials* potentials);

  // One column (x, y, z, 0) per slot: a particle is one 4-double vector, so a spring reads and writes its two
  // particles with whole-vector loads and stores instead of three scalars each (see force_field.cpp).
  using SlotMatrix = Eigen::Matrix<double, 4, Eigen::Dynamic>;

  const Scene& scene_;
  SlotMatrix X_;  // all slots' positions: x in the free columns, the pinned rest positions in the tail
  SlotMatrix V_;  // all slots' velocities: v in the free columns, zeros in the tail
  SlotMatrix F_;  // all slots' forces; the tail (forces on pinned particles) is computed and ignored
  SparseMatrix pattern_;
  std::vector<SpringBlocks> spring_blocks_;
  std::vector<int> diagonal_entry_;  // value index of entry (k, k), for the mass term
  std::vector<std::array<int, 3>> diagonal_blocks_;  // column starts of each free particle's diagonal block
  SlotMatrix frozen_direction_;        // u0 of every spring, (x, y, z, 0), when the scene is damped
  std::vector<double> frozen_length_;  // l0 of every spring, when the scene is damped
  std::unique_ptr<BendingEnergy> bending_;  // the scene's hinges, when its model is hinge or quadratic
};

}  // namespace cloth
