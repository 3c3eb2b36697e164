#pragma once
// Everything a run writes, in one place and one order: result.vtu and results.pvd (through the injected FieldWriter:
// core has no VTK), convergence.csv of a Newton run, each table of its process as <name>.csv and each chart as PNG
// (through the injected ChartSink), and summary.json last — so a summary on disk means the rest is there. The
// tables, charts and units are the process's registries (base/Measures.h): nothing here knows a process.
#include <filesystem>
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
  /// Every increment's fields as a collection (results.pvd and its files beside it).
  virtual void write_increments(const std::filesystem::path& file, const Model& model, const Results& results,
                                const std::vector<std::string>& fields) const = 0;
};

/// What the front end provides for the files core cannot draw or encode itself.
struct RunSinks {
  const FieldWriter* fields = nullptr;  // null: no VTU written
  const ChartSink* charts = nullptr;    // null: no PNG written
};

/// <name>.csv of a table: its column names, then its rows (10 significant digits).
std::string measure_csv(const MeasureTable& table);

/// Writes the run's files into `dir` (which exists and holds no earlier run's: OutputFolder), each atomically;
/// throws std::runtime_error naming the file that could not be written.
void write_run(const std::filesystem::path& dir, const Model& model, const Results& results, const RunInfo& info,
               const OutputConfig& output, const RunSinks& sinks);

}  // namespace rollsim
