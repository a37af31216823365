// The cloth as SUNDIALS sees it: the first-order system y = (x, v), y' = (v, f(x, v) / m), with its analytic sparse
// Jacobian in compressed columns (exact, or with df/dx as the book's Newton matrix treats it), both callbacks
// counting their evaluations and honouring a stop request.
#pragma once

#include "model/force_field.hpp"
#include "program/sundials.hpp"

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_sparse.h>

namespace ch09 {

// y = (x, v) for SUNDIALS: y' = (v, f(x, v) / m), and its Jacobian [[0, I], [df/dx / m, df/dv / m]] in
// compressed columns with every diagonal entry stored (SUNDIALS forms I - gamma J in place). With a treatment other
// than exact, df/dx is the one the book's Newton matrix of that treatment holds (the definite one: Choi & Ko 2002,
// compressed springs without their transverse term), read off A = M - df/dv - df/dx at h = 1.
struct ClothSystem {
  cloth::ForceField& field;
  int n;  // free coordinates
  double mass;
  cloth::StiffnessTreatment treatment;
  cloth::SparseMatrix dfdx, dfdv, newton;
  cloth::Vector f;
  long long rhs_evaluations = 0, jacobian_evaluations = 0;

  explicit ClothSystem(cloth::ForceField& fld, cloth::StiffnessTreatment treat = cloth::StiffnessTreatment::exact)
      : field(fld), n(fld.dof_count()), mass(fld.scene().params().mass), treatment(treat), dfdx(fld.pattern()),
        dfdv(fld.pattern()), newton(fld.pattern()), f(fld.dof_count()) {}

  // df/dx = M - df/dv - A(h = 1), entry by entry: the three matrices share the pattern, and nothing is allocated.
  void treated_dfdx(const Eigen::Map<const cloth::Vector>& x, const Eigen::Map<const cloth::Vector>& v) {
    field.newton_matrix(x, v, 1.0, treatment, newton);
    const Eigen::Index nonzeros = dfdx.nonZeros();
    for (Eigen::Index k = 0; k < nonzeros; ++k) dfdx.valuePtr()[k] = -dfdv.valuePtr()[k] - newton.valuePtr()[k];
    for (int i = 0; i < n; ++i) dfdx.coeffRef(i, i) += mass;
  }

  [[nodiscard]] sunindextype nonzeros() const { return 2 * n + 2 * static_cast<sunindextype>(dfdx.nonZeros()); }

  // Each callback first honours a stop request (SIGINT, SIGTERM): the integration then ends within one
  // evaluation, however long the run (program/sundials.hpp).
  static int rhs(realtype /*t*/, N_Vector y, N_Vector ydot, void* data) {
    if (const int stop = cloth::sundials_stop_requested()) return stop;
    auto& s = *static_cast<ClothSystem*>(data);
    const Eigen::Map<const cloth::Vector> x(N_VGetArrayPointer(y), s.n), v(N_VGetArrayPointer(y) + s.n, s.n);
    Eigen::Map<cloth::Vector> dx(N_VGetArrayPointer(ydot), s.n), dv(N_VGetArrayPointer(ydot) + s.n, s.n);
    s.field.forces(x, v, s.f);
    dx = v;
    dv = s.f / s.mass;
    ++s.rhs_evaluations;
    return 0;
  }

  static int jacobian(realtype /*t*/, N_Vector y, N_Vector /*fy*/, SUNMatrix J, void* data, N_Vector /*tmp1*/,
                      N_Vector /*tmp2*/, N_Vector /*tmp3*/) {
    if (const int stop = cloth::sundials_stop_requested()) return stop;
    auto& s = *static_cast<ClothSystem*>(data);
    const Eigen::Map<const cloth::Vector> x(N_VGetArrayPointer(y), s.n), v(N_VGetArrayPointer(y) + s.n, s.n);
    s.field.jacobians(x, v, s.dfdx, s.dfdv);
    if (s.treatment != cloth::StiffnessTreatment::exact) s.treated_dfdx(x, v);
    ++s.jacobian_evaluations;
    sunindextype* start = SUNSparseMatrix_IndexPointers(J);
    sunindextype* row = SUNSparseMatrix_IndexValues(J);
    realtype* value = SUNSparseMatrix_Data(J);
    sunindextype k = 0;
    const auto column = [&](int c, const cloth::SparseMatrix& block, double diagonal) {
      start[c] = k;
      row[k] = c < s.n ? c : c - s.n;  // the upper block's entry: 0 (x columns) or I (v columns)
      value[k++] = diagonal;
      const int bc = c < s.n ? c : c - s.n;
      for (cloth::SparseMatrix::InnerIterator it(block, bc); it; ++it) {
        row[k] = s.n + it.row();
        value[k++] = it.value() / s.mass;
      }
    };
    for (int c = 0; c < s.n; ++c) column(c, s.dfdx, 0.0);
    for (int c = s.n; c < 2 * s.n; ++c) column(c, s.dfdv, 1.0);
    start[2 * s.n] = k;
    return 0;
  }
};

}  // namespace ch09
