#pragma once
// How a solve, an increment or a whole run ended: one vocabulary from the interface CG up to summary.json, the
// window's status bar and the exit code of `rollsim run` (docs/OUTPUTS.md lists them). Only `converged` is a result.
#include <string>

namespace rollsim {

enum class Status {
  converged,      // every increment in equilibrium to the solvers' tolerances
  not_converged,  // an iterative part stopped short (Reason says which); no result
  diverged,       // the iteration ran away (NaN, growing residuals); no result
  cancelled,      // stopped on request; the fields are those of the last iterate
  error,          // the model cannot be solved as given (invalid input, a singular system)
  no_bite,        // a rolling pass whose friction cannot draw the slab in (μ below tan α): nothing was solved
};

enum class Reason {
  none,
  iteration_limit,     // an iteration count reached its limit before the tolerance (CG, active set)
  breakdown,           // CG lost positive curvature or met a NaN: the operator is not positive definite as seen
  round_off,           // CG reached the round-off level of its data before the tolerance asked for
  active_set_cycling,  // the frictionless active set came back to a set it had already tried
};

struct RunStatus {
  Status status = Status::converged;
  Reason reason = Reason::none;
  std::string message;  // for the user: what stopped where (increment, solve, iteration, residual)

  bool ok() const { return status == Status::converged; }
};

/// "converged", "not_converged", "diverged", "cancelled", "error", "no_bite" — the words written to summary.json.
const char* to_string(Status s);
/// "", "iteration_limit", "breakdown", "round_off", "active_set_cycling".
const char* to_string(Reason r);

/// Exit code of `rollsim run` for a run that ended with `s`: 0 converged, 2 error (invalid input or model),
/// 3 not_converged, 4 diverged, 5 cancelled, 6 no_bite (1 is kept for an internal failure of the program itself).
int exit_code(Status s);

}  // namespace rollsim
