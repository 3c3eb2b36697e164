// Every sample: `skyline` and `direct` give the same displacements (1e-10 relative), and the key
// quantities (dofs, reactions, probe displacements) match the committed golden file
// tests/golden/<sample>.json to 1e-8 relative. ROLLSIM_UPDATE_GOLDEN=1 rewrites the golden files.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "analysis/LinearStatic.h"
#include "io/Summary.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

using namespace rollsim;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> sample_files() {
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(fs::path(ROLLSIM_SOURCE_DIR) / "samples"))
    if (e.path().extension() == ".json") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

struct Solved {
  Results results;
  SolveStats stats;
};

Solved solve(const Model& model, const std::string& mode) {
  auto solver = make_solver(mode, {});
  Solved s{run_linear_static(model, *solver), {}};
  s.stats = solver->stats();
  return s;
}

/// The golden part of a summary: what must not change silently.
json golden_view(const json& summary) {
  return {{"model", summary.at("model")},
          {"reactions", summary.at("results").at("reactions")},
          {"probes", summary.at("results").at("probes")},
          {"max_abs_displacement", summary.at("results").at("max_abs_displacement")}};
}

void expect_close(const json& got, const json& want, const std::string& path) {
  if (want.is_number_float() || (want.is_number() && got.is_number_float())) {
    const double g = got.get<double>(), w = want.get<double>();
    EXPECT_NEAR(g, w, 1e-8 * std::max(1.0, std::abs(w))) << path;
  } else if (want.is_object() || want.is_array()) {
    ASSERT_EQ(got.size(), want.size()) << path;
    for (auto it = want.begin(); it != want.end(); ++it) {
      const std::string key = want.is_object() ? it.key() : std::to_string(std::distance(want.begin(), it));
      const json& g = want.is_object() ? got.at(it.key()) : got.at(static_cast<size_t>(std::stoul(key)));
      expect_close(g, *it, path + "." + key);
    }
  } else {
    EXPECT_EQ(got, want) << path;
  }
}

class SampleTest : public testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(SampleTest, SkylineEqualsDirectAndMatchesGolden) {
  const Project project = load_project(GetParam());
  const Model model = build_model(project);
  const Solved direct = solve(model, "direct"), skyline = solve(model, "skyline");
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const auto& ud = direct.results.bodies[b].displacement;
    const auto& us = skyline.results.bodies[b].displacement;
    EXPECT_LE((us - ud).cwiseAbs().maxCoeff(), 1e-10 * ud.cwiseAbs().maxCoeff()) << model.bodies[b].name;
  }
  const json got =
      golden_view(make_summary(model, direct.results, direct.stats, {project.name(), "direct", 1e-4, 1, ""}));
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
