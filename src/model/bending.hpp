// Bending energies on the grid's triangles (Chapter 12): the discrete hinge energy of Bridson, Marino & Fedkiw
// (2003) and Grinspun, Hirani, Desbrun & Schroeder (2003), and the quadratic isometric model of Bergou, Wardetzky,
// Harmon, Zorin & Grinspun (2006), with their gradients and Hessians, scaled so that one bending rigidity B [N m]
// gives the same sheet at every spacing.
#pragma once

#include "base/name_table.hpp"
#include "model/force_field.hpp"
#include "model/grid.hpp"
#include "model/scene.hpp"

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

namespace cloth {

/// The models by name: flexion, hinge, quadratic.
const NameTable<BendingModel>& bending_models();

using Vector12 = Eigen::Matrix<double, 12, 1>;
using Matrix12 = Eigen::Matrix<double, 12, 12>;

/// One hinge: the edge (p0, p1) shared by the triangles (p0, p1, p2) and (p1, p0, p3), as particle numbers, with
/// its rest quantities. Coordinates of the four particles are stacked x0, x1, x2, x3 in a 12-vector.
struct Hinge {
  std::array<int, 4> particle{};
  /// |e|^2 / A_e at rest: the squared edge length over the two triangles' area. theta ~ kappa times the distance
  /// between the triangles' centroids, so (B/2) theta^2 |e|^2 / A_e is (B/2) kappa^2 times an area: the weight
  /// that makes the energy independent of the spacing.
  double shape = 0;
  double area = 0;  ///< A_e: the two triangles' rest area [m^2]
  /// c: 1/2 when the grid's two triangulations are superposed, doubled on a clamp's edge (BendingEnergy)
  double weight_factor = 1;
  /// The quadratic model's weights: sum_i w_i x_i vanishes on every plane image of the rest hinge (sum w_i = 0,
  /// sum w_i X_i = 0) and equals |e| theta n to first order when the hinge folds by theta (w2 = |e| / h2,
  /// w3 = |e| / h3 for the apex heights h2, h3; Bergou et al. 2006 write them with cotangents).
  std::array<double, 4> weight{};
};

/// The splits by name: uniform, both.
const NameTable<GridSplit>& grid_splits();

/// The interior edges of the split grid as hinges, with shape = c |e|^2 / A_e. On one triangulation c = 1: a
/// sheet bent uniformly about a grid line or about the split diagonal then has the continuum energy
/// B kappa^2 / 2 per area, but one bent about the other diagonal three times that, and twist is coupled to
/// bending: the apices of the hinges along x and y sit off-centre along their edges, so their angles pick up the
/// twist. A free strip twists to relieve its bending and is 20 % softer than B says. `both` superposes the two
/// triangulations with c = 1/2: the off-centre terms cancel, bending about any grid line costs B kappa^2 / 2 per
/// area, bending about a diagonal twice that and twist three times the continuum's (Chapter 12 derives all of
/// these from the hinges' weights).
std::vector<Hinge> grid_hinges(const Grid& grid, GridSplit split);

/// True when the hinge has no dihedral angle: its edge has collapsed to a point, or an apex lies on the edge's
/// line (a triangle of zero area, its apex within eps |e| of the line). hinge_angle, its gradient and Hessians
/// are then 0 (the hinge contributes nothing), not the 0/0 of their formulas: a crushed cell costs no bending and
/// gives no NaN.
bool hinge_degenerate(const Vector12& x);

/// The signed dihedral angle theta of a hinge, the angle between the normals N1 = e x (x2 - x0) and
/// N2 = (x3 - x0) x e, e = x1 - x0: 0 when flat, positive when the apices drop below the side N1 points to (a
/// ridge seen from there). By atan2, so that it is accurate near 0 and defined up to +-pi.
double hinge_angle(const Vector12& x);

/// d theta / dx: the apex terms -|e| N / |N|^2 (N a triangle's area-weighted normal), the edge terms from the
/// apices' positions along the edge (Bridson et al. 2003).
Vector12 hinge_angle_gradient(const Vector12& x);

/// d^2 theta / dx^2 in closed form: hinge_angle_gradient's formula differentiated term by term (the apex terms'
/// normals and lengths, the feet of the apices along the edge); Tamstorf & Grinspun 2013 derive an equivalent
/// form from the normals' angles.
Matrix12 hinge_angle_hessian(const Vector12& x);

/// The same d^2 theta / dx^2 by forward-mode differentiation (Eigen's AutoDiff) of the gradient's formula: exact
/// up to rounding and independent of the closed form's algebra, which the tests check against it; Chapter 12
/// times the two.
Matrix12 hinge_angle_hessian_forward_mode(const Vector12& x);

/// The bending energy of a scene's sheet and its derivatives with respect to the free particles' positions.
/// The flexion model has no hinges here: its energy is in the flexion springs of the ForceField. Owns the
/// Hessian's sparsity pattern (3x3 blocks between free particles of a hinge), built at the first hessian().
class BendingEnergy {
 public:
  BendingEnergy(const Scene& scene, BendingModel model, double bending_rigidity,
                GridSplit split = GridSplit::both);

  [[nodiscard]] BendingModel model() const { return model_; }
  [[nodiscard]] const std::vector<Hinge>& hinges() const { return hinges_; }

  /// The energy [J] at free positions x (pinned particles at rest).
  double energy(const ConstVectorRef& x);
  /// Adds the bending force -dE/dx to f.
  void add_forces(const ConstVectorRef& x, VectorRef f);
  /// The Hessian d^2E/dx^2 refilled in place, in its own pattern. `definite`: the hinge model keeps only its
  /// positive semi-definite part (B |e|^2 / A_e) grad theta grad theta^T (Gauss-Newton); the quadratic model's
  /// Hessian is constant and semi-definite already.
  const SparseMatrix& hessian(const ConstVectorRef& x, bool definite);

  /// The 3x3 blocks (zeros) the Hessian fills, between the free particles of each hinge: a caller that holds the
  /// Hessian inside a larger matrix (the ForceField's) puts them in its pattern, then calls bind() with it.
  void add_pattern_blocks(std::vector<Eigen::Triplet<double>>& triplets) const;
  /// Finds where every hinge block lies in `pattern`'s values (which must hold them), once per pattern.
  void bind(const SparseMatrix& pattern);
  /// values += scale d^2E/dx^2 (definite as for hessian()) in the values of the pattern last bound: allocates
  /// nothing. The quadratic model's constant Hessian is assembled once, by bind(), and added as one array.
  void add_hessian(const ConstVectorRef& x, bool definite, double scale, double* values);

 private:
  Vector12 gather(const Hinge& h) const;
  // Every hinge's 12 x 12 Hessian, scaled, added block by block into the bound pattern's values (x is read by
  // the hinge model only).
  void add_hinge_hessians(const ConstVectorRef& x, bool definite, double scale, double* values);
  const Scene& scene_;
  BendingModel model_;
  double B_;
  std::vector<Hinge> hinges_;
  Vector all_;  // all particles' positions, grid order
  SparseMatrix H_;  // hessian()'s own matrix, its pattern built at the first call
  // Per hinge, per block (a, b) of its 4 x 4 particles and per column c of the block: the value index of the
  // block's first row in that column of the pattern last bound, or -1 when a or b is pinned.
  std::vector<std::array<int, 48>> block_start_;
  std::vector<double> constant_values_;  // the quadratic model's Hessian in the bound pattern's values
};

}  // namespace cloth
