// The peer programs of Chapter 10's comparison, written as a reader would from each library's documentation:
// Boost.Odeint's RK4 and controlled Dormand-Prince, CVODE's BDF and ARKODE's backward Euler with KLU, each driving
// an OdeSystem (peer_systems.hpp: a plain loop over the springs or the book's force routine) from rest to T.
#pragma once

#include "peer_systems.hpp"

#include <string>
#include <vector>

namespace ch10 {

/// How a peer's run ended, and the state it ended in.
struct Outcome {
  bool ok = true;
  std::string note;  ///< why a run failed, or what a tolerance-controlled run did
  long long steps = 0;
  std::vector<double> y;
};

/// Boost.Odeint's classical RK4 at the fixed step T / steps.
Outcome odeint_rk4(OdeSystem& system, double T, long long steps);
/// Boost.Odeint's Dormand-Prince 5(4) under its step-size controller, absolute and relative tolerance tol.
Outcome odeint_dopri5(OdeSystem& system, double T, double tol);

/// The SUNDIALS peers: CVODE's BDF; ARKODE's backward Euler with its own Newton iteration, or declared linearly
/// implicit (one Newton iteration: Baraff and Witkin's step).
enum class Sundials { cvode_bdf, arkode_newton, arkode_linear };
/// A SUNDIALS peer to T: CVODE at tolerances rtol = atol = tol, ARKODE at the fixed step T / steps.
Outcome sundials_run(OdeSystem& system, Sundials peer, double T, double tol, long long steps);

}  // namespace ch10
