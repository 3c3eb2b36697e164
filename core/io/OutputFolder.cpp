#include "io/OutputFolder.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>

#include "io/AtomicFile.h"

namespace rollsim {

namespace {
bool is_result_increment(const std::string& name) {  // results_0001.vtu
  const std::string head = "results_", tail = ".vtu";
  if (name.size() <= head.size() + tail.size() || name.rfind(head, 0) != 0 ||
      name.compare(name.size() - tail.size(), tail.size(), tail) != 0)
    return false;
  const auto digits = name.substr(head.size(), name.size() - head.size() - tail.size());
  return std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool is_final_output(const std::string& name, const std::vector<std::string>& others) {
  static const char* const names[] = {"summary.json", "result.vtu", "results.pvd", "convergence.csv",
                                      "last_converged.vtu"};
  return std::find(std::begin(names), std::end(names), name) != std::end(names) ||
         std::find(others.begin(), others.end(), name) != others.end() || is_result_increment(name);
}
}  // namespace

bool is_run_output(const std::filesystem::path& path, const std::vector<std::string>& others) {
  const std::string name = path.filename().string();
  const std::optional<std::string> temporary = temporary_for(name);
  return is_final_output(temporary ? *temporary : name, others);
}

void clear_run_outputs(const std::filesystem::path& dir, const std::vector<std::string>& others) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    if (!entry.is_regular_file() || !is_run_output(entry.path(), others)) continue;
    std::error_code removed;
    std::filesystem::remove(entry.path(), removed);
    if (removed)
      throw std::runtime_error("cannot remove " + entry.path().string() + " of an earlier run: " + removed.message());
  }
  if (ec) throw std::runtime_error("cannot list " + dir.string() + ": " + ec.message());
}

}  // namespace rollsim
