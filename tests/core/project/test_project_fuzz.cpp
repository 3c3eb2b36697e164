// Seeded mutation fuzzing of the project parser and model builder: whatever the text, the only outcome besides
// success is a ProjectError whose every issue has a message (no crash, no other exception, no hang).
#include <gtest/gtest.h>

#include <random>

#include "../../common/ProjectMutator.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_project_fuzz {

using namespace rollsim;

namespace {

/// Parses and builds; returns "" on success or a ProjectError, else a description of what went wrong.
std::string outcome(const std::string& text, bool& valid) {
  try {
    const Model m = build_model(parse_project(text, "mutant"));
    valid = true;
    return m.total_nodes() > 0 ? "" : "a model without nodes";
  } catch (const ProjectError& e) {
    valid = false;
    if (e.issues().empty()) return "a ProjectError without issues";
    for (const auto& i : e.issues())
      if (i.message.empty()) return "an issue without a message at '" + i.path + "'";
    return "";
  } catch (const std::exception& e) {
    return std::string("unexpected ") + typeid(e).name() + ": " + e.what();
  }
}

}  // namespace

TEST(ProjectFuzz, SeedsAreValid) {
  for (const char* seed : fuzz::kSeeds) EXPECT_NO_THROW(build_model(parse_project(seed, "seed")));
}

TEST(ProjectFuzz, MutantsOnlyEverGiveProjectErrors) {
  constexpr unsigned kMutants = 20000;
  int valid = 0;
  for (unsigned seed = 1; seed <= kMutants; ++seed) {
    std::mt19937 rng(seed);
    const std::string text = fuzz::mutate(fuzz::kSeeds[seed % std::size(fuzz::kSeeds)], rng);
    bool ok = false;
    const std::string problem = outcome(text, ok);
    ASSERT_EQ(problem, "") << "seed " << seed << "\n" << text.substr(0, 2000);
    valid += ok;
  }
  std::printf("  %u mutants: %d valid, %d refused with a ProjectError\n", kMutants, valid, kMutants - valid);
  EXPECT_GT(valid, 100) << "too few valid mutants: the builder is hardly exercised";
  EXPECT_GT(kMutants - valid, kMutants / 2u) << "too few invalid mutants: the validator is hardly exercised";
}

TEST(ProjectFuzz, DeepNestingIsRefusedWithoutRecursion) {
  const std::string seed = fuzz::kSeeds[0];
  auto deep = [](const std::string& open, const std::string& close, int n) {
    std::string s;
    for (int i = 0; i < n; ++i) s += open;
    for (int i = 0; i < n; ++i) s += close;
    return s;
  };
  for (const std::string& text : {std::string(100000, '['), deep("{\"a\":", "}", 100000),
                                  "{\"dimension\": 2, \"x\": " + deep("[", "]", 1000000) + "}",
                                  std::string(seed).replace(seed.find("[4, 3]"), 6, deep("[", "]", 1000000))}) {
    try {
      parse_project(text, "deep");
      ADD_FAILURE() << "accepted";
    } catch (const ProjectError& e) {
      EXPECT_NE(std::string(e.what()).find("nested deeper than 64 levels at line "), std::string::npos) << e.what();
    }
  }
}

TEST(ProjectFuzz, NestingWithinTheLimitIsNotRefusedForIt) {
  std::string nested = "{\"dimension\": 2, \"x\": ";
  for (int i = 0; i < 60; ++i) nested += "[";
  nested += "\"[[[[{{{{\"";  // brackets inside strings do not count
  for (int i = 0; i < 60; ++i) nested += "]";
  try {
    parse_project(nested + "}", "nested");
    ADD_FAILURE() << "accepted";
  } catch (const ProjectError& e) {
    EXPECT_EQ(std::string(e.what()).find("nested deeper"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("x: unknown field"), std::string::npos) << e.what();
  }
}

}  // namespace test_project_fuzz
