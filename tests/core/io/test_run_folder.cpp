// One run owns its output folder (io/RunFolder): the lock refuses a second owner naming the first, the earlier
// outputs go and a `running` summary with the run's stamp comes at once, a read-only folder is refused before any
// work, free space is compared with what the results need, and the project's hash is what sha256sum prints.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "../../common/FreshDir.h"
#include "io/RunFolder.h"

namespace test_run_folder {

using namespace rollsim;
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {
json read_json(const fs::path& p) {
  std::ifstream in(p);
  return json::parse(in);
}
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const FolderError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(RunFolder, TakesTheFolderRemovesTheEarlierRunAndSaysRunning) {
  const fs::path d = fresh_dir("runfolder-take") / "out";
  fs::create_directories(d);
  std::ofstream(d / "result.vtu") << "an earlier run's";
  std::ofstream(d / "notes.txt") << "the user's";
  const json stamp = RunStamp{"rollsim run p.json", "p.json"}.to_json();
  {
    const RunFolder folder(d, stamp, {});
    EXPECT_FALSE(fs::exists(d / "result.vtu"));
    EXPECT_TRUE(fs::exists(d / "notes.txt"));
    const json s = read_json(d / "summary.json");
    EXPECT_EQ(s["status"], "running");
    EXPECT_EQ(s["run"]["pid"], static_cast<long>(::getpid()));
    EXPECT_EQ(s["run"]["command"], "rollsim run p.json");
  }
  fs::remove_all(d.parent_path());
}

TEST(RunFolder, ASecondOwnerIsRefusedNamingTheFirstUntilItEnds) {
  const fs::path d = fresh_dir("runfolder-busy");
  const json stamp = RunStamp{"rollsim run first.json", "first.json"}.to_json();
  {
    const RunFolder first(d, stamp, {});
    const std::string m = message_of([&] { RunFolder second(d, RunStamp{"second", ""}.to_json(), {}); });
    EXPECT_NE(m.find("is in use by the run started " + stamp["started"].get<std::string>() + " by pid " +
                     std::to_string(::getpid()) + " (`rollsim run first.json`)"),
              std::string::npos)
        << m;
    EXPECT_EQ(read_json(d / "summary.json")["run"]["command"], "rollsim run first.json") << "the refused run wrote";
  }
  EXPECT_EQ(message_of([&] { RunFolder again(d, RunStamp{"again", ""}.to_json(), {}); }), "");
  fs::remove_all(d);
}

TEST(RunFolder, AReadOnlyFolderIsRefused) {
  const fs::path d = fresh_dir("runfolder-readonly");
  fs::permissions(d, fs::perms::owner_read | fs::perms::owner_exec);
  const std::string m = message_of([&] { RunFolder f(d, json::object(), {}); });
  EXPECT_NE(m.find("read-only"), std::string::npos) << m;
  EXPECT_TRUE(fs::is_empty(d));
  fs::permissions(d, fs::perms::owner_all);
  fs::remove_all(d);
}

TEST(RunFolder, FreeSpaceIsComparedWithWhatTheResultsNeed) {
  const fs::path d = fresh_dir("runfolder-space");
  EXPECT_EQ(message_of([&] { check_free_space(d, 1e3); }), "");
  const std::string m = message_of([&] { check_free_space(d, 1e18); });
  EXPECT_NE(m.find("the results need at least 1000000000000.0 MB"), std::string::npos) << m;
  EXPECT_NE(m.find(" MB free"), std::string::npos) << m;
  fs::remove_all(d);
}

TEST(RunFolder, TheProjectHashIsSha256OfItsBytes) {
  const fs::path d = fresh_dir("runfolder-hash");
  std::ofstream(d / "abc") << "abc";
  EXPECT_EQ(file_sha256(d / "abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(file_sha256(d / "missing"), "");
  fs::remove_all(d);
}

}  // namespace test_run_folder
