// Every sample: `skyline` and `direct` give the same displacements (1e-10 relative), `mixed` (CG tolerance
// 1e-10) the same to 1e-7, and so does `feti` where the sample asks for it; a model with a floating body is refused by
// `skyline` with a clear error. The key quantities (dofs, reactions, probe displacements, contact resultants) match the
// committed golden file tests/golden/<sample>.json to 1e-8 relative (a vector component to its largest).
// ROLLSIM_UPDATE_GOLDEN=1 rewrites the golden files.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "analysis/LinearStatic.h"
#include "io/Summary.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_samples {

using namespace rollsim;
namespace fs = std::filesystem;

namespace {

/// The samples of the linear analysis (the Newton samples have their own tests: their answers depend on the path).
std::vector<std::string> sample_files() {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(fs::path(ROLLSIM_SOURCE_DIR) / "samples"))
    if (e.path().extension() == ".json" && load_project(e.path()).config().analysis == "linear")
      files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

struct Solved {
  Results results;
  SolveStats stats;
};

Solved solve(const Model& model, const std::string& mode) {
  auto solver = make_solver(mode, {1e-10, 1});
  Solved s{run_linear_static(model, *solver), {}};
  s.stats = solver->stats();
  return s;
}

/// The golden part of a summary: what must not change silently.
json golden_view(const json& summary) {
  return {{"model", summary.at("model")},
          {"reactions", summary.at("results").at("reactions")},
          {"probes", summary.at("results").at("probes")},
          {"max_abs_displacement", summary.at("results").at("max_abs_displacement")},
          {"contact", summary.at("results").at("contact")}};
}

/// A number within 1e-8 of `scale` (at least 1 and |want|): a vector's components are judged against the largest of
/// them, so a component that is zero up to round-off (the x reaction of a panel loaded in y) is not held to 1e-8 alone.
void expect_close(const json& got, const json& want, const std::string& path, double scale = 1.0) {
  if (want.is_number_float() || (want.is_number() && got.is_number_float())) {
    const double g = got.get<double>(), w = want.get<double>();
    EXPECT_NEAR(g, w, 1e-8 * std::max(scale, std::abs(w))) << path;
  } else if (want.is_object() || want.is_array()) {
    ASSERT_EQ(got.size(), want.size()) << path;
    double largest = 1.0;
    if (want.is_array())
      for (const json& w : want)
        if (w.is_number()) largest = std::max(largest, std::abs(w.get<double>()));
    for (auto it = want.begin(); it != want.end(); ++it) {
      const std::string key = want.is_object() ? it.key() : std::to_string(std::distance(want.begin(), it));
      const json& g = want.is_object() ? got.at(it.key()) : got.at(static_cast<size_t>(std::stoul(key)));
      expect_close(g, *it, path + "." + key, largest);
    }
  } else {
    EXPECT_EQ(got, want) << path;
  }
}

}  // namespace

// outside the anonymous namespace: the fixture of a TEST_P must not have internal linkage (GCC's -Wsubobject-linkage)
class SampleTest : public testing::TestWithParam<std::string> {};

void expect_same_displacements(const Model& model, const Results& a, const Results& b, double tol,
                               const std::string& what) {
  double umax = 0, diff = 0;
  for (size_t i = 0; i < model.bodies.size(); ++i) {
    umax = std::max(umax, a.bodies[i].displacement.cwiseAbs().maxCoeff());
    diff = std::max(diff, (a.bodies[i].displacement - b.bodies[i].displacement).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(diff, tol * umax) << what;
}

TEST_P(SampleTest, SolversAgreeAndMatchGolden) {
  const Project project = load_project(GetParam());
  const Model model = build_model(project);
  const Solved direct = solve(model, "direct"), mixed = solve(model, "mixed");
  expect_same_displacements(model, direct.results, mixed.results, 1e-7, "mixed vs direct");
  if (project.data.at("solver").at("mode") == "feti")
    expect_same_displacements(model, direct.results, solve(model, "feti").results, 1e-7, "feti vs direct");
  if (direct.results.rigid_modes > 0) {
    EXPECT_THROW(solve(model, "skyline"), AnalysisError);
  } else {
    // two direct factorizations of one matrix agree to about κ ε: the Cook's membrane's ν = 0.4999 rubber is the
    // worst conditioned sample (its tip's difference 3e-11 of the tip's displacement, 1.5e-10 since the element
    // matrices are computed from coordinates relative to the element: the same matrix to round-off)
    expect_same_displacements(model, direct.results, solve(model, "skyline").results, 1e-9, "skyline vs direct");
  }
  const json got = golden_view(make_summary(model, direct.results, {project.name(), "direct", to_json(RunConfig{})}));
  const fs::path golden = fs::path(ROLLSIM_SOURCE_DIR) / "tests" / "golden" / (project.name() + ".json");
  if (std::getenv("ROLLSIM_UPDATE_GOLDEN")) {
    std::ofstream(golden) << got.dump(2) << "\n";
    GTEST_SKIP() << "golden file rewritten: " << golden;
  }
  std::ifstream in(golden);
  ASSERT_TRUE(in) << "missing golden file " << golden << " (run with ROLLSIM_UPDATE_GOLDEN=1 once)";
  expect_close(got, json::parse(in), project.name());
}

INSTANTIATE_TEST_SUITE_P(Samples, SampleTest, testing::ValuesIn(sample_files()), [](const auto& info) {
  std::string n = fs::path(info.param).stem().string();
  for (char& c : n)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return n;
});

}  // namespace test_samples
