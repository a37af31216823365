// The properties a Butcher tableau decides, computed from its coefficients (see tableau_properties.hpp).
#include "analysis/tableau_properties.hpp"

#include "analysis/stability_function.hpp"

#include <algorithm>
#include <cmath>

namespace cloth {

namespace {

// Rounding tolerance: the book's tableaus are fractions and square roots, so their identities hold to a few ulps.
constexpr double tolerance = 1e-12;

// The largest p <= 8 such that the order conditions of orders 1 to p hold for b (or b-hat).
int satisfied_order(const ButcherTableau& t, bool embedded) {
  int p = 0;
  while (p < 8 && order_condition_defect(t, p + 1, embedded) <= tolerance) ++p;
  return p;
}

}  // namespace

TableauProperties tableau_properties(const ButcherTableau& t) {
  TableauProperties p;
  const int s = t.stages();
  p.stages = s;
  p.explicit_method = true;
  for (int i = 0; i < s; ++i)
    for (int j = i; j < s; ++j)
      if (t.A(i, j) != 0.0) p.explicit_method = false;
  p.explicit_first_stage = !p.explicit_method && t.A.row(0).cwiseAbs().maxCoeff() == 0.0;
  p.order = satisfied_order(t, false);
  p.embedded_order = t.has_embedded() ? satisfied_order(t, true) : 0;
  p.stiffly_accurate = (t.A.row(s - 1).transpose() - t.b).cwiseAbs().maxCoeff() <= tolerance;
  p.r_infinity = stability_at_infinity(t);
  p.a_stable = !p.explicit_method && a_stable(t);
  p.l_stable = p.a_stable && std::abs(p.r_infinity) <= 1e-9;  // stability_at_infinity is good to about 1e-11
  double worst = 0;
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j)
      worst = std::max(worst, std::abs(t.b[i] * t.A(i, j) + t.b[j] * t.A(j, i) - t.b[i] * t.b[j]));
  p.symplectic = worst <= tolerance;
  return p;
}

}  // namespace cloth
