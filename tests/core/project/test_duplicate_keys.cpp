// A key given twice in one object is refused with its path (project/DuplicateKeys): JSON parsers keep the last one
// silently, although unknown keys are refused.
#include <gtest/gtest.h>

#include "project/DuplicateKeys.h"
#include "project/Project.h"

namespace test_duplicate_keys {

using namespace rollsim;

TEST(DuplicateKeys, NamesEachRepeatedKeyByItsPath) {
  const auto issues = duplicate_keys(R"({"a": 1, "process": {"reduction": 0.2, "travel": 5, "reduction": 0.3},
      "bodies": [{"name": "x"}, {"name": "y", "mesh": {"nx": 2, "nx": 3}}], "a": 2})");
  ASSERT_EQ(issues.size(), 3u);
  EXPECT_EQ(issues[0].path, "process.reduction");
  EXPECT_EQ(issues[1].path, "bodies[1].mesh.nx");
  EXPECT_EQ(issues[2].path, "a");
  EXPECT_NE(issues[0].message.find("given twice"), std::string::npos);
}

TEST(DuplicateKeys, TheSameKeyInDifferentObjectsIsFine) {
  EXPECT_TRUE(duplicate_keys(R"({"a": {"n": 1}, "b": {"n": 2}, "c": [{"n": 1}, {"n": 2}], "n": [1, 1]})").empty());
}

TEST(DuplicateKeys, AProjectWithOneIsRefused) {
  try {
    parse_project(R"({"dimension": 2, "dimension": 3})", "p.json");
    ADD_FAILURE() << "accepted";
  } catch (const ProjectError& e) {
    EXPECT_NE(std::string(e.what()).find("dimension"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("given twice"), std::string::npos) << e.what();
  }
}

}  // namespace test_duplicate_keys
