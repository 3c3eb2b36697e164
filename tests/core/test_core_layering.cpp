// The layering of core/'s folders, checked on the sources the way CoreIsolation checks Qt and VTK: a folder includes
// only the folders below it (../shared/architecture.json draws the same rules). kKnown lists, by file, an arrow that
// is tolerated for a while; the test fails on any new arrow and on a listed one that has gone.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>

namespace test_core_layering {

namespace {

// folder -> folders it must never include
const std::map<std::string, std::set<std::string>> kNever = {
    {"base",
     {"mesh", "model", "fem", "material", "partition", "contact", "solve", "analysis", "process", "project", "io",
      "bench"}},
    {"mesh",
     {"model", "fem", "material", "partition", "contact", "solve", "analysis", "process", "project", "io", "bench"}},
    {"model", {"fem", "material", "partition", "contact", "solve", "analysis", "process", "project", "io", "bench"}},
    {"material", {"fem", "partition", "contact", "solve", "analysis", "process", "project", "io", "bench"}},
    {"fem", {"partition", "contact", "solve", "analysis", "process", "project", "io", "bench"}},
    {"partition", {"fem", "material", "contact", "solve", "analysis", "process", "project", "io", "bench"}},
    {"contact", {"fem", "partition", "solve", "analysis", "process", "project", "io", "bench"}},
    {"solve",
     {"mesh", "model", "fem", "material", "partition", "contact", "analysis", "process", "project", "io", "bench"}},
    {"analysis", {"process", "project", "io", "bench"}},  // the driver speaks of measures, not of a process
    {"process", {"project", "io", "bench"}},
    {"io", {"solve", "process", "project", "bench"}},  // writers loop over registries: they know no process
};

// file -> folder it still includes against the rules (none left: keep the mechanism for the next exception)
const std::set<std::pair<std::string, std::string>> kKnown = {};

}  // namespace

TEST(CoreLayering, FoldersIncludeOnlyTheFoldersBelowThem) {
  const std::filesystem::path core = std::filesystem::path(ROLLSIM_SOURCE_DIR) / "core";
  const std::regex include(R"(^\s*#\s*include\s*"([a-z]+)/)");
  std::set<std::pair<std::string, std::string>> found;
  int files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(core)) {
    if (!e.is_regular_file()) continue;
    const std::string rel = std::filesystem::relative(e.path(), core).generic_string();
    const std::string folder = rel.substr(0, rel.find('/'));
    const auto rules = kNever.find(folder);
    if (rules == kNever.end()) continue;
    ++files;
    std::ifstream in(e.path());
    std::string line;
    std::smatch m;
    while (std::getline(in, line))
      if (std::regex_search(line, m, include) && rules->second.count(m[1].str())) {
        found.insert({rel, m[1].str()});
        EXPECT_TRUE(kKnown.count({rel, m[1].str()})) << rel << " includes " << m[1] << "/: " << line;
      }
  }
  for (const auto& known : kKnown)
    EXPECT_TRUE(found.count(known)) << known.first << " no longer includes " << known.second
                                    << "/: remove it from kKnown";
  EXPECT_GT(files, 60);
}

}  // namespace test_core_layering
