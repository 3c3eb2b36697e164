// The output folder holds one run: the files a run writes (and the temporaries of an interrupted write) are
// recognised and removed before the next run writes, other files are kept; a failed atomic write leaves no
// temporary behind.
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>

#include <algorithm>
#include <fstream>

#include "../../common/FreshDir.h"
#include "io/AtomicFile.h"
#include "io/OutputFolder.h"

namespace test_output_folder {

using namespace rollsim;
namespace fs = std::filesystem;

namespace {
void touch(const fs::path& p) { std::ofstream(p) << "x"; }
}  // namespace

TEST(OutputFolder, RecognisesWhatARunWrites) {
  for (const char* name :
       {"summary.json", "result.vtu", "results.pvd", "results_0001.vtu", "results_12345.vtu", ".summary.json.tmp",
        ".results_0002.vtu.tmp", ".result.vtu.4242-7.tmp", "convergence.csv", "rolling.csv", "contact_profile.csv",
        "rolling.png", "contact_profile.png", ".rolling.png.tmp"})
    EXPECT_TRUE(is_run_output(name, {"rolling.csv", "contact_profile.csv", "rolling.png", "contact_profile.png"}))
        << name;
  EXPECT_FALSE(is_run_output("rolling.csv"));  // a process's file is one only when the caller names it
  for (const char* name : {"mesh.vtu", "notes.txt", "results_.vtu", "results_00a1.vtu", "summary.json.bak",
                           ".notes.txt.tmp", "result.vtu.tmp", "my_results_0001.vtu"})
    EXPECT_FALSE(is_run_output(name)) << name;
}

TEST(OutputFolder, ClearRemovesAnEarlierRunAndKeepsOtherFiles) {
  const fs::path d = fresh_dir("clear");
  for (const char* name :
       {"summary.json", "result.vtu", "results.pvd", "results_0003.vtu", ".result.vtu.tmp", "notes.txt", "mesh.vtu"})
    touch(d / name);
  fs::create_directories(d / "results_0004.vtu");  // a folder is never removed
  clear_run_outputs(d);
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(d)) left.push_back(e.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"mesh.vtu", "notes.txt", "results_0004.vtu"}));
  fs::remove_all(d);
}

TEST(OutputFolder, FailedAtomicWriteLeavesNoTemporary) {
  const fs::path d = fresh_dir("atomic");
  fs::create_directories(d / "summary.json" / "occupied");  // the rename onto a non-empty folder fails
  EXPECT_THROW(write_file_atomically(d / "summary.json", "{}\n"), std::runtime_error);
  write_file_atomically(d / "other.json", "{}\n");
  EXPECT_TRUE(fs::exists(d / "other.json"));
  for (const auto& e : fs::directory_iterator(d))
    EXPECT_NE(e.path().filename().string()[0], '.') << "a temporary was left: " << e.path();
  fs::remove_all(d);
}

}  // namespace test_output_folder
