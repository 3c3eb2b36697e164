#include "io/AtomicFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

namespace rollsim {

namespace {
namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& target, const std::string& what, int error) {
  throw WriteError("cannot write " + target.string() + ": " + what +
                   (error ? std::string(": ") + std::strerror(error) : ""));
}

/// The file a write to `target` replaces: the target, or what its symlink (chain) points to.
fs::path resolve(const fs::path& target) {
  std::error_code ec;
  if (!fs::is_symlink(fs::symlink_status(target, ec))) return target;
  const fs::path real = fs::weakly_canonical(target, ec);
  return ec ? target : real;
}

/// A temporary beside `file`, created exclusively with mode 0666 less the umask; its fd.
int create_temporary(const fs::path& file, fs::path& tmp) {
  static std::atomic<unsigned> counter = 0;
  for (int attempt = 0; attempt < 100; ++attempt) {
    tmp = file.parent_path() / ("." + file.filename().string() + "." + std::to_string(::getpid()) + "-" +
                                std::to_string(counter++) + ".tmp");
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

/// Writes every byte; the number written (short only on error, errno set).
size_t write_all(int fd, const std::string& content) {
  size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = EIO;
      break;
    }
    done += static_cast<size_t>(n);
  }
  return done;
}

void sync_folder(const fs::path& dir) {
  const int fd = ::open(dir.empty() ? "." : dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);  // the rename's durability: best effort (some file systems refuse fsync on folders)
  ::close(fd);
}

/// Writes `content` into the open temporary `fd` (keeping `mode` if the target had one) and closes it.
void fill(int fd, const fs::path& target, const std::string& content, const struct stat* existing) {
  const size_t written = write_all(fd, content);
  int error = errno;
  if (written != content.size()) {
    ::close(fd);
    fail(target, "wrote " + std::to_string(written) + " of " + std::to_string(content.size()) + " bytes", error);
  }
  if (existing && ::fchmod(fd, existing->st_mode & 07777) != 0) {
    error = errno;
    ::close(fd);
    fail(target, "cannot keep its permissions", error);
  }
  if (::fsync(fd) != 0) {
    error = errno;
    ::close(fd);
    fail(target, "cannot flush it to disk", error);
  }
  if (::close(fd) != 0) fail(target, "cannot close it", errno);
}
}  // namespace

bool is_writable(const fs::path& path) {
  struct stat s {};
  return ::stat(path.c_str(), &s) == 0 && (s.st_mode & 0222) != 0 && ::access(path.c_str(), W_OK) == 0;
}

void write_file_atomically(const fs::path& target, const std::string& content) {
  const fs::path file = resolve(target);
  struct stat existing {};
  const bool exists = ::stat(file.c_str(), &existing) == 0;
  if (exists && !S_ISREG(existing.st_mode)) fail(target, "it exists and is not a regular file", 0);
  if (exists && !is_writable(file)) fail(target, "it is read-only", 0);
  fs::path tmp;
  const int fd = create_temporary(file, tmp);
  if (fd < 0) fail(target, "cannot create a file in " + file.parent_path().string(), errno);
  try {
    fill(fd, target, content, exists ? &existing : nullptr);
    if (::rename(tmp.c_str(), file.c_str()) != 0) fail(target, "cannot rename the complete file into place", errno);
  } catch (...) {
    ::unlink(tmp.c_str());  // no temporary left behind
    throw;
  }
  sync_folder(file.parent_path());
}

std::optional<std::string> temporary_for(const std::string& name) {
  const std::string tail = ".tmp";
  if (name.size() <= 1 + tail.size() || name[0] != '.' ||
      name.compare(name.size() - tail.size(), tail.size(), tail) != 0)
    return std::nullopt;
  std::string inner = name.substr(1, name.size() - 1 - tail.size());  // NAME or NAME.<pid>-<n>
  const size_t dot = inner.rfind('.');
  if (dot != std::string::npos && dot + 1 < inner.size() &&
      inner.find_first_not_of("0123456789-", dot + 1) == std::string::npos && inner.find('-', dot) != std::string::npos)
    inner.resize(dot);
  return inner;
}

}  // namespace rollsim
