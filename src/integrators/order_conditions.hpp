// Rooted trees and the order conditions they stand for: Butcher's theory generates every condition a Runge-Kutta
// method of order p must satisfy, so that no condition has to be typed by hand (Chapters 3 and 8). It stands
// here, among the integrators, rather than in analysis/ beside the tableaus' other properties, because the
// integrator layer uses it: butcher_tableau.cpp refuses a tableau whose coefficients do not satisfy the order it
// declares, and a layer uses only the layers before it (base, model, integrators, analysis, program).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace cloth {

/// A rooted tree t: a root whose subtrees are `children` (indices into rooted_trees(), in non-decreasing order).
/// The order condition it stands for is  sum_i b_i Phi_i(t) = 1 / gamma(t)  (Butcher 2016, section 31;
/// Hairer, Norsett & Wanner 1993, II.2), with the elementary weights
///   Phi(tau) = (1, ..., 1),   Phi([t_1, ..., t_m])_i = prod_k (A Phi(t_k))_i,
/// and the density gamma(tau) = 1, gamma([t_1, ..., t_m]) = |t| prod_k gamma(t_k).
struct RootedTree {
  int order = 1;              ///< |t|, the number of nodes
  std::vector<int> children;  ///< the subtrees of the root
  long long density = 1;      ///< gamma(t)
  std::string bracket;        ///< Butcher's notation: "t", "[t]", "[t^2]", "[[t]]", "[t [t]]", ...
  std::string condition;      ///< the condition as a sum: "sum b_i c_i a_ij c_j = 1/8"
};

/// The largest order the trees are generated for (200 trees; a 7(8) pair needs them all).
inline constexpr int max_tree_order = 8;

/// Every rooted tree with 1 to max_tree_order nodes, ordered by order; a tree's children come before it.
/// The counts by order are 1, 1, 2, 4, 9, 20, 48, 115 (Cayley; OEIS A000081).
const std::vector<RootedTree>& rooted_trees();

/// The elementary weights Phi(t) of every tree of rooted_trees() up to `max_order`, for the matrix A.
std::vector<Eigen::VectorXd> elementary_weights(const Eigen::MatrixXd& A, int max_order);

/// The largest |sum_i w_i Phi_i(t) - 1/gamma(t)| over the trees of order p: 0 (to rounding) when the weights
/// `w` (b, or the embedded b-hat) satisfy every condition of order p. `worst`, when given, receives the index of
/// the tree with the largest residual.
double order_condition_defect(const Eigen::MatrixXd& A, const Eigen::VectorXd& w, int p, int* worst = nullptr);

}  // namespace cloth
