#pragma once
// The output folder of `rollsim run` holds one run: when a run takes the folder (io/RunFolder, before its analysis),
// every file an earlier run wrote there (summary.json, result.vtu, last_converged.vtu, results.pvd and its
// results_NNNN.vtu, convergence.csv, the files a process writes —
// named by the caller, from the process registry — and the hidden temporaries of an interrupted write) is removed,
// so a failed run never leaves an older result beside its own summary. Other files are kept.
#include <filesystem>
#include <string>
#include <vector>

namespace rollsim {

/// True for the names a run writes (above, `others` among them), results_<digits>.vtu and the temporaries of
/// write_file_atomically for any of those.
bool is_run_output(const std::filesystem::path& name, const std::vector<std::string>& others = {});

/// Removes the run outputs (is_run_output) directly inside `dir`; throws std::runtime_error naming a file that
/// cannot be removed.
void clear_run_outputs(const std::filesystem::path& dir, const std::vector<std::string>& others = {});

}  // namespace rollsim
