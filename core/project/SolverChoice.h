#pragma once
// `solver.mode: auto` (issue 14, item 5): the solver mode chosen from the predicted cost of each candidate, with the
// partition table's cost model (partition/PartitionReport.h: predicted_cost, estimate_factor), not a second one.
// Candidates: `direct`, `mixed`, and `feti` when a body is partitioned. `skyline` and `petsc` are never chosen
// (docs/BENCHMARKS.md, "solver.mode: auto", says where skyline was measured fastest and by how much).
#include "model/Model.h"
#include "project/RunConfig.h"
#include "solve/AutoChoice.h"

namespace rollsim {

/// The cost model of each candidate: c = factorizations · flops(L) + (cg_iterations · substitutions + 2) · 4 nnz(L),
/// summed over the factors a mode makes, with S the linear solves expected (load increments × 3 active-set
/// iterations with a unilateral pair, 1 otherwise).
/// - direct: the bodies' factors as one matrix; with contact multipliers UMFPACK's LU (4 × a Cholesky factor: twice
///   the flops, measured at half the rate) refactored S times.
/// - mixed: each body factored once, 25 · S interface CG iterations (one substitution each) with contact, none
///   without.
/// - feti: partitioned bodies by the table's model for the project's preconditioner (dirichlet 25 iterations, two
///   factors; lumped 45, one; none 60, one), times 2 — the table's AMD estimate flatters a partition about 2× against
///   CHOLMOD's METIS ordering (docs/BENCHMARKS-PARTITION.md) —, the others as under mixed.
AutoChoice choose_solver_mode(const RunConfig& config, const Model& model);

}  // namespace rollsim
