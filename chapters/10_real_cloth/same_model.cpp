// Chapter 10's check that the peers integrate the book's model: the plain loop over the springs (plain_fabric.hpp)
// and the book's force routine give the same accelerations and the same Jacobian at a perturbed, moving state.
#include "same_model.hpp"
#include "study.hpp"

#include "program/fragment.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

using namespace cloth;

namespace ch10 {

// The plain loop and the book's forces must be the same model: compare the right-hand sides and the
// Jacobians at a perturbed, moving state (pinned rows excepted, which the core does not have).
void check_same_model(const Scene& scene, PlainSystem& plain, CoreSystem& core, const std::string& dir) {
  std::vector<double> yp = plain.initial_state(), yc = core.initial_state();
  const int P = scene.particle_count(), n = scene.dof_count();
  for (int particle = 0; particle < P; ++particle) {
    const int s = scene.slot(particle);
    for (int k = 0; k < 3; ++k) {
      const double dx = 1e-3 * std::sin(1.3 * (3 * particle + k)), dv = 0.1 * std::cos(0.7 * (3 * particle + k));
      if (s < scene.free_count()) {
        yp[3 * particle + k] += dx, yc[3 * s + k] += dx;
        yp[3 * (P + particle) + k] += dv, yc[n + 3 * s + k] += dv;
      }
    }
  }
  std::vector<double> fp(yp.size()), fc(yc.size());
  plain.rhs(yp.data(), fp.data());
  core.rhs(yc.data(), fc.data());
  double rhs_difference = 0, scale = 0;
  for (int particle = 0; particle < P; ++particle) {
    const int s = scene.slot(particle);
    if (s >= scene.free_count()) continue;
    for (int k = 0; k < 3; ++k) {
      rhs_difference = std::max(rhs_difference, std::abs(fp[3 * (P + particle) + k] - fc[n + 3 * s + k]));
      scale = std::max(scale, std::abs(fc[n + 3 * s + k]));
    }
  }
  // Jacobians as dense matrices over the free coordinates (1200 x 1200 doubles each half: 46 MB in all).
  const auto dense = [](OdeSystem& sys, const std::vector<double>& y) {
    std::vector<sunindextype> starts(static_cast<std::size_t>(sys.size()) + 1);
    std::vector<sunindextype> rows(static_cast<std::size_t>(sys.nonzeros()));
    std::vector<double> values(rows.size());
    sys.jacobian(y.data(), starts.data(), rows.data(), values.data());
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(sys.size(), sys.size());
    for (int c = 0; c < sys.size(); ++c)
      for (sunindextype k = starts[c]; k < starts[c + 1]; ++k) J(rows[k], c) += values[k];
    return J;
  };
  const Eigen::MatrixXd Jp = dense(plain, yp), Jc = dense(core, yc);
  double jacobian_difference = 0, jacobian_scale = 0;
  for (int a = 0; a < P; ++a)
    for (int b = 0; b < P; ++b) {
      const int sa = scene.slot(a), sb = scene.slot(b);
      if (sa >= scene.free_count() || sb >= scene.free_count()) continue;
      for (int half = 0; half < 2; ++half)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) {
            const double vp = Jp(3 * (P + a) + i, half * 3 * P + 3 * b + j);
            const double vc = Jc(n + 3 * sa + i, half * n + 3 * sb + j);
            jacobian_difference = std::max(jacobian_difference, std::abs(vp - vc));
            jacobian_scale = std::max(jacobian_scale, std::abs(vc));
          }
    }
  const double rhs_relative = rhs_difference / scale, jacobian_relative = jacobian_difference / jacobian_scale;
  std::printf("plain loop against the book's forces: right-hand side %.1e, Jacobian %.1e (relative)\n",
              rhs_relative, jacobian_relative);
  if (!(rhs_relative < 1e-12 && jacobian_relative < 1e-12))
    throw std::logic_error("ch10_peers: the plain loop and the book's force routine disagree");
  write_text_fragment(dir + "/peers_check.md",
                      format("At a perturbed, moving state the plain loop's accelerations agree with the book's "
                             "to %.0e and its Jacobian to %.0e, relative to their largest entries.",
                             std::max(rhs_relative, 1e-16), std::max(jacobian_relative, 1e-16)));
}

}  // namespace ch10
