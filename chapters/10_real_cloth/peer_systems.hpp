// The two right-hand sides Chapter 10's peer programs drive Boost.Odeint and SUNDIALS with: y = (x, v), y' = (v, a),
// and the Jacobian dy'/dy in compressed columns, from a reader's plain loop (plain_fabric.hpp) or from the book's
// force routine; with the SUNDIALS callbacks over them. The Jacobian is the exact one, or with `definite` the
// matrix the book's Newton uses (compressed springs' transverse term and the damper's d/dx dropped).
#pragma once

#include "../06_speed_vs_error/plain_fabric.hpp"

#include "base/format_number.hpp"
#include "model/force_field.hpp"
#include "model/scene.hpp"
#include "program/sundials.hpp"

#include <sunmatrix/sunmatrix_sparse.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace ch10 {

using cloth::Vector;

struct OdeSystem {
  virtual ~OdeSystem() = default;
  [[nodiscard]] virtual int size() const = 0;
  [[nodiscard]] virtual std::vector<double> initial_state() const = 0;
  virtual void rhs(const double* y, double* dydt) = 0;
  [[nodiscard]] virtual long nonzeros() const = 0;
  /// Fills a compressed-column matrix with the Jacobian at y (pattern and values).
  virtual void jacobian(const double* y, sunindextype* starts, sunindextype* rows, double* values) = 0;
  /// Every particle's position (pinned ones included, grid order) from a state.
  [[nodiscard]] virtual Vector positions(const std::vector<double>& y) const = 0;
};

// A reader's own loop over the springs.
class PlainSystem : public OdeSystem {
 public:
  explicit PlainSystem(const cloth::SceneParams& p, bool definite = false)
      : cloth_(p.grid.M, p.grid.N, p.grid.d, p.stiffness, p.damping, p.mass, p.gravity, p.initial_velocity_z,
               p.pins == cloth::PinSet::edge, p.initial_swing),
        definite_(definite) {}
  [[nodiscard]] int size() const override { return cloth_.size(); }
  [[nodiscard]] std::vector<double> initial_state() const override { return cloth_.initial_state(); }
  void rhs(const double* y, double* dydt) override { cloth_.rhs(y, dydt); }
  [[nodiscard]] long nonzeros() const override { return cloth_.nonzeros(); }
  void jacobian(const double* y, sunindextype* starts, sunindextype* rows, double* values) override {
    std::copy(cloth_.column_starts().begin(), cloth_.column_starts().end(), starts);
    std::copy(cloth_.rows().begin(), cloth_.rows().end(), rows);
    cloth_.jacobian(y, values, definite_);
  }
  [[nodiscard]] Vector positions(const std::vector<double>& y) const override {
    return Eigen::Map<const Vector>(y.data(), 3 * cloth_.particles());
  }

 private:
  ch06::PlainFabric cloth_;
  bool definite_;
};

// The book's force routine, cloth::ForceField, on the free particles.
class CoreSystem : public OdeSystem {
 public:
  explicit CoreSystem(const cloth::Scene& scene, bool definite = false)
      : scene_(scene), field_(scene_), n_(scene.dof_count()), dfdx_(field_.pattern()), dfdv_(field_.pattern()),
        newton_(field_.pattern()), definite_(definite) {}
  [[nodiscard]] int size() const override { return 2 * n_; }
  [[nodiscard]] std::vector<double> initial_state() const override {
    std::vector<double> y(static_cast<std::size_t>(2 * n_));
    Eigen::Map<Vector>(y.data(), n_) = scene_.initial_positions();
    Eigen::Map<Vector>(y.data() + n_, n_) = scene_.initial_velocities();
    return y;
  }
  void rhs(const double* y, double* dydt) override {
    Eigen::Map<Vector>(dydt, n_) = Eigen::Map<const Vector>(y + n_, n_);
    field_.acceleration(Eigen::Map<const Vector>(y, n_), Eigen::Map<const Vector>(y + n_, n_),
                        Eigen::Map<Vector>(dydt + n_, n_));
  }
  [[nodiscard]] long nonzeros() const override { return 2L * n_ + 2L * dfdx_.nonZeros(); }
  // [[0, I], [df/dx / m, df/dv / m]], the upper half's diagonal stored in every column.
  void jacobian(const double* y, sunindextype* starts, sunindextype* rows, double* values) override {
    const Eigen::Map<const Vector> x(y, n_), v(y + n_, n_);
    field_.jacobians(x, v, dfdx_, dfdv_);
    if (definite_) {  // the book's definite df/dx from its Newton matrix at h = 1: M - df/dv - A(1)
      field_.newton_matrix(x, v, 1.0, cloth::StiffnessTreatment::definite, newton_);
      cloth::SparseMatrix mass(n_, n_);
      mass.setIdentity();
      dfdx_ = scene_.params().mass * mass - dfdv_ - newton_;
    }
    const double m = scene_.params().mass;
    sunindextype k = 0;
    for (int c = 0; c < 2 * n_; ++c) {
      const bool velocity = c >= n_;
      const int block_column = velocity ? c - n_ : c;
      starts[c] = k;
      rows[k] = block_column;
      values[k++] = velocity ? 1.0 : 0.0;
      for (cloth::SparseMatrix::InnerIterator it(velocity ? dfdv_ : dfdx_, block_column); it; ++it) {
        rows[k] = n_ + it.row();
        values[k++] = it.value() / m;
      }
    }
    starts[2 * n_] = k;
  }
  [[nodiscard]] Vector positions(const std::vector<double>& y) const override {
    Vector all(3 * scene_.particle_count());
    scene_.all_positions(Eigen::Map<const Vector>(y.data(), n_), all);
    return all;
  }

 private:
  const cloth::Scene& scene_;
  cloth::ForceField field_;
  int n_;
  cloth::SparseMatrix dfdx_, dfdv_, newton_;
  bool definite_;
};


// SUNDIALS is C: an exception must not pass through it, so an interrupt (Ctrl-C) is an unrecoverable failure of
// either callback, which ends the integration; the caller then stops at throw_if_interrupted().
inline int rhs_callback(realtype /*t*/, N_Vector y, N_Vector ydot, void* data) {
  if (const int stop = cloth::sundials_stop_requested()) return stop;
  static_cast<OdeSystem*>(data)->rhs(N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
  return 0;
}

inline int jacobian_callback(realtype /*t*/, N_Vector y, N_Vector /*fy*/, SUNMatrix J, void* data, N_Vector /*tmp1*/,
                      N_Vector /*tmp2*/, N_Vector /*tmp3*/) {
  if (const int stop = cloth::sundials_stop_requested()) return stop;
  static_cast<OdeSystem*>(data)->jacobian(N_VGetArrayPointer(y), SUNSparseMatrix_IndexPointers(J),
                                          SUNSparseMatrix_IndexValues(J), SUNSparseMatrix_Data(J));
  return 0;
}

inline void check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string("SUNDIALS ") + call + " failed with flag " + std::to_string(flag));
}

// A failed run's note, in the model page's terms: the status (with its failure kind), the step that could not be
// taken and the last good time, and the library's flag: "step_failed (newton_not_converged) at step 1 after
// t = 0 s, ARK_CONV_FAILURE".
inline std::string failure_note(const cloth::SundialsEnd& end, long steps_taken, double t) {
  std::string note = cloth::run_status_name(end.status);
  if (end.status == cloth::RunStatus::step_failed) note.append(" (").append(cloth::step_failure_name(end.failure)).append(")");
  return note + " at step " + std::to_string(steps_taken + 1) + " after t = " + cloth::format_number(t, 3) + " s, " + end.flag;
}

}  // namespace ch10
