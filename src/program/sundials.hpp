// What the benchmark programs that drive SUNDIALS (CVODE, ARKODE's ARKStep) share: the callbacks' way of honouring
// SIGINT and SIGTERM inside the library, ARKODE's fixed steps ending on T with a step's own value, and how an
// integration ended said in the model page's terms (ok, diverged, step_failed with its failure kind, interrupted)
// with the library's own return flag beside it. Header-only: the library does not link SUNDIALS; the programs
// that do (Chapters 9 and 10) include it.
#pragma once

#include "integrators/simulate.hpp"
#include "program/interrupt.hpp"

#include <arkode/arkode_arkstep.h>
#include <cvode/cvode.h>

#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>

namespace cloth {

/// What a right-hand-side or Jacobian callback returns so that a stop request ends the integration at once:
/// SUNDIALS is C, so no exception may pass through it, and an unrecoverable failure (< 0) makes CVode and
/// ARKStepEvolve return after the current attempt, with the last successful step's state. 0 otherwise.
inline int sundials_stop_requested() { return interrupt_flag().load(std::memory_order_relaxed) != 0 ? -1 : 0; }

/// ARKStep at its fixed step h from where it is (t) to T, one step at a time, the last one shortened to end on T
/// exactly when T is not a multiple of h, as the book's driver does: y is then the step's own solution at T.
/// (Asked for T in its normal mode, or given T as a stop time, ARKODE 6.4 returns its interpolant instead, which for
/// a first-order table has degree 0 and halves the last step's change.) Returns ARKStepEvolve's last flag.
/// A step that fails leaves y and t at the last good state (ARKODE 6.4 returns the time of the failed attempt).
inline int arkode_fixed_steps_to(void* arkode_mem, double T, double h, N_Vector y, realtype& t) {
  N_Vector last = N_VClone(y);
  if (last == nullptr) throw std::bad_alloc();
  int flag = ARK_SUCCESS;
  while (flag >= 0 && T - t > 1e-9 * h) {
    if (t + h > T) {
      flag = ARKStepSetFixedStep(arkode_mem, T - t);
      if (flag < 0) break;
    }
    N_VScale(1.0, y, last);
    const realtype t_last = t;
    flag = ARKStepEvolve(arkode_mem, T, y, &t, ARK_ONE_STEP);
    if (flag < 0) {
      N_VScale(1.0, last, y);
      t = t_last;
    }
  }
  N_VDestroy(last);
  return flag;
}

/// The model page's reading of a SUNDIALS return flag.
struct SundialsEnd {
  RunStatus status = RunStatus::ok;
  StepFailureKind failure = StepFailureKind::none;
  std::string flag;    ///< the library's name of its return flag ("CV_CONV_FAILURE"), for run.txt's extra line
  std::string reason;  ///< every status but ok: one line
};

/// Reads `flag`, returned by CVode (`cvode`) or by ARKStepEvolve, whose state is then `state_finite` or not.
/// A failure after a stop request is the interruption it caused; a non-finite state is divergence; Newton's
/// convergence failures are newton_not_converged, a failed setup or solve of the linear solver (KLU's
/// factorization) factorization_singular, and repeated error-test failures, a step at the round-off floor or the
/// step limit reached step_size_too_small. Other flags (a failed allocation, a bad input) are not a result of the
/// simulation: std::runtime_error.
inline SundialsEnd sundials_end(int flag, bool cvode, bool state_finite) {
  SundialsEnd end;
  char* name = cvode ? CVodeGetReturnFlagName(flag) : ARKStepGetReturnFlagName(flag);
  end.flag = name != nullptr ? name : std::to_string(flag);
  std::free(name);  // SUNDIALS allocates the name with malloc
  const std::string who = std::string(cvode ? "CVode" : "ARKStepEvolve") + " returned " + end.flag;
  if (interrupt_flag().load() != 0 && flag < 0) {
    end.status = RunStatus::interrupted;
    end.reason = "stopped by the signal inside the integrator (" + who + ")";
  } else if (!state_finite) {
    end.status = RunStatus::diverged;
    end.reason = "the state became non-finite (" + who + ")";
  } else if (flag >= 0) {
    end.status = RunStatus::ok;
  } else {
    end.status = RunStatus::step_failed;
    switch (flag) {
      case CV_CONV_FAILURE:  // = ARK_CONV_FAILURE: SUNDIALS numbers its shared failures alike
        end.failure = StepFailureKind::newton_not_converged;
        end.reason = "Newton's iteration failed to converge repeatedly or at the smallest step (" + who + ")";
        break;
      case CV_LSETUP_FAIL:
      case CV_LSOLVE_FAIL:
        end.failure = StepFailureKind::factorization_singular;
        end.reason = "the linear solver (KLU) could not factor or solve the Newton matrix (" + who + ")";
        break;
      case CV_ERR_FAILURE:
      case CV_TOO_MUCH_WORK:
      case CV_TOO_MUCH_ACC:
        end.failure = StepFailureKind::step_size_too_small;
        end.reason = "the error test failed repeatedly or the steps became too small to reach T (" + who + ")";
        break;
      default:
        throw std::runtime_error(who + ", which is not a result of the simulation");
    }
  }
  return end;
}

}  // namespace cloth
