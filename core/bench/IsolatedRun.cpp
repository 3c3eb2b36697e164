#include "bench/IsolatedRun.h"

#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <string>

#include "base/Stopwatch.h"

namespace rollsim::bench {

namespace {

void write_all(int fd, const std::string& s) {
  size_t done = 0;
  while (done < s.size()) {
    const ssize_t n = ::write(fd, s.data() + done, s.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    done += static_cast<size_t>(n);
  }
}

[[noreturn]] void child(const SuiteCase& c, int fd) {
  std::string text;
  try {
    text = to_json(run_case(c)).dump();
  } catch (...) {
    text = R"({"status": "error", "message": "the case could not report its outcome"})";
  }
  write_all(fd, text);
  ::close(fd);
  ::_exit(0);
}

/// Reads the child's report until it closes the pipe or the deadline passes (false: timed out).
bool read_report(int fd, double timeout_s, std::string& text) {
  Stopwatch clock;
  char buffer[65536];
  for (;;) {
    const double left = timeout_s - clock.seconds();
    if (left <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(left * 1000) + 1);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    text.append(buffer, static_cast<size_t>(n));
  }
}

CaseOutcome failed(const std::string& status, const std::string& message) {
  CaseOutcome o;
  o.status = status, o.message = message;
  return o;
}

}  // namespace

CaseOutcome run_case_isolated(const SuiteCase& c, double timeout_s) {
  int fds[2];
  if (::pipe(fds) != 0) return failed("error", std::string("pipe: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) return failed("error", std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    ::close(fds[0]);
    child(c, fds[1]);
  }
  ::close(fds[1]);
  std::string text;
  const bool in_time = read_report(fds[0], timeout_s, text);
  if (!in_time) ::kill(pid, SIGKILL);
  ::close(fds[0]);
  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  CaseOutcome o;
  if (!in_time)
    o = failed("timeout", "no answer within " + std::to_string(static_cast<int>(timeout_s)) + " s (killed)");
  else if (WIFSIGNALED(status))
    o = failed("crashed", std::string("killed by signal ") + std::to_string(WTERMSIG(status)) + " (" +
                              strsignal(WTERMSIG(status)) + ")");
  else
    try {
      o = outcome_from_json(json::parse(text));
    } catch (const std::exception& e) {
      o = failed("crashed", std::string("no readable report: ") + e.what());
    }
  o.peak_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // Linux: kilobytes
  return o;
}

}  // namespace rollsim::bench
