#include "project/SolverChoice.h"

#include <algorithm>
#include <cstdio>

#include "base/Stopwatch.h"
#include "model/DofMap.h"
#include "partition/PartitionReport.h"

namespace rollsim {

namespace {
constexpr double kActiveSetSolves = 3;       // linear solves assumed per increment with a unilateral pair
constexpr double kInterfaceIterations = 25;  // interface CG iterations per solve with contact (CostModel's default)
// UMFPACK's LU of the bordered matrix against CHOLMOD's Cholesky of the bodies: L and U are twice the flops, and
// UMFPACK factored 3.4–5.8 × slower than CHOLMOD on the block-indent samples (docs/BENCHMARKS-CONTACT.md)
constexpr double kLuFactors = 4;
// The table's AMD estimate flatters a partition against CHOLMOD's METIS ordering of the whole body by about 2×
// (docs/BENCHMARKS-PARTITION.md): feti is weighed at twice its predicted cost
constexpr double kPartitionFlattery = 2;

/// The feti model of the partition table for a preconditioner (PartitionReport.h's CostModel and its notes), with
/// `solves` linear solves; none: 60 iterations, 2.3 × Dirichlet's (the 20 × 20 cantilever of BENCHMARKS-FETI.md).
CostModel feti_model(Preconditioner preconditioner, double solves) {
  CostModel m;  // dirichlet
  if (preconditioner == Preconditioner::Lumped) m = {45, 1, 1};
  if (preconditioner == Preconditioner::None) m = {60, 1, 1};
  m.cg_iterations *= solves;
  return m;
}

/// Per body: its undivided factor and, when partitioned, the partition table's report of its partition.
struct BodyEstimate {
  FactorEstimate whole;
  double feti_cost = 0;  // Σ c_i of its subdomains (0: not partitioned)
};

BodyEstimate estimate_body(const Model& model, size_t b, const CostModel& feti) {
  const Body& body = model.bodies[b];
  const DofMap dofs(body, static_cast<int>(b), model.displacements);
  BodyEstimate e;
  if (body.partition.num_subdomains <= 1) {
    e.whole = estimate_factor(body.mesh, dofs);
    return e;
  }
  ReporterOptions options;
  options.cost = feti;
  PartitionReporter reporter(body, dofs, options);
  const PartitionReport& r = reporter.update(body.partition);
  e.whole = r.one_domain;
  e.feti_cost = r.cost;
  return e;
}

std::string describe(const AutoChoice& c) {
  std::string s = c.mode + " (predicted cost:";
  for (const ModeCost& m : c.costs) {
    char buf[80];
    std::snprintf(buf, sizeof buf, " %s %.3g", m.mode.c_str(), m.flops);
    s += buf + std::string(&m == &c.costs.back() ? " flops)" : ",");
  }
  return s;
}
}  // namespace

AutoChoice choose_solver_mode(const RunConfig& config, const Model& model) {
  const Stopwatch clock;
  const bool contact = !model.contacts.empty();
  const bool unilateral = std::any_of(model.contacts.begin(), model.contacts.end(),
                                      [](const ContactPair& p) { return p.kind != ContactKind::Tied; });
  const double solves = unilateral && config.analysis == "linear" ? kActiveSetSolves * config.steps.increments : 1;
  const CostModel direct{0, contact ? kLuFactors * solves : 1, 0};
  const CostModel mixed{contact ? kInterfaceIterations * solves : 0, 1, 1};
  const CostModel feti = feti_model(config.solver.preconditioner, solves);

  double direct_cost = 0, mixed_cost = 0, feti_cost = 0;
  bool partitioned = false;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const BodyEstimate e = estimate_body(model, b, feti);
    direct_cost += predicted_cost(e.whole, direct);
    mixed_cost += predicted_cost(e.whole, mixed);
    partitioned = partitioned || e.feti_cost > 0;
    feti_cost += e.feti_cost > 0 ? kPartitionFlattery * e.feti_cost : predicted_cost(e.whole, mixed);
  }
  AutoChoice choice;
  choice.costs = {{"direct", direct_cost}, {"mixed", mixed_cost}};
  if (partitioned) choice.costs.push_back({"feti", feti_cost});
  const auto best = std::min_element(choice.costs.begin(), choice.costs.end(),
                                     [](const ModeCost& a, const ModeCost& b) { return a.flops < b.flops; });
  choice.mode = best->mode;
  choice.reason = describe(choice);
  choice.seconds = clock.seconds();
  return choice;
}

}  // namespace rollsim
