// One run of each kind of program Chapter 10's map compares, on one scene, recording the cloth at every frame it
// lands on and timed by the book's timing rule: the book's methods by their one name (integrators/configuration.hpp),
// and the peers a reader would write: Boost.Odeint's RK4 and Dormand-Prince, SUNDIALS' CVODE BDF and ARKODE's
// backward Euler with KLU on the definite Jacobian, and a plain XPBD program.
#pragma once

#include "integrators/simulate.hpp"
#include "model/scene.hpp"

#include <string>
#include <vector>

namespace ch10 {

/// A run of the map: the frames it recorded (every particle, grid order, at whole multiples of its frame
/// interval), or where it stopped.
struct MapRun {
  bool ok = true;
  std::string note;  ///< why it stopped, with the step and the time
  long long steps = 0;
  double seconds = 0;  ///< thread processor seconds of the run (the fastest of up to three when short)
  std::vector<cloth::Frame> frames;
};

/// What a peer program is driven with: a reader's plain loop over the springs, or the book's force routine.
enum class Forces { plain, book };

/// The book's method `name` (a composed configuration name, "implicit_euler/one/cg") at step h to T, the Newton
/// matrix by the book's default rule. h is a whole fraction or multiple of the frame interval 1/60 s.
MapRun book_run(const cloth::Scene& scene, const std::string& name, double h, double T);
/// The book's Dormand-Prince pair (dopri5, Chapter 8) under the max-norm tolerance rtol = atol = tol, each frame
/// interval integrated to its end (analysis/reference_trajectory.hpp, the reference's own routine at a looser
/// tolerance).
MapRun book_dopri5_run(const cloth::Scene& scene, double tol, double T);
/// Boost.Odeint's runge_kutta4 at the fixed step h.
MapRun odeint_rk4_run(const cloth::Scene& scene, Forces forces, double h, double T);
/// Boost.Odeint's controlled Dormand-Prince 5(4), rtol = atol = tol, frames from its dense output (integrate_times).
MapRun odeint_dopri5_run(const cloth::Scene& scene, Forces forces, double tol, double T);
/// CVODE's BDF (orders up to max_order) with KLU on the definite Jacobian, rtol = atol = tol, stopped at each
/// frame (CVodeSetStopTime) so that every frame is its own solution, not its interpolant.
MapRun cvode_run(const cloth::Scene& scene, Forces forces, double tol, int max_order, double T);
/// A SUNDIALS run (CVODE or ARKODE) started after this call is stopped once it has used `seconds` of thread CPU
/// time, and reported so: an adaptive run's time cannot be predicted from the rung before it (CVODE at
/// tolerance 0.1 on the stiff curtain takes minutes, at 0.01 seconds).
void set_sundials_run_cap(double seconds);
/// ARKODE's one-stage backward Euler at the fixed step h, Newton with KLU on the definite Jacobian (up to 20
/// iterations, the Jacobian evaluated every step), one step at a time to each frame.
MapRun arkode_run(const cloth::Scene& scene, Forces forces, double h, double T);
/// The plain XPBD program (plain_xpbd.hpp): `substeps` substeps of one sweep per 1/60 s frame.
MapRun plain_xpbd_run(const cloth::Scene& scene, int substeps, double T);

}  // namespace ch10
