#include "io/RunFolder.h"

#include <fcntl.h>
#include <openssl/evp.h>
#include <sys/file.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iterator>

#include "io/AtomicFile.h"
#include "io/OutputFolder.h"

namespace rollsim {

namespace fs = std::filesystem;
using json = nlohmann::json;

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string file_sha256(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "";
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest, &length, EVP_sha256(), nullptr) != 1) return "";
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) {
    char byte[3];
    std::snprintf(byte, sizeof byte, "%02x", digest[i]);
    hex += byte;
  }
  return hex;
}

json RunStamp::to_json() const {
  char host[256] = "";
  ::gethostname(host, sizeof host - 1);
  return {{"started", utc_now()},
          {"command", command},
          {"project_file", project_file},
          {"project_sha256", file_sha256(project_file)},
          {"pid", static_cast<long>(::getpid())},
          {"host", host}};
}

namespace {
/// Who holds `dir`, from the summary it wrote when it started.
std::string owner_of(const fs::path& dir) {
  std::ifstream in(dir / "summary.json");
  const json summary = json::parse(in, nullptr, false);
  if (summary.is_discarded() || !summary.contains("run")) return "another run";
  const json& run = summary["run"];
  return "the run started " + run.value("started", std::string("?")) + " by pid " +
         std::to_string(run.value("pid", 0L)) + " (`" + run.value("command", std::string("?")) + "`)";
}

std::string megabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f MB", bytes / 1e6);
  return text;
}
}  // namespace

RunFolder::RunFolder(const fs::path& dir, const json& run, const std::vector<std::string>& outputs) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw FolderError("cannot create output directory " + dir.string() + ": " + ec.message());
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw FolderError("cannot open the output folder " + dir.string() + ": " + std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    throw FolderError("the output folder " + dir.string() + " is in use by " + owner_of(dir) +
                      ": wait for it to end, or choose another folder (--out)");
  }
  try {
    if (!is_writable(dir)) throw FolderError("it is read-only");
    clear_run_outputs(dir, outputs);
    write_file_atomically(dir / "summary.json", json{{"status", "running"}, {"run", run}}.dump(2) + "\n");
  } catch (const std::exception& e) {
    ::close(fd_);
    throw FolderError("cannot write into the output folder " + dir.string() +
                      " (checked before the analysis): " + e.what());
  }
}

RunFolder::~RunFolder() { ::close(fd_); }  // closing the folder releases the lock

void check_free_space(const fs::path& dir, double bytes) {
  struct statvfs s {};
  if (::statvfs(dir.c_str(), &s) != 0) return;  // unknown: the writes are checked one by one anyway
  const double free = static_cast<double>(s.f_bavail) * static_cast<double>(s.f_frsize);
  if (bytes > free)
    throw FolderError("the results need at least " + megabytes(bytes) + " and the file system of " + dir.string() +
                      " has " + megabytes(free) +
                      " free: free some space, choose another folder (--out), or write "
                      "fewer files (output.increments, output.fields)");
}

}  // namespace rollsim
