// Seeded mutation fuzzing of the project parser and model builder: whatever the text, the only
// outcome besides success is a ProjectError with at least one message (no crash, no other exception).
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "../../common/ProjectMutator.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

using namespace rollsim;
using fuzz::kSeed;
using fuzz::mutate;

TEST(ProjectFuzz, SeedIsValid) { EXPECT_NO_THROW(build_model(parse_project(kSeed, "seed"))); }

TEST(ProjectFuzz, MutantsOnlyEverGiveProjectErrors) {
  int valid = 0, invalid = 0;
  for (unsigned seed = 1; seed <= 3000; ++seed) {
    std::mt19937 rng(seed);
    const std::string text = mutate(kSeed, rng);
    try {
      const Model m = build_model(parse_project(text, "mutant"));
      ++valid;
      EXPECT_GT(m.total_nodes(), 0);
    } catch (const ProjectError& e) {
      ++invalid;
      ASSERT_FALSE(e.issues().empty()) << "seed " << seed;
      for (const auto& i : e.issues()) ASSERT_FALSE(i.message.empty()) << "seed " << seed;
    } catch (const std::exception& e) {
      FAIL() << "seed " << seed << ": unexpected " << typeid(e).name() << ": " << e.what() << "\n" << text;
    }
  }
  std::printf("  3000 mutants: %d valid, %d refused with a ProjectError\n", valid, invalid);
  EXPECT_GT(invalid, 1000);
}

TEST(ProjectFuzz, DeepNestingIsRefused) {
  for (const std::string& open : {std::string("["), std::string("{\"a\":")}) {
    std::string text;
    for (int i = 0; i < 100000; ++i) text += open;
    EXPECT_THROW(parse_project(text, "deep"), ProjectError);
  }
}
