#include "io/RunWriter.h"

#include <sstream>

#include "io/AtomicFile.h"
#include "io/ConvergenceCsv.h"

namespace rollsim {

std::string measure_csv(const MeasureTable& table) {
  std::ostringstream out;
  out.precision(10);
  for (size_t c = 0; c < table.columns.size(); ++c) out << (c ? "," : "") << table.columns[c].name;
  out << '\n';
  for (const MeasureRow& row : table.rows) {
    for (size_t c = 0; c < row.size(); ++c) out << (c ? "," : "") << row[c];
    out << '\n';
  }
  return out.str();
}

namespace {
void write_process(const std::filesystem::path& dir, const ProcessResults& p, const ChartSink* charts) {
  for (const MeasureTable& t : p.tables) write_file_atomically(dir / (t.name + ".csv"), measure_csv(t));
  if (!charts) return;
  for (const ChartRequest& c : p.charts)
    if (const MeasureTable* t = p.table(c.table)) write_file_atomically(dir / c.file, charts->png(c, *t));
}
}  // namespace

void write_run(const std::filesystem::path& dir, const Model& model, const Results& results, const RunInfo& info,
               const OutputConfig& output, const RunSinks& sinks) {
  if (results.status.ok() && output.vtu && sinks.fields) {
    sinks.fields->write_result(dir / "result.vtu", model, results, output.fields);
    if (results.load_increments > 1 && output.all_increments)
      sinks.fields->write_increments(dir / "results.pvd", model, results, output.fields);
  }
  if (!results.newton.empty()) write_file_atomically(dir / "convergence.csv", convergence_csv(results));
  if (results.process) write_process(dir, *results.process, sinks.charts);
  write_file_atomically(dir / "summary.json", make_summary(model, results, info).dump(2) + "\n");
}

}  // namespace rollsim
