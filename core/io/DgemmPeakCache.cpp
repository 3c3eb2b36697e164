#include "io/DgemmPeakCache.h"

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "base/Blas.h"
#include "io/AtomicFile.h"

namespace rollsim {

namespace {
using nlohmann::json;

/// /proc/cpuinfo's first "model name" ("unknown CPU" where there is none).
std::string cpu_model_name() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      const size_t at = line.find_first_not_of(" \t", line.find(':') + 1);
      return at == std::string::npos ? "unknown CPU" : line.substr(at);
    }
  return "unknown CPU";
}

std::string cache_key(int threads, int n) {
  return cpu_model_name() + " | " + std::to_string(threads) + " threads | " + blas_description() + " | n " +
         std::to_string(n);
}

/// The cache's entries, or an empty object for a file that is missing, unreadable or not a JSON object of objects.
json read_cache(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return json::object();
  const json cache = json::parse(in, nullptr, false);
  return cache.is_object() ? cache : json::object();
}

bool read_entry(const json& cache, const std::string& key, DgemmPeak& peak) {
  const auto it = cache.find(key);
  if (it == cache.end() || !it->is_object()) return false;
  const auto g = it->find("gflops"), n = it->find("n"), calls = it->find("calls");
  if (g == it->end() || n == it->end() || calls == it->end() || !g->is_number() || !n->is_number_integer() ||
      !calls->is_number_integer() || !(g->get<double>() > 0))
    return false;
  peak = {g->get<double>(), 0.0, n->get<int>(), calls->get<int>()};
  return true;
}
}  // namespace

std::filesystem::path default_cache_dir() {
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::filesystem::path(x) / "rollsim";
  if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".cache" / "rollsim";
  return {};
}

std::filesystem::path dgemm_peak_cache_file(const std::filesystem::path& dir) { return dir / "dgemm-peak.json"; }

DgemmPeak cached_dgemm_peak(int threads, int n, const std::filesystem::path& dir) {
  if (dir.empty()) return measure_dgemm_peak(threads, n);
  const std::filesystem::path file = dgemm_peak_cache_file(dir);
  json cache = read_cache(file);
  const std::string key = cache_key(threads, n);
  DgemmPeak peak;
  if (read_entry(cache, key, peak)) return peak;
  peak = measure_dgemm_peak(threads, n);
  cache[key] = {{"gflops", peak.gflops}, {"n", peak.n}, {"calls", peak.calls}};
  try {  // kept when it can be: a cache is a convenience, never a reason to fail a run
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    write_file_atomically(file, cache.dump(2) + "\n");
  } catch (const WriteError&) {
  }
  return peak;
}

}  // namespace rollsim
