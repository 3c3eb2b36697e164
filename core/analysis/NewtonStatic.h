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
#include "analysis/IncrementMeasure.h"
#include "analysis/MeshMotion.h"
#include "analysis/NewtonOptions.h"
#include "analysis/Results.h"
#include "base/Observer.h"
#include "model/Model.h"
#include "solve/SolverStrategy.h"
#include "solve/UpdatePolicy.h"

namespace rollsim {

/// Runs the Newton analysis; Results::status is converged, cancelled (between iterations: the last converged step
/// stays the result), not_converged (a linear solve short of its tolerance when no cut-back is left) or diverged.
/// `measure` (may be null): a process's measures of each completed increment, told to the observer as it goes.
/// `motion` (may be null): an ALE run — after every converged step its body's nodes are put back and its state
/// advected (analysis/AleStep); each increment's fields then belong to the model of that step
/// (IncrementResults::model).
Results run_newton_static(const Model& model, SolverStrategy& solver, const UpdatePolicy& policy,
                          AnalysisObserver* observer = nullptr, const NewtonOptions& options = {},
                          const IncrementMeasure* measure = nullptr, const MeshMotion* motion = nullptr);

}  // namespace rollsim
