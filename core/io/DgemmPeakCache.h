#pragma once
// The DGEMM peak (base/DgemmPeak, the yardstick of a run's factor_gflops) measured once per machine and kept in a
// small JSON file, so a run does not spend ~10–30 ms probing it again: keyed by the CPU's model name, the BLAS
// thread count, the loaded BLAS and the order of the probe. A cache that is missing, unreadable, corrupt or cannot
// be written is measured around: the probe runs, and its result is kept only when the file can be written (whole:
// io/AtomicFile). `rollsim bench` measures afresh.
#include <filesystem>
#include <string>

#include "base/DgemmPeak.h"

namespace rollsim {

/// $XDG_CACHE_HOME/rollsim, else $HOME/.cache/rollsim; empty when neither is set.
std::filesystem::path default_cache_dir();

/// The cache file in `dir`.
std::filesystem::path dgemm_peak_cache_file(const std::filesystem::path& dir);

/// measure_dgemm_peak(threads, n) from the cache in `dir` (its `seconds` then 0: nothing was probed), or measured and
/// added to it. An empty `dir`: measured.
DgemmPeak cached_dgemm_peak(int threads, int n, const std::filesystem::path& dir);

}  // namespace rollsim
