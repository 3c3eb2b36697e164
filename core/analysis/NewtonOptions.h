#pragma once
// The Newton driver's options, typed, and the table that declares them to the project schema (the analysis
// section): every default the member's initializer, every field's range and documentation its bind(...) line.
#include <string>
#include <vector>

#include "base/BoundField.h"
#include "base/SchemaFields.h"
#include "base/Words.h"

namespace rollsim {

/// Which part of the contact's geometric stiffness (contact/ContactStiffness) the tangent takes: none; the terms
/// whose two dofs lie in one group (into its K_g: every strategy); or every term, those joining two groups too
/// (BlockSystem::coupling: strategies with one global matrix only).
enum class ContactTangent { None, Groups, Full };
/// Slipping Coulomb friction: solved with λ_n (C_eq) where the strategy can, or lagged one iteration.
enum class FrictionTangent { Consistent, Lagged };
/// A step's first iteration: the tangents of the last step's converged iterate, or assembled afresh there.
enum class FirstTangent { Converged, Fresh };
/// Under a policy reading residuals: a constant tangent (elastic, small strain) kept, or judged like any group.
enum class ConstantTangents { Keep, Refactor };
/// Where a step's first iteration starts: at the converged state with the prescribed increment carried by the tangent
/// (tangent), at the converged state plus the last converged step's displacement scaled to this step (extrapolate), or
/// on the quadratic through the last three converged states (quadratic).
enum class Predictor { Tangent, Extrapolate, Quadratic };
/// Where the large-sliding pairs' stuck points get the facet frame (normal, tangents) their rows are written in when a
/// step begins: where the step begins, or where the last converged step's motion, repeated, says it will end.
enum class ContactFrames { StepStart, Predicted };
/// The interface Krylov solve's relative tolerance per Newton iteration (mixed, feti, petsc): solver.cg_tolerance at
/// every iteration (fixed), or following the Newton residual (Eisenstat–Walker; analysis/ForcingSequence).
enum class Forcing { Fixed, EisenstatWalker };

/// The interface tolerance under Newton two orders below Newton's residual tolerance: the interface solve's relative
/// residual is the constraint error it leaves (gaps, sticking points' slips, glue) relative to the interface's data;
/// Newton's constraint, correction and projection checks measure the same error against one step (a rolling pass at
/// 1e-4 diverged after 0.12 mm of travel). solver.cg_tolerance left unset under `fixed` forcing; the tightest tolerance
/// (the floor) of `eisenstat_walker`.
inline constexpr double kInterfaceTolerancePerNewton = 1e-2;
/// The loosest interface tolerance of `eisenstat_walker` forcing when solver.cg_tolerance is unset: on the main job
/// 1e-2 took 24 % more Newton iterations than a fixed 1e-10, 1e-4 1.4 %, 1e-5 0.3 % (docs/BENCHMARKS-NONLINEAR.md).
inline constexpr double kLoosestForcing = 1e-5;

template <>
inline const std::vector<std::string>& words<ContactTangent>() {
  static const std::vector<std::string> w{"none", "groups", "full"};
  return w;
}
template <>
inline const std::vector<std::string>& words<FrictionTangent>() {
  static const std::vector<std::string> w{"consistent", "lagged"};
  return w;
}
template <>
inline const std::vector<std::string>& words<FirstTangent>() {
  static const std::vector<std::string> w{"converged", "fresh"};
  return w;
}
template <>
inline const std::vector<std::string>& words<Predictor>() {
  static const std::vector<std::string> w{"tangent", "extrapolate", "quadratic"};
  return w;
}
template <>
inline const std::vector<std::string>& words<Forcing>() {
  static const std::vector<std::string> w{"fixed", "eisenstat_walker"};
  return w;
}
template <>
inline const std::vector<std::string>& words<ContactFrames>() {
  static const std::vector<std::string> w{"step_start", "predicted"};
  return w;
}
template <>
inline const std::vector<std::string>& words<ConstantTangents>() {
  static const std::vector<std::string> w{"keep", "refactor"};
  return w;
}

struct NewtonOptions {
  int increments = 1;                    // equal load steps N (analysis.increments; a cut-back halves the current one)
  int max_iterations = 25;               // Newton iterations of one attempt
  double tolerance = 1e-8;               // ‖r_k‖ ≤ tolerance × max(‖r_1‖, ‖r_2‖) of the attempt
  double displacement_tolerance = 1e-2;  // and ‖du_k‖ ≤ this × ‖u − u_n‖ (the step's displacement)
  int max_cutbacks = 8;                  // failed attempts in the whole run before it is declared diverged
  int first_step_halvings = 0;           // the first step is the nominal one halved this often (then grows back)
  bool line_search = true;               // one secant step along du when the residual's work along it did not halve
  FrictionTangent friction_tangent = FrictionTangent::Consistent;
  FirstTangent first_tangent = FirstTangent::Converged;
  ContactTangent contact_tangent = ContactTangent::Groups;
  ContactFrames contact_frames = ContactFrames::StepStart;
  ConstantTangents constant_tangents = ConstantTangents::Keep;
  Predictor predictor = Predictor::Tangent;
  double duration = 0;  // the analysis's time [s]: a step of load-factor span Δλ lasts Δλ × duration (0: no time)
  Forcing forcing = Forcing::Fixed;
  // remeshing (analysis/Remeshing): the smallest corner Jacobian ratio an element of a finite-strain plastic body may
  // reach, against the mesh its segment started on, before the run moves that body's nodes back to their spread (0:
  // never), and how often it may
  double remesh_quality = 0;
  int max_remeshes = 100;
  // how the user makes the steps smaller, for a diverged run's advice (a process's own step: "a smaller
  // process.travel_increment (now 1 mm)"); empty: more analysis.increments
  std::string smaller_steps;
};

/// The analysis section's Newton fields, in the order shown to users (analysis.increments is the load steps' field,
/// read by both analyses: project/RunConfig).
inline const std::vector<BoundField<NewtonOptions>>& newton_option_fields() {
  using namespace schema;
  using N = NewtonOptions;
  static const std::vector<BoundField<N>> table = {
      bind(count("max_iterations", "Newton: iterations of one step before it is cut back", 200), &N::max_iterations),
      bind(below(positive("tolerance", "-",
                          "Newton: ‖r_k‖ / max(‖r_1‖, ‖r_2‖) of the out-of-balance force to converge a step (‖r_2‖: "
                          "the scale of a step driven by a prescribed body alone)"),
                 1.0),
           &N::tolerance),
      bind(bounded(count("max_cutbacks",
                         "Newton: how often the step may be halved below its nominal size (after failed attempts; it "
                         "grows back by doubling after a step that converges at once) before the run is diverged"),
                   0, 50),
           &N::max_cutbacks),
      bind(bounded(count("first_step_halvings",
                         "Newton: the first step is the nominal step halved this often, and grows back by doubling "
                         "after each step that converges at once — a start from a stress-free state that one whole "
                         "step would take to a distorted one (0: none, or an ALE rolling pass's 3, 6 in 3D)"),
                   0, 20),
           &N::first_step_halvings),
      bind(str("friction_tangent",
               "Newton with Coulomb friction: consistent — a slipping point's friction force μ λ_n is solved for with "
               "its normal multiplier (an unsymmetric system: UMFPACK under direct, projected GMRES on the interface "
               "under mixed and feti; skyline lags it whatever this says); lagged — it lags one iteration behind the "
               "normal force (a symmetric system)"),
           &N::friction_tangent),
      bind(str("first_tangent",
               "Newton: the tangent a step's first iteration factors — converged: the one assembled at the step "
               "before's converged iterate, with its plastic flow; fresh: assembled again at the converged state, "
               "where a zero strain increment returns elastically, so a flowing body starts each step with its "
               "elastic stiffness (docs/BENCHMARKS-ROLLING.md: what made `--update always` fail on the rolling pass)"),
           &N::first_tangent),
      bind(non_negative("duration", "s",
                        "the time the analysis takes: a step lasts its share of it (a cut-back halves it with the "
                        "step), so that a rate-dependent flow stress (materials[].flow_stress) sees the plastic "
                        "strain's rate; 0: quasi-static, no time (a rolling pass sets it from process.roll_speed)"),
           &N::duration),
      bind(str("predictor",
               "Newton: where a step's first iteration starts — tangent: the converged state, the prescribed motion's "
               "increment carried into the body by the tangent assembled there (elastic where a zero strain increment "
               "returns elastically; in an ALE run as extrapolate: its window's flow repeats); extrapolate: the "
               "converged state plus the last converged step's displacement "
               "scaled to this step, the prescribed dofs at their new values (a steadily flowing body starts near "
               "its answer); quadratic: on the quadratic through the last three converged states (a body whose flow "
               "changes smoothly: plastic upsetting 59 Newton iterations against extrapolate's 65; a rolling pass, "
               "whose contact changes in jumps, takes more — docs/BENCHMARKS-NONLINEAR.md \"Predictors\")"),
           &N::predictor),
      bind(str("forcing",
               "Newton under mixed, feti and petsc: the interface Krylov solve's relative tolerance at each iteration "
               "— fixed: solver.cg_tolerance at every iteration; eisenstat_walker: loose while the Newton residual "
               "falls slowly and tighter as it falls fast (Eisenstat & Walker's choice 2), solver.cg_tolerance (unset: "
               "1e-5) its loosest value and analysis.tolerance / 100 its tightest, the constraint rows still met to "
               "analysis.tolerance before a step is accepted (docs/BENCHMARKS-NONLINEAR.md \"Inexact Newton\")"),
           &N::forcing),
      bind(str("contact_tangent",
               "Newton with contact pairs that slide `large_every_iteration`: the contact's geometric stiffness (how "
               "the rows' normal and projection turn with the displacement: node-to-segment in 2D, node-to-face in "
               "3D). groups — the terms within one group (the master's own part; the slave's on a warped 3D face) "
               "into its stiffness block, every solver; full — also the terms joining slave and master, direct and "
               "skyline only; none — the rows' change is not linearised. full pays where points slide over a "
               "deformable master (a block pushed along a base: 60 Newton iterations against 94); a sticking point's "
               "term only shifts the multipliers, so on a sticking pass full repeats none "
               "(docs/BENCHMARKS-NONLINEAR.md). In 3D the turning of a slipping friction force's direction (its "
               "slip-direction term) joins slave and master under groups too where the solver can take it — direct "
               "and skyline in their global matrix, mixed as compliant interface rows (feti: the parts within one "
               "group); none leaves it out"),
           &N::contact_tangent),
      bind(str("contact_frames",
               "Newton with contact pairs that slide `large`: the frame (normal, tangents) a sticking point's rows are "
               "written in when a step begins — step_start: the master facet's where the step begins; predicted: "
               "where the last converged step's motion, repeated, puts it at the step's end. A sticking point holds "
               "its position along that frame, and the step is checked in the frame where it ends: a roll turning "
               "1/300 rad a step moves a point 0.1 mm off its master point 3e-4 mm off its projection, so under "
               "step_start nearly every step is searched again and converged again (a rolling pass: 17 % fewer Newton "
               "iterations with predicted, the same checks met; docs/BENCHMARKS.md \"The main job at half its CPU "
               "time\")"),
           &N::contact_frames),
      bind(str("constant_tangents",
               "Newton under the selective update: keep — a group whose tangent cannot change (elastic, small strain) "
               "is assembled and factored once; refactor — it is re-evaluated by its residual like any group (to "
               "measure what keeping saves)"),
           &N::constant_tangents),
      bind(bounded(
               non_negative(
                   "remesh_quality", "-",
                   "Newton, 2D: remesh before an element folds — after a converged step where an element "
                   "of a finite-strain plastic body has a corner Jacobian below this share of where its "
                   "segment began (ParaView's jacobian_ratio field), that body's nodes are moved back to "
                   "their original spread along its deformed boundary (same elements and node sets), "
                   "every point's state (plastic strain, elastic strain, temperature) carried onto them "
                   "by a lumped L2 projection, and the run goes on from there with what is left of the "
                   "prescribed motion (summary.json `remeshes`: when, why, the shape before and after, "
                   "the plastic strain's integral before and after). 0: never. Every body must be "
                   "finite-strain, the run driven by prescribed motion — a Lagrangian rolling pass is: its "
                   "slab is remeshed, its roll goes on from where it is (docs/VALIDATION.md "
                   "\"Remeshing\"); 1: after every step that compresses an element at all, a check of the transfer)"),
               0.0, 1.0),
           &N::remesh_quality),
      bind(count("max_remeshes", "Newton: how many remeshes a run may make (analysis.remesh_quality)", 1000),
           &N::max_remeshes),
      bind(boolean("line_search",
                   "Newton: one secant step along the correction when the residual's work along it did not halve"),
           &N::line_search),
  };
  return table;
}

}  // namespace rollsim
