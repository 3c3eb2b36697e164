#pragma once
// Everything a run writes, in one place and one order: result.vtu and results.pvd (through the injected FieldWriter:
// core has no VTK) — of a run that did not converge, last_converged.vtu and results.pvd of the increments it
// completed —, convergence.csv of a Newton run, each table of its process as <name>.csv and each chart as PNG
// (through the injected ChartSink), and summary.json last — so a summary on disk means the rest is there. The
// tables, charts and units are the process's registries (base/Measures.h): nothing here knows a process.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "analysis/Results.h"
#include "io/ChartSink.h"
#include "io/OutputConfig.h"
#include "io/Summary.h"
#include "model/Model.h"

namespace rollsim {

/// Writes the result fields: the front end's adapter (vtkio's VtkFieldWriter).
class FieldWriter {
 public:
  virtual ~FieldWriter() = default;
  /// The final fields as one file (result.vtu), only the arrays `fields` selects (empty: every one).
  virtual void write_result(const std::filesystem::path& file, const Model& model, const Results& results,
                            const std::vector<std::string>& fields) const = 0;
  /// One increment's fields (Results::increments[increment]) as one file: a failed run's last converged state.
  virtual void write_state(const std::filesystem::path& file, const Model& model, const Results& results,
                           size_t increment, const std::vector<std::string>& fields) const = 0;
  /// Every increment's fields as a collection (results.pvd and its files beside it); when `stop` turns true, the
  /// collection of the increments written so far. Returns how many it holds.
  virtual size_t write_increments(const std::filesystem::path& file, const Model& model, const Results& results,
                                  const std::vector<std::string>& fields, const std::function<bool()>& stop) const = 0;
};

/// What a run that did not converge writes of its last converged increment (beside results.pvd of the increments it
/// completed), so that the state before the failure — the element about to fold that the message names — can be seen.
inline constexpr const char* kLastConverged = "last_converged.vtu";

/// What the front end provides for the files core cannot draw or encode itself.
struct RunSinks {
  const FieldWriter* fields = nullptr;  // null: no VTU written
  const ChartSink* charts = nullptr;    // null: no PNG written
  std::function<bool()> stop = {};      // asked before each file: true ends the writing (Ctrl-C), empty: never
};

/// <name>.csv of a table: its column names, then its rows (10 significant digits).
std::string measure_csv(const MeasureTable& table);

/// Writes the run's files into `dir` (which exists and holds no earlier run's: io/RunFolder), each atomically, and
/// returns how the run ended as written: the analysis's status, or `cancelled` when `sinks.stop` ended the writing
/// (the files written so far are complete and summary.json names what is missing), or `error` when a file could
/// not be written (summary.json names it and the OS reason). Throws WriteError only when summary.json itself cannot
/// be written.
RunStatus write_run(const std::filesystem::path& dir, const Model& model, const Results& results, const RunInfo& info,
                    const OutputConfig& output, const RunSinks& sinks);

}  // namespace rollsim
