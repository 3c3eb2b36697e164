// Files written whole or not at all (io/AtomicFile): a cut-off write is an error naming the file and the OS reason
// and publishes nothing; an existing target keeps its permissions, a symlinked one stays a link, a read-only one is
// refused, and a planted temporary name is never followed.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../../common/FreshDir.h"
#include "io/AtomicFile.h"

namespace test_atomic_file {

using namespace rollsim;
namespace fs = std::filesystem;

namespace {
std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
void put(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }
std::vector<std::string> names(const fs::path& d) {
  std::vector<std::string> n;
  for (const auto& e : fs::directory_iterator(d)) n.push_back(e.path().filename().string());
  std::sort(n.begin(), n.end());
  return n;
}
mode_t mode_of(const fs::path& p) {
  struct stat s {};
  ::stat(p.c_str(), &s);
  return s.st_mode & 07777;
}
}  // namespace

// The reported case: under `ulimit -f 50` (SIGXFSZ ignored) the cut-off file was renamed into place as complete.
TEST(AtomicFile, AWriteCutOffByTheFileSizeLimitFailsAndPublishesNothing) {
  const fs::path d = fresh_dir("atomic-fsize");
  const std::string big(200 * 1024, 'x');
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // the limit applies to this process only
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{50 * 1024, 50 * 1024};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      write_file_atomically(d / "result.vtu", big);
      ::_exit(10);  // published as complete
    } catch (const WriteError& e) {
      const std::string m = e.what();
      const bool named = m.find((d / "result.vtu").string()) != std::string::npos;
      const bool counted = m.find("wrote 51200 of 204800 bytes") != std::string::npos;
      const bool reason = m.find("File too large") != std::string::npos;
      ::_exit(named && counted && reason ? 0 : 11);
    }
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0)
      << "10: the cut-off file was published; 11: the message lacks file, count or reason";
  EXPECT_TRUE(names(d).empty()) << "neither the target nor a temporary may be left";
  fs::remove_all(d);
}

TEST(AtomicFile, AnExistingTargetKeepsItsPermissions) {
  const fs::path d = fresh_dir("atomic-mode");
  put(d / "project.json", "{}");
  fs::permissions(d / "project.json", fs::perms::owner_read | fs::perms::owner_write);
  write_file_atomically(d / "project.json", "{\"a\": 1}\n");
  EXPECT_EQ(read(d / "project.json"), "{\"a\": 1}\n");
  EXPECT_EQ(mode_of(d / "project.json"), 0600u) << "a private file must not be widened to 0644";
  fs::remove_all(d);
}

TEST(AtomicFile, AReadOnlyTargetIsRefusedAndKept) {
  const fs::path d = fresh_dir("atomic-readonly");
  put(d / "project.json", "original");
  fs::permissions(d / "project.json", fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  try {
    write_file_atomically(d / "project.json", "replaced");
    ADD_FAILURE() << "a read-only target was replaced";
  } catch (const WriteError& e) {
    EXPECT_NE(std::string(e.what()).find("read-only"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read(d / "project.json"), "original");
  EXPECT_EQ(names(d), std::vector<std::string>{"project.json"});
  fs::remove_all(d);
}

TEST(AtomicFile, ASymlinkedTargetIsWrittenThroughAndStaysALink) {
  const fs::path d = fresh_dir("atomic-link");
  fs::create_directories(d / "real");
  put(d / "real" / "project.json", "old");
  fs::create_symlink("real/project.json", d / "project.json");
  write_file_atomically(d / "project.json", "new");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(d / "project.json")));
  EXPECT_EQ(read(d / "real" / "project.json"), "new");
  fs::remove_all(d);
}

TEST(AtomicFile, APlantedTemporaryNameIsNeverFollowed) {
  const fs::path d = fresh_dir("atomic-planted");
  put(d / "victim", "keep me");
  fs::create_symlink(d / "victim", d / ".project.json.tmp");  // the old fixed temporary name
  write_file_atomically(d / "project.json", "saved");
  EXPECT_EQ(read(d / "victim"), "keep me");
  EXPECT_EQ(read(d / "project.json"), "saved");
  EXPECT_FALSE(fs::is_symlink(fs::symlink_status(d / "project.json")));
  fs::remove_all(d);
}

TEST(AtomicFile, TemporaryNamesAreRecognised) {
  EXPECT_EQ(temporary_for(".result.vtu.123-4.tmp"), "result.vtu");
  EXPECT_EQ(temporary_for(".result.vtu.tmp"), "result.vtu");
  EXPECT_EQ(temporary_for(".results_0002.vtu.99-0.tmp"), "results_0002.vtu");
  EXPECT_FALSE(temporary_for("result.vtu.tmp"));
  EXPECT_FALSE(temporary_for("result.vtu"));
  EXPECT_FALSE(temporary_for(".tmp"));
}

}  // namespace test_atomic_file
