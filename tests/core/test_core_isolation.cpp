// core/ must not include Qt or VTK (the engine never knows the widgets): checked on the sources.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace test_core_isolation {

TEST(CoreIsolation, NoQtOrVtkIncludes) {
  const std::regex forbidden(R"(^\s*#\s*include\s*[<"](Q[A-Za-z]|vtk|QVTK))");
  int files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(std::string(ROLLSIM_SOURCE_DIR) + "/core")) {
    if (!e.is_regular_file()) continue;
    std::ifstream in(e.path());
    std::string line;
    int n = 0;
    ++files;
    while (std::getline(in, line)) {
      ++n;
      EXPECT_FALSE(std::regex_search(line, forbidden)) << e.path() << ":" << n << ": " << line;
    }
  }
  EXPECT_GT(files, 20);
}

}  // namespace test_core_isolation
