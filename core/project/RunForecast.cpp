#include "project/RunForecast.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "model/DofMap.h"
#include "partition/PartitionReport.h"

namespace rollsim {

namespace {
// Rates of one thread on the CI's kind of machine (2 cores, OpenBLAS), fitted on the samples' summary.json timings by
// tests/bench/run_forecast.py (docs/BENCHMARKS.md, "The run forecast"; refitted 2026-11-30 after the element kernels
// got 2–3 times faster):
// one element's tangent and internal force [s], per dimension (2, 3) and kinematics (small, finite)
constexpr double kElementSeconds[2][2] = {{0.8e-6, 1.5e-6}, {1.4e-5, 1.5e-5}};
// a Cholesky factorization: the estimate's flops (an AMD ordering's, 2.6 × CHOLMOD's METIS-ordered count on the 16³
// cube) at this rate, and a cost per entry of L that the small supernodes of 2D factors spend beside it
constexpr double kFactorFlopRate = 5e10;      // [flop/s]
constexpr double kFactorEntrySeconds = 2e-8;  // [s]
// the LU of direct's bordered matrix (UMFPACK) against a Cholesky of the bodies (block-plastic-3d: 0.08 s a factor
// since freed memory is kept for reuse, base/Memory.h; 0.31 s before)
constexpr double kLuFactors = 1;
// Newton iterations per increment, cut-backs included, as the samples took them (4.4–12.7 with a contact pair, 4.8
// and 13.5 without): with a contact pair and without
constexpr double kIterationsWithContact = 8;
constexpr double kIterationsWithoutContact = 6;
// an ALE run's: the window's flow repeats from step to step, so each starts near its answer (measured 2026-11-30: 2.1
// an increment on samples/rolling-3d-ale.json, 3.0 on its 42-column window, 3.8 on rolling-2d-ale.json's 2.5 mm steps)
constexpr double kIterationsAle = 3;
// solves per increment of a linear analysis with a unilateral pair (the active set's), as auto's cost model takes it
constexpr double kActiveSetSolves = 3;
// selective update: the share of iterations an elastic body is refactored in (rolling-2d-36x6: 278 of 1022)
constexpr double kElasticRefactorShare = 0.3;
// what an increment costs beside its iterations (contact search, results, the files written), per dof [s], and the
// process's start
constexpr double kIncrementDofSeconds[2] = {3e-6, 5e-6};
constexpr double kStartSeconds = 0.05;

bool unilateral_contact(const Model& model) {
  return std::any_of(model.contacts.begin(), model.contacts.end(),
                     [](const ContactPair& p) { return p.kind != ContactKind::Tied; });
}

double iterations_per_increment(const RunConfig& config, const Model& model, bool ale) {
  if (config.analysis == "linear") return unilateral_contact(model) ? kActiveSetSolves : 1;
  if (ale) return kIterationsAle;
  return model.contacts.empty() ? kIterationsWithoutContact : kIterationsWithContact;
}

bool selective(const RunConfig& config) {
  return config.update.kind == UpdateSetting::Kind::Selective && config.solver_mode != "direct";
}

/// Whether a Newton run assembles and factors `body` once: its tangent is constant (elastic, small strain: a fixed
/// roll) and kept under the selective update, its internal force the kept matrix times its displacement.
bool assembled_once(const RunConfig& config, const Body& body, bool linear) {
  return !linear && selective(config) && !body.material.plastic() && body.kinematics == Kinematics::Small &&
         config.newton.constant_tangents == ConstantTangents::Keep;
}

/// The share of iterations in which `body` is factored again.
double refactor_share(const RunConfig& config, const Body& body, bool linear) {
  if (linear) return 1;
  return selective(config) && !body.material.plastic() ? kElasticRefactorShare : 1;
}
}  // namespace

RunForecast forecast_run(const RunConfig& config, const Model& model) {
  RunForecast f;
  bool ale = false;
  if (config.process) {
    const auto run = config.process->start(config.process_section, model);
    f.facts = run->facts();
    f.refusal = run->refusal();
    f.increments = static_cast<int>(std::ceil(config.steps.increments * run->expected_share() - 1e-9));
    ale = run->mesh_motion() != nullptr;
  } else {
    f.increments = config.steps.increments;
  }
  const bool linear = config.analysis == "linear";
  f.linear = linear;
  const double lu = config.solver_mode == "direct" && !model.contacts.empty() ? kLuFactors : 1;
  f.iterations = f.increments * iterations_per_increment(config, model, ale);
  double seconds = 0;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    const DofMap dofs(body, static_cast<int>(b), model.displacements);
    const FactorEstimate factor = estimate_factor(body.mesh, dofs);
    f.dofs += dofs.num_free();
    f.elements += body.mesh.num_elements();
    f.factor_flops += factor.flops;
    const int d = model.dim == 3 ? 1 : 0, k = body.kinematics == Kinematics::Finite ? 1 : 0;
    const double once = assembled_once(config, body, linear) ? 1 / std::max(f.iterations, 1.0) : 0;
    seconds += (once ? once : 1) * body.mesh.num_elements() * kElementSeconds[d][k];
    seconds += (once ? once : refactor_share(config, body, linear)) *
               (lu * factor.flops / kFactorFlopRate + factor.nnz * kFactorEntrySeconds);
  }
  f.seconds_per_iteration = seconds;
  const double increment = static_cast<double>(f.dofs) * kIncrementDofSeconds[model.dim == 3 ? 1 : 0];
  f.seconds = f.refusal.ok() ? kStartSeconds + f.iterations * seconds + f.increments * increment : 0;
  return f;
}

namespace {
std::string flops(double n) {
  char s[32];
  if (n < 1e9)
    std::snprintf(s, sizeof s, "%.2g Mflop", n / 1e6);
  else
    std::snprintf(s, sizeof s, "%.2g Gflop", n / 1e9);
  return s;
}
}  // namespace

std::string forecast_line(const RunForecast& f) {
  if (!f.refusal.ok()) return "nothing will be solved: " + f.refusal.message;
  char s[200];
  const double t = f.seconds;
  char time[40];
  if (t < 120)
    std::snprintf(time, sizeof time, "about %.2g s", t);
  else
    std::snprintf(time, sizeof time, "about %.2g min", t / 60);
  std::snprintf(s, sizeof s, "%ld dofs, factors of %s, %d increment%s, about %.0f %s: %s", f.dofs,
                flops(f.factor_flops).c_str(), f.increments, f.increments == 1 ? "" : "s", f.iterations,
                f.linear ? (f.iterations == 1 ? "solve" : "solves") : "Newton iterations", time);
  return s;
}

}  // namespace rollsim
