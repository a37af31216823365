// Rooted trees generated order by order (a tree of order n is a root over a multiset of smaller trees whose orders
// sum to n - 1), their densities, elementary weights and the order conditions written out as sums.
#include "integrators/order_conditions.hpp"

#include <cmath>
#include <functional>

namespace cloth {

namespace {

// The summation indices of the written-out conditions, root first: sum b_i ..., a_ij, a_jk, ...
constexpr const char index_names[] = "ijklmnopq";

// Phi_i(t) written out with `root` as the index of t's root, e.g. "c_i a_ij c_j" for [t [t]]; fresh indices are
// taken from `next`. A leaf child contributes sum_j a_ij = c_i; equal leaf children are gathered into a power.
std::string weight_text(const std::vector<RootedTree>& trees, const RootedTree& t, char root, int& next) {
  std::string text;
  int leaves = 0;
  for (int child : t.children)
    if (trees[static_cast<std::size_t>(child)].order == 1) ++leaves;
  if (leaves > 0) {
    text += "c_";
    text.push_back(root);
    if (leaves > 1) text.append(1, '^').append(std::to_string(leaves));
  }
  for (int child : t.children) {
    const RootedTree& sub = trees[static_cast<std::size_t>(child)];
    if (sub.order == 1) continue;
    const char j = index_names[next++];
    if (!text.empty()) text += ' ';
    text += "a_";
    text.push_back(root);
    text.push_back(j);
    const std::string inner = weight_text(trees, sub, j, next);
    if (!inner.empty()) text += " " + inner;
  }
  return text;
}

std::vector<RootedTree> generate() {
  std::vector<RootedTree> trees;
  // [generate_trees]
  trees.push_back({1, {}, 1, "t", ""});
  for (int n = 2; n <= max_tree_order; ++n) {
    const std::size_t smaller = trees.size();  // every tree of order < n
    std::vector<int> children;
    // Multisets of smaller trees with orders summing to n - 1, as non-decreasing index sequences.
    const std::function<void(int, std::size_t)> extend = [&](int remaining, std::size_t first) {
      if (remaining == 0) {
        RootedTree t;
        t.order = n;
        t.children = children;
        t.density = n;
        for (int c : children) t.density *= trees[static_cast<std::size_t>(c)].density;
        trees.push_back(t);
        return;
      }
      for (std::size_t k = first; k < smaller; ++k) {
        if (trees[k].order > remaining) continue;
        children.push_back(static_cast<int>(k));
        extend(remaining - trees[k].order, k);
        children.pop_back();
      }
    };
    extend(n - 1, 0);
  }
  // [generate_trees]
  // Names: brackets with equal neighbours gathered into powers, and the written-out sum.
  for (RootedTree& t : trees) {
    if (t.order == 1) continue;
    std::string inside;
    for (std::size_t k = 0; k < t.children.size();) {
      std::size_t run = k;
      while (run < t.children.size() && t.children[run] == t.children[k]) ++run;
      if (!inside.empty()) inside += ' ';
      inside += trees[static_cast<std::size_t>(t.children[k])].bracket;
      if (run - k > 1) inside.append(1, '^').append(std::to_string(run - k));
      k = run;
    }
    t.bracket = "[" + inside + "]";
  }
  for (RootedTree& t : trees) {
    int next = 1;
    const std::string phi = t.order == 1 ? "" : weight_text(trees, t, 'i', next);
    t.condition = "sum b_i";
    if (!phi.empty()) t.condition += " " + phi;
    t.condition += t.density == 1 ? std::string(" = 1") : " = 1/" + std::to_string(t.density);
  }
  return trees;
}

}  // namespace

const std::vector<RootedTree>& rooted_trees() {
  static const std::vector<RootedTree> trees = generate();
  return trees;
}

std::vector<Eigen::VectorXd> elementary_weights(const Eigen::MatrixXd& A, int max_order) {
  const std::vector<RootedTree>& trees = rooted_trees();
  std::vector<Eigen::VectorXd> phi;
  std::vector<Eigen::VectorXd> A_phi;  // A Phi(t), the factor t contributes to a parent
  // [elementary_weights]
  for (const RootedTree& t : trees) {
    if (t.order > max_order) break;
    Eigen::VectorXd w = Eigen::VectorXd::Ones(A.rows());
    for (int c : t.children) w = w.cwiseProduct(A_phi[static_cast<std::size_t>(c)]);
    A_phi.push_back(A * w);
    phi.push_back(std::move(w));
  }
  // [elementary_weights]
  return phi;
}

double order_condition_defect(const Eigen::MatrixXd& A, const Eigen::VectorXd& w, int p, int* worst) {
  const std::vector<RootedTree>& trees = rooted_trees();
  const std::vector<Eigen::VectorXd> phi = elementary_weights(A, p);
  double defect = 0;
  int arg = -1;
  for (std::size_t k = 0; k < phi.size(); ++k) {
    if (trees[k].order != p) continue;
    const double residual = std::abs(w.dot(phi[k]) - 1.0 / static_cast<double>(trees[k].density));
    if (arg < 0 || residual > defect) defect = residual, arg = static_cast<int>(k);
  }
  if (worst != nullptr) *worst = arg;
  return defect;
}

}  // namespace cloth
