#pragma once
// The forcing terms of an inexact Newton method (analysis.forcing): the relative tolerance of each iteration's
// interface Krylov solve. `fixed`: solver.cg_tolerance throughout. `eisenstat_walker`: Eisenstat & Walker's choice 2
// (SIAM J. Sci. Comput. 17, 1996), η_k = γ (‖r_k‖ / ‖r_{k−1}‖)^α with γ = 0.9, α = 2, safeguarded by
// γ η_{k−1}^α where that is above 0.1, and kept within [floor, loosest]: loose while Newton is far from the answer
// (no solve spends digits a wrong tangent throws away), tighter as the residual falls fast.
#include "analysis/NewtonOptions.h"
#include "solve/BlockSystem.h"

namespace rollsim {

class ForcingSequence {
 public:
  /// `loosest`: solver.cg_tolerance (fixed: every η); `floor`: the tightest η (above `loosest`: `loosest`).
  ForcingSequence(Forcing kind, double loosest, double floor);
  /// A step (or attempt) begins: its first solve takes the loosest η.
  void restart();
  /// The next solve's tolerance from the Newton residual ‖r_k‖ of the iterate it corrects: η_k, the floor where that
  /// iterate is `balanced` (it solves again only to meet a check: the constraint rows, the contact statuses); under
  /// eisenstat_walker with the constraint error `enough` as an absolute tolerance (solving below it spends
  /// iterations the Newton checks do not ask for). fixed: {loosest, 0}, and for a balanced iterate at most `enough`
  /// (the relative tolerance of the total multipliers' residual may leave the constraint rows unmet by more than
  /// Newton's check accepts).
  InterfaceTolerance next(double residual, bool balanced, double enough);
  double floor() const { return floor_; }

 private:
  Forcing kind_;
  double loosest_, floor_;
  double last_residual_ = 0, last_eta_ = 0;  // 0: no solve yet in this step
};

}  // namespace rollsim
