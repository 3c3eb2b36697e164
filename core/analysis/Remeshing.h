#pragma once
// A Newton run that moves a distorted body's nodes instead of letting its elements fold (analysis.remesh_quality):
// the run stops after a converged step where an element of a finite-strain plastic body has a corner Jacobian below
// that share of its start (NewtonOptions::remesh_quality), and goes on as a new run (a segment) whose model starts
// where the last one stopped —
// - every body's reference is its current configuration, its integration-point state carried there
//   (fem/StateTransfer: current_state, J2's C_p⁻¹ becoming b_e), the displacement zero;
// - the distorted body's nodes moved back to its original spread (mesh/EvenNodes: same elements and node sets), its
//   state and temperatures transferred onto them (lumped L2 projection and interpolation);
// - the prescribed motion what is left of it (values and rotation angles × (1 − λ), a rotation's centre moved on),
//   the time what is left of analysis.duration, the steps as long as before.
// Equilibrium is restored by the next segment's first step (its first residual: what the transfer left unbalanced).
// The segments' results are one run's: increments on the run's load factor, each with the model it was computed on,
// and every remesh reported (RemeshRecord). The run may be driven by prescribed motion only: a load would have to be
// carried at its level λ f across the segments (refused by the project's checks). A process's measures (a rolling
// pass's, live while it runs) see each segment's increments as the run's: on the run's load factor, with the model
// their fields are on.
#include <functional>

#include "analysis/IncrementMeasure.h"
#include "analysis/NewtonOptions.h"
#include "analysis/Results.h"
#include "base/Observer.h"
#include "model/Model.h"

namespace rollsim {

/// One segment's run: the Newton analysis of `model` with `options`, reporting to `observer`, its increments measured
/// by `measure` (may be null).
using SegmentRun = std::function<Results(const Model& model, const NewtonOptions& options, AnalysisObserver* observer,
                                         const IncrementMeasure* measure)>;

/// The Newton run of `model` with remeshing (options.remesh_quality > 0), each segment run by `run`; `measure` (a
/// process's, may be null) measures every increment of the run.
Results run_with_remeshing(const Model& model, const NewtonOptions& options, const SegmentRun& run,
                           AnalysisObserver* observer, const IncrementMeasure* measure = nullptr);

/// The model a segment goes on with after `done` (a segment of `model` that stopped for a remesh, its last increment
/// at the segment's load factor `lf`): see the header. `original`: the run's first model (the spread to move back
/// to). Fills `record` with what the remesh changed; a body whose nodes would fold an element when moved keeps them
/// where they are (record.nodes_kept says why: the run goes on from its current shape). Throws AnalysisError when a
/// body would go on from a shape with a folded element (a reference must not be folded: restarted from one, a punch's
/// force fell by 40 % in a step).
Model remeshed_model(const Model& model, const Model& original, const Results& done, double lf, RemeshRecord& record);

}  // namespace rollsim
