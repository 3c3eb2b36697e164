// docs/project-format.md is the schema's own markdown: the docs cannot drift from the validator.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "project/ProjectSchema.h"

namespace test_project_format_doc {

TEST(ProjectFormatDoc, MatchesSchema) {
  std::ifstream in(std::string(ROLLSIM_SOURCE_DIR) + "/docs/project-format.md");
  ASSERT_TRUE(in) << "docs/project-format.md is missing: build/app/rollsim schema > docs/project-format.md";
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), rollsim::project_format_markdown())
      << "docs/project-format.md is stale: regenerate with build/app/rollsim schema > docs/project-format.md";
}

}  // namespace test_project_format_doc
