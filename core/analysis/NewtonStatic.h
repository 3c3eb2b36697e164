#pragma once
// Incremental Newton analysis (paper §1): loads and prescribed displacements applied in increments; in each, Newton
// iterations on the residual r = f_ext − f_int(u, state) − Cᵀλ of every group, each a linear solve of the block
// system with the chosen strategy (K_g: the consistent tangent; C du = d − C u for the constraints), the frictionless
// active set updated from every iterate (no inner contact loop). The update policy decides which groups get a new
// tangent and factor at each iteration (always: Mixed I / DD-I; selective: Mixed II / DD-II). A step that does not
// converge (iteration limit, a residual that grows or is not finite, an inverted element, a failed linear solve) is
// cut back and retried from the last converged state; when the cut-backs run out the run ends `diverged`, naming
// the increment and the cause. Integration-point states are committed only when a step converges.
// Under `petsc` (mpirun -n P) every rank runs this driver alike — every group's residual, state and convergence test,
// redundantly, so that every rank takes the same decisions and rank 0 holds every body's fields — but assembles the
// tangent of its own subdomain only (SolverStrategy::local_groups); the linear solve is PETSc's, distributed.
#include <string>

#include "analysis/AnalysisError.h"
#include "analysis/Results.h"
#include "model/Model.h"
#include "solve/Observer.h"
#include "solve/SolverStrategy.h"
#include "solve/UpdatePolicy.h"

namespace rollsim {

/// Which part of the contact's geometric stiffness (contact/ContactStiffness) the tangent takes: none; the terms
/// whose two dofs lie in one group (into its K_g: every strategy); or every term, those joining two groups too
/// (BlockSystem::coupling: strategies with one global matrix only).
enum class ContactTangent { None, Groups, Full };

struct NewtonOptions {
  int increments = 10;                   // equal load steps N (a cut-back halves the current one)
  int max_iterations = 25;               // Newton iterations of one attempt
  double tolerance = 1e-8;               // ‖r_k‖ ≤ tolerance × max(‖r_1‖, ‖r_2‖) of the attempt
  double displacement_tolerance = 1e-2;  // and ‖du_k‖ ≤ this × ‖u − u_n‖ (the step's displacement)
  int max_cutbacks = 8;                  // failed attempts in the whole run before it is declared diverged
  bool line_search = true;               // one secant step along du when the residual's work along it did not halve
  bool consistent_friction = true;       // slipping Coulomb friction solved with λ_n (C_eq) where the strategy can
  ContactTangent contact_tangent = ContactTangent::Groups;
  // a step's first iteration factors the tangents of the last step's converged iterate (not re-assembled there)
  bool first_tangent_converged = true;
  bool keep_constant_tangents = true;  // a policy reading residuals (selective) never re-assembles a group whose
                                       // tangent is constant (elastic, small strain); false: like any group
};

/// Runs the Newton analysis; Results::status is converged, cancelled (between iterations: the last converged step
/// stays the result), not_converged (a linear solve short of its tolerance when no cut-back is left) or diverged.
Results run_newton_static(const Model& model, SolverStrategy& solver, const UpdatePolicy& policy,
                          AnalysisObserver* observer = nullptr, const NewtonOptions& options = {});

}  // namespace rollsim
