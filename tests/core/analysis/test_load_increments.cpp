// Load increments (analysis.increments): without contact, or with bilateral (tied) contact, increment i of N is
// (i / N) × the one-increment solution to round-off; with frictionless contact (the Hertz sample) the contact force
// and the contact zone grow increment by increment and the last increment equals the one-increment run to the CG
// tolerance. The observer sees every increment begin and end with progress i / N, a cancel between increments keeps
// the completed ones, and the last increment's fields are the Results' own.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "analysis/LinearStatic.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_load_increments {

using namespace rollsim;

namespace {

json sample_json(const std::string& name) {
  std::ifstream in(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / name);
  return json::parse(in);
}

Results solve(const json& project, const std::string& mode, int increments, AnalysisObserver* obs = nullptr) {
  const Project p = parse_project(project.dump(), "increments");
  const Model model = build_model(p);
  auto solver = make_solver(mode, {1e-10, 1});
  return run_linear_static(model, *solver, obs, increments);
}

/// The Hertz sample with mesh size about 0.04 near the contact (as tests/core/contact/test_hertz.cpp).
json small_hertz() {
  json j = sample_json("cylinder-indent-2d.json");
  j["bodies"][0]["mesh"]["nx"] = 38;
  j["bodies"][0]["mesh"]["ny"] = 38;
  j["bodies"][1]["mesh"]["n_around"] = 39;
  j["bodies"][1]["mesh"]["n_radial"] = 22;
  j["boundary_conditions"][3]["fy"] = -2.16 / 23;
  return j;
}

double max_abs(const Results& r) {
  double m = 0;
  for (const BodyResults& b : r.bodies) m = std::max(m, b.displacement.cwiseAbs().maxCoeff());
  return m;
}

class Recorder : public AnalysisObserver {
 public:
  std::vector<std::string> events;
  std::vector<double> progress;
  int cancel_after_increment = 0;
  void on_increment_begin(int i, int n) override {
    events.push_back("begin " + std::to_string(i) + "/" + std::to_string(n));
  }
  void on_increment_end(int i, int n) override {
    events.push_back("end " + std::to_string(i) + "/" + std::to_string(n));
    cancel_ = cancel_ || i == cancel_after_increment;
  }
  void on_progress(double f) override { progress.push_back(f); }
  bool cancel_requested() const override { return cancel_; }

 private:
  bool cancel_ = false;
};

}  // namespace

TEST(LoadIncrements, LinearIncrementsAreProportionalToTheSingleSolution) {
  // plate with a hole: a pressure load; block indent: a prescribed displacement and tied (bilateral, linear) contact
  for (const std::string name : {"plate-hole-2d.json", "block-indent-2d-50x30.json"}) {
    SCOPED_TRACE(name);
    const json j = sample_json(name);
    const Results one = solve(j, "direct", 1), four = solve(j, "direct", 4);
    ASSERT_EQ(one.increments.size(), 1u);
    ASSERT_EQ(four.increments.size(), 4u);
    EXPECT_EQ(four.load_increments, 4);
    const double scale = max_abs(one);
    ASSERT_GT(scale, 0);
    for (size_t i = 0; i < 4; ++i) {
      const IncrementResults& inc = four.increments[i];
      const double lf = (i + 1) / 4.0;
      EXPECT_EQ(inc.load_factor, lf);
      ASSERT_EQ(inc.bodies.size(), one.bodies.size());
      for (size_t b = 0; b < one.bodies.size(); ++b) {
        const BodyResults &got = inc.bodies[b], &full = one.bodies[b];
        EXPECT_LT((got.displacement - lf * full.displacement).cwiseAbs().maxCoeff(), 1e-12 * scale) << i;
        const double f = std::max(full.nodal_force.cwiseAbs().maxCoeff(), 1e-300);
        EXPECT_LT((got.nodal_force - lf * full.nodal_force).cwiseAbs().maxCoeff(), 1e-9 * f) << i;
        for (size_t e = 0; e < full.element_stress.size(); e += 37)
          EXPECT_NEAR(got.element_stress[e][1], lf * full.element_stress[e][1],
                      1e-9 * (1 + std::abs(full.element_stress[e][1])));
      }
      for (size_t c = 0; c < one.contacts.size(); ++c)
        EXPECT_NEAR(inc.contacts[c].normal_force, lf * one.contacts[c].normal_force,
                    1e-9 * std::abs(one.contacts[c].normal_force));
    }
    // the Results' own fields are the last increment's
    for (size_t b = 0; b < four.bodies.size(); ++b)
      EXPECT_EQ(four.bodies[b].displacement, four.increments.back().bodies[b].displacement);
  }
}

TEST(LoadIncrements, OneIncrementIsThePlainLinearSolve) {
  const json j = sample_json("block-indent-2d-50x30.json");
  const Results plain = solve(j, "mixed", 1);
  const size_t n = plain.bodies.size();
  ASSERT_EQ(plain.increments.size(), 1u);
  EXPECT_EQ(plain.increments[0].load_factor, 1.0);
  for (size_t b = 0; b < n; ++b) {
    EXPECT_EQ(plain.increments[0].bodies[b].displacement, plain.bodies[b].displacement);
    EXPECT_EQ(plain.increments[0].bodies[b].nodal_force, plain.bodies[b].nodal_force);
  }
  EXPECT_EQ(plain.increments[0].active_set_iterations, plain.active_set_iterations);
}

TEST(LoadIncrements, ContactForceAndZoneGrowWithTheLoadAndTheLastIncrementIsTheFullSolve) {
  const json j = small_hertz();
  const Results one = solve(j, "mixed", 1);
  Recorder rec;
  const Results four = solve(j, "mixed", 4, &rec);
  ASSERT_EQ(to_string(four.status.status), std::string("converged"));
  ASSERT_EQ(four.increments.size(), 4u);
  const double P = one.contacts.at(0).normal_force;
  std::printf(
      "| increment | load factor | contact force | force / (factor × P) | active nodes | active-set solves "
      "| CG iterations |\n|---|---|---|---|---|---|---|\n");
  for (size_t i = 0; i < 4; ++i) {
    const IncrementResults& inc = four.increments[i];
    const ContactResult& c = inc.contacts.at(0);
    std::printf("| %zu | %.2f | %.6g | %.8f | %d | %d | %ld |\n", i + 1, inc.load_factor, c.normal_force,
                c.normal_force / (inc.load_factor * P), c.active_nodes, inc.active_set_iterations, inc.cg_iterations);
    // the cylinder floats: the contact carries the applied share of the load (Σ f·n, not Σ f_y: within the cosine
    // of the active normals' tilt, under 0.1 % here; exact at the full load, whose active set is the one-step run's)
    EXPECT_NEAR(c.normal_force, inc.load_factor * P, 1e-3 * inc.load_factor * P) << i;
    if (i > 0) {
      EXPECT_GT(c.normal_force, four.increments[i - 1].contacts[0].normal_force) << i;
      EXPECT_GE(c.active_nodes, four.increments[i - 1].contacts[0].active_nodes) << i;
    }
  }
  // the Hertz zone grows like sqrt(P): more nodes in contact at the full load than at a quarter of it
  EXPECT_GT(four.increments[3].contacts[0].active_nodes, four.increments[0].contacts[0].active_nodes);
  EXPECT_EQ(four.increments[3].contacts[0].active_nodes, one.contacts[0].active_nodes);
  EXPECT_NEAR(four.contacts[0].normal_force, P, 1e-6 * P);
  const double scale = max_abs(one);
  for (size_t b = 0; b < one.bodies.size(); ++b)
    EXPECT_LT((four.bodies[b].displacement - one.bodies[b].displacement).cwiseAbs().maxCoeff(), 1e-6 * scale);
  // a later increment starts from the previous active set: it settles in fewer solves than the first
  EXPECT_LE(four.increments[3].active_set_iterations, four.increments[0].active_set_iterations);
  const std::vector<std::string> expected{"begin 1/4", "end 1/4", "begin 2/4", "end 2/4",
                                          "begin 3/4", "end 3/4", "begin 4/4", "end 4/4"};
  EXPECT_EQ(rec.events, expected);
  EXPECT_EQ(rec.progress, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
}

TEST(LoadIncrements, CancelBetweenIncrementsKeepsTheCompletedOnes) {
  Recorder rec;
  rec.cancel_after_increment = 2;  // asked as increment 2 ends: honoured before increment 3 starts
  const Results r = solve(sample_json("plate-hole-2d.json"), "direct", 4, &rec);
  EXPECT_EQ(to_string(r.status.status), std::string("cancelled"));
  ASSERT_EQ(r.increments.size(), 2u);
  EXPECT_EQ(rec.events, (std::vector<std::string>{"begin 1/4", "end 1/4", "begin 2/4", "end 2/4"}));
  ASSERT_EQ(r.bodies.size(), r.increments[1].bodies.size());
  for (size_t b = 0; b < r.bodies.size(); ++b)
    EXPECT_EQ(r.bodies[b].displacement, r.increments[1].bodies[b].displacement);
}

TEST(LoadIncrements, CountOutsideOneToAThousandIsRefused) {
  const Project p = parse_project(sample_json("plate-hole-2d.json").dump(), "increments");
  const Model model = build_model(p);
  auto solver = make_solver("direct", {});
  for (const int n : {0, -1, 1001}) EXPECT_THROW(run_linear_static(model, *solver, nullptr, n), AnalysisError) << n;
  json bad = sample_json("plate-hole-2d.json");
  for (const json& v : {json(0), json(1.5), json("x"), json(1001)}) {
    bad["analysis"] = {{"increments", v}};
    try {
      parse_project(bad.dump(), "bad");
      ADD_FAILURE() << "accepted " << v.dump();
    } catch (const ProjectError& e) {
      EXPECT_NE(std::string(e.what()).find("analysis.increments"), std::string::npos) << e.what();
    }
  }
  bad["analysis"] = {{"increments", 3}};
  EXPECT_EQ(parse_project(bad.dump(), "ok").config().steps.increments, 3);
}

}  // namespace test_load_increments
