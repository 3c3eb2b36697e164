// Spawns the rollsim binary (posix_spawn), collects stdout/stderr through files, enforces a timeout.
#include "RunBinary.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace {

using Clock = std::chrono::steady_clock;

pid_t spawn(const std::string& program, const std::vector<std::string>& args, const std::string& out,
            const std::string& err) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv{const_cast<char*>(program.c_str())};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot spawn " + program);
  return pid;
}

/// Waits for `pid`, polling (calling `on_poll`, if given, at each poll); kills it at the deadline. Returns the wait
/// status.
int wait_with_timeout(pid_t pid, int timeout_s, bool& timed_out, const std::function<void()>& on_poll = {}) {
  const auto deadline = Clock::now() + std::chrono::seconds(timeout_s);
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (on_poll) on_poll();
    if (Clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return status;
}

}  // namespace

std::string make_temp_dir(const std::string& tag) {
  static std::atomic<int> counter = 0;
  const auto dir = std::filesystem::temp_directory_path() /
                   ("rollsim-" + tag + "-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

std::vector<std::string> list_dir(const std::string& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

RunResult run_rollsim(const std::vector<std::string>& args, int timeout_s) {
  return run_program(ROLLSIM_BINARY, args, timeout_s);
}

RunResult run_program(const std::string& program, const std::vector<std::string>& args, int timeout_s) {
  return run_program_interrupted(program, args, "", timeout_s);
}

RunResult run_program_interrupted(const std::string& program, const std::vector<std::string>& args,
                                  const std::string& marker, int timeout_s) {
  return run_program_on_marker(
      program, args, marker, [](int pid) { kill(pid, SIGINT); }, timeout_s);
}

RunResult run_program_on_marker(const std::string& program, const std::vector<std::string>& args,
                                const std::string& marker, const std::function<void(int pid)>& on_marker,
                                int timeout_s) {
  const std::string dir = make_temp_dir("io");
  const std::string out = dir + "/stdout", err = dir + "/stderr";
  RunResult r;
  const auto start = Clock::now();
  const pid_t pid = spawn(program, args, out, err);
  bool done = marker.empty();
  const auto act_on_marker = [&] {
    if (!done && read_text(err).find(marker) != std::string::npos) {
      done = true;
      on_marker(pid);
    }
  };
  const int status = wait_with_timeout(pid, timeout_s, r.timed_out, act_on_marker);
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (!r.timed_out && WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.out = read_text(out);
  r.err = read_text(err);
  std::filesystem::remove_all(dir);
  return r;
}
