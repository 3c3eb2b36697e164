// The analysis reports through AnalysisObserver: one increment, every linear solve numbered and ended with its CG
// iterations, every CG iteration tagged with its solve, factorizations per group equal to the strategy's counts,
// active-set iterations; a cancel stops at the next safe point (between CG iterations, before a solve) with status
// "cancelled" and the finite, consistent fields of the last iterate; an observer that never cancels changes nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "../../common/TributaryMeasure.h"
#include "analysis/LinearStatic.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_observer {

using namespace rollsim;
using testing_support::tributary_measure;

namespace {

Model sample(const std::string& name, const std::string& preconditioner = "") {
  Project p = load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / name);
  if (!preconditioner.empty()) p.data["solver"]["preconditioner"] = preconditioner;
  return build_model(p);
}

/// Records every call; cancels when `cancel_when` says so.
class Recorder : public AnalysisObserver {
 public:
  struct Cg {
    int solve, iteration;
    double residual;
  };
  std::vector<std::string> events;  // "increment_begin", "solve_end", ... in call order
  std::vector<Cg> cg;
  std::vector<std::pair<int, int>> solves;  // (solve, cg iterations)
  std::map<std::string, long> factorizations;
  std::vector<std::pair<int, int>> active_set;
  std::vector<double> progress;
  std::function<bool(const Recorder&)> cancel_when;

  void on_increment_begin(int i, int n) override { events.push_back("increment_begin " + pair(i, n)); }
  void on_increment_end(int i, int n) override { events.push_back("increment_end " + pair(i, n)); }
  void on_newton_iteration(int, int, double) override { events.push_back("newton"); }
  void on_cg_iteration(int solve, int iteration, double residual) override {
    cg.push_back({solve, iteration, residual});
  }
  void on_solve_end(int solve, int iterations) override {
    events.push_back("solve_end");
    solves.emplace_back(solve, iterations);
  }
  void on_factorization(const std::string& group) override { ++factorizations[group]; }
  void on_active_set_iteration(int it, int changed) override { active_set.emplace_back(it, changed); }
  void on_progress(double f) override { progress.push_back(f); }
  bool cancel_requested() const override { return cancel_when && cancel_when(*this); }

 private:
  static std::string pair(int i, int n) { return std::to_string(i) + "/" + std::to_string(n); }
};

void expect_finite(const Results& r) {
  for (const BodyResults& b : r.bodies) {
    EXPECT_TRUE(b.displacement.allFinite());
    EXPECT_TRUE(b.nodal_force.allFinite());
    EXPECT_TRUE(b.contact_pressure.allFinite());
    for (const auto& s : b.nodal_stress)
      for (const double v : s) EXPECT_TRUE(std::isfinite(v));
  }
  for (const ContactResult& c : r.contacts) EXPECT_TRUE(std::isfinite(c.normal_force));
}

/// The CG iterations reported per solve, from the per-iteration calls.
std::map<int, int> iterations_per_solve(const Recorder& rec) {
  std::map<int, int> n;
  for (const auto& [solve, iterations] : rec.solves) n[solve] = 0;
  for (const Recorder::Cg& c : rec.cg) {
    EXPECT_EQ(c.iteration, n[c.solve] + 1) << "iterations of solve " << c.solve << " are 1, 2, ...";
    n[c.solve] = c.iteration;
  }
  return n;
}

}  // namespace

TEST(AnalysisObserver, MixedReportsSolvesIterationsFactorizationsAndTheIncrement) {
  const Model model = sample("cylinder-indent-2d.json");  // frictionless: several active-set solves
  auto solver = make_solver("mixed", {1e-8, 1});
  Recorder rec;
  const Results res = run_linear_static(model, *solver, &rec);
  const SolveStats& st = solver->stats();
  ASSERT_EQ(to_string(res.status.status), std::string("converged"));
  ASSERT_GT(res.active_set_iterations, 1);
  EXPECT_EQ(rec.events.front(), "increment_begin 1/1");
  EXPECT_EQ(rec.events.back(), "increment_end 1/1");
  EXPECT_EQ(rec.progress, std::vector<double>{1.0});
  // solves numbered 1..n, one per active-set iteration, each ended with its CG iterations
  ASSERT_EQ(static_cast<int>(rec.solves.size()), res.active_set_iterations);
  EXPECT_EQ(st.solves, res.active_set_iterations);
  const std::map<int, int> per_solve = iterations_per_solve(rec);
  long total = 0;
  for (size_t s = 0; s < rec.solves.size(); ++s) {
    EXPECT_EQ(rec.solves[s].first, static_cast<int>(s) + 1);
    EXPECT_EQ(per_solve.at(rec.solves[s].first), rec.solves[s].second);
    total += rec.solves[s].second;
  }
  EXPECT_EQ(total, st.cg_iterations);
  EXPECT_GT(total, 0);  // (the first solve may need none: one active point, its λ fixed by Gᵀλ = e)
  for (const Recorder::Cg& c : rec.cg) EXPECT_TRUE(c.residual >= 0 && std::isfinite(c.residual));
  // factorizations as counted by the strategy (each body once: its stiffness never changes)
  EXPECT_EQ(rec.factorizations, st.factorizations);
  EXPECT_EQ(rec.factorizations.size(), 2u);
  // one active-set report per solve, the last one settled
  ASSERT_EQ(static_cast<int>(rec.active_set.size()), res.active_set_iterations);
  EXPECT_EQ(rec.active_set.back().second, 0);
}

TEST(AnalysisObserver, DirectReportsARefactorizationPerSolveAndNoCgIterations) {
  const Model model = sample("cylinder-indent-2d.json");
  auto solver = make_solver("direct", {});
  Recorder rec;
  const Results res = run_linear_static(model, *solver, &rec);
  ASSERT_EQ(to_string(res.status.status), std::string("converged"));
  EXPECT_TRUE(rec.cg.empty());
  ASSERT_EQ(static_cast<int>(rec.solves.size()), res.active_set_iterations);
  for (const auto& [solve, iterations] : rec.solves) EXPECT_EQ(iterations, 0);
  EXPECT_EQ(rec.factorizations, solver->stats().factorizations);
  EXPECT_EQ(rec.factorizations.at("block"), res.active_set_iterations);
}

TEST(AnalysisObserver, FetiReportsEverySubdomainFactorization) {
  const Model model = sample("block-indent-dd-2d-50x30.json");
  auto solver = make_solver("feti", {1e-6, 1, Preconditioner::Dirichlet});
  Recorder rec;
  const Results res = run_linear_static(model, *solver, &rec);
  ASSERT_EQ(to_string(res.status.status), std::string("converged"));
  EXPECT_EQ(rec.factorizations, solver->stats().factorizations);
  EXPECT_EQ(static_cast<long>(rec.factorizations.size()), res.subdomains);  // 15 subdomains of the base + the block
  ASSERT_EQ(rec.solves.size(), 1u);
  EXPECT_EQ(rec.solves[0].second, solver->stats().cg_iterations);
}

TEST(AnalysisObserver, AnObserverThatNeverCancelsChangesNothing) {
  const Model model = sample("block-indent-dd-2d-50x30.json");
  auto a = make_solver("feti", {1e-6, 1, Preconditioner::Dirichlet}),
       b = make_solver("feti", {1e-6, 1, Preconditioner::Dirichlet});
  Recorder rec;
  const Results quiet = run_linear_static(model, *a), observed = run_linear_static(model, *b, &rec);
  ASSERT_EQ(quiet.bodies.size(), observed.bodies.size());
  for (size_t i = 0; i < quiet.bodies.size(); ++i)
    EXPECT_EQ(quiet.bodies[i].displacement, observed.bodies[i].displacement);  // bit-identical
  EXPECT_EQ(a->stats().cg_iterations, b->stats().cg_iterations);
}

TEST(AnalysisObserver, CancelBetweenCgIterationsKeepsTheIterate) {
  // no preconditioner and a tight tolerance: hundreds of CG iterations; cancel at the first one
  const Model model = sample("block-indent-dd-2d-50x30.json", "none");
  auto solver = make_solver("feti", {1e-12, 1, Preconditioner::None});
  Recorder rec;
  rec.cancel_when = [](const Recorder& r) { return !r.cg.empty(); };
  const Results res = run_linear_static(model, *solver, &rec);
  EXPECT_EQ(to_string(res.status.status), std::string("cancelled"));
  EXPECT_EQ(rec.cg.size(), 1u) << "stops at the next iteration";
  ASSERT_EQ(rec.solves.size(), 1u);
  EXPECT_EQ(rec.solves[0].second, 1);
  EXPECT_EQ(std::count(rec.events.begin(), rec.events.end(), "increment_end 1/1"), 0);
  EXPECT_TRUE(rec.progress.empty());
  // the fields of that iterate: every body, finite, contact resultants from the same multipliers
  ASSERT_EQ(res.bodies.size(), model.bodies.size());
  expect_finite(res);
  ASSERT_EQ(res.contacts.size(), 1u);
  EXPECT_GT(res.contacts[0].active_nodes, 0);
  EXPECT_GT(res.bodies[1].displacement.cwiseAbs().maxCoeff(), 0);
}

TEST(AnalysisObserver, CancelBetweenActiveSetIterationsKeepsTheLastSolve) {
  const Model model = sample("cylinder-indent-2d.json");
  auto solver = make_solver("direct", {});
  Recorder rec;
  rec.cancel_when = [](const Recorder& r) { return !r.solves.empty(); };  // after the first solve
  const Results res = run_linear_static(model, *solver, &rec);
  EXPECT_EQ(to_string(res.status.status), std::string("cancelled"));
  EXPECT_EQ(res.active_set_iterations, 1);
  EXPECT_EQ(rec.solves.size(), 1u);
  ASSERT_EQ(res.bodies.size(), model.bodies.size());
  expect_finite(res);
  // the fields of solve 1, not of the converged active set (which solve 1 changed)
  ASSERT_EQ(rec.active_set.size(), 1u);
  EXPECT_GT(rec.active_set[0].second, 0);
  auto full = make_solver("direct", {});
  const Results converged = run_linear_static(model, *full);
  EXPECT_GT((res.bodies[0].displacement - converged.bodies[0].displacement).cwiseAbs().maxCoeff(), 0);
  // contact resultants and nodal pressure from the same multipliers
  const ContactPair& p = model.contacts[0];
  const Mesh& slave = model.bodies[static_cast<size_t>(p.slave_body)].mesh;
  double sum = 0;
  for (const auto& [node, measure] : tributary_measure(slave, slave.surfaces.at(p.slave_surface)))
    sum += res.bodies[static_cast<size_t>(p.slave_body)].contact_pressure[node] * measure;
  EXPECT_NEAR(sum, res.contacts[0].normal_force, 1e-10 * std::abs(res.contacts[0].normal_force));
}

TEST(AnalysisObserver, CancelBeforeTheFirstSolveLeavesNoFields) {
  const Model model = sample("plate-hole-2d.json");
  auto solver = make_solver("direct", {});
  Recorder rec;
  rec.cancel_when = [](const Recorder&) { return true; };
  const Results res = run_linear_static(model, *solver, &rec);
  EXPECT_EQ(to_string(res.status.status), std::string("cancelled"));
  EXPECT_TRUE(res.bodies.empty());
  EXPECT_TRUE(rec.solves.empty());
  EXPECT_EQ(rec.events, std::vector<std::string>{"increment_begin 1/1"});
}

}  // namespace test_observer
