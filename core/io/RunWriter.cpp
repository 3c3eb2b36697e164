#include "io/RunWriter.h"

#include <sstream>

#include "io/AtomicFile.h"
#include "io/ConvergenceCsv.h"
#include "io/RunFolder.h"

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
/// Whether a run that stopped short of convergence (not_converged, diverged, cancelled, or an error met after
/// completed increments, short of the whole load) completed an increment whose fields it kept.
bool has_converged_state(const Model& model, const Results& results) {
  const Status s = results.status.status;  // an `error` at the whole load: its fields are not a state (not finite)
  if (results.status.ok() || s == Status::no_bite) return false;
  if (results.increments.empty() || results.increments.back().bodies.size() != model.bodies.size()) return false;
  if (s == Status::error && results.increments.back().load_factor >= 1.0) return false;
  for (const BodyResults& b : results.increments.back().bodies)  // a state of 1e308 loads overflows: no NaN written
    if (!b.displacement.allFinite()) return false;
  return true;
}

/// One file (or the collection) of the run, written when its turn comes.
struct PendingFile {
  std::string name;
  std::function<void()> write;
};

std::vector<PendingFile> files_of(const std::filesystem::path& dir, const Model& model, const Results& results,
                                  const OutputConfig& output, const RunSinks& sinks, size_t& increments_written) {
  std::vector<PendingFile> files;
  const bool converged = results.status.ok();
  if (output.vtu && sinks.fields && (converged || has_converged_state(model, results))) {
    if (converged)
      files.push_back(
          {"result.vtu", [&, dir] { sinks.fields->write_result(dir / "result.vtu", model, results, output.fields); }});
    else
      files.push_back({kLastConverged, [&, dir] {
                         sinks.fields->write_state(dir / kLastConverged, model, results, results.increments.size() - 1,
                                                   output.fields);
                       }});
    const bool several = converged ? results.load_increments > 1 : results.increments.size() > 1;
    if (several && output.all_increments)
      files.push_back({"results.pvd", [&, dir] {
                         increments_written = sinks.fields->write_increments(dir / "results.pvd", model, results,
                                                                             output.fields, sinks.stop);
                       }});
  }
  if (!results.newton.empty())
    files.push_back(
        {"convergence.csv", [&, dir] { write_file_atomically(dir / "convergence.csv", convergence_csv(results)); }});
  if (const ProcessResults* p = results.process ? &*results.process : nullptr) {
    for (const MeasureTable& t : p->tables)
      files.push_back({t.name + ".csv", [&t, dir] { write_file_atomically(dir / (t.name + ".csv"), measure_csv(t)); }});
    for (const ChartRequest& c : p->charts)
      if (const MeasureTable* t = p->table(c.table); t && sinks.charts)
        files.push_back(
            {c.file, [&c, t, &sinks, dir] { write_file_atomically(dir / c.file, sinks.charts->png(c, *t)); }});
  }
  return files;
}

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text.empty() ? "none" : text;
}
}  // namespace

RunStatus write_run(const std::filesystem::path& dir, const Model& model, const Results& results, const RunInfo& info,
                    const OutputConfig& output, const RunSinks& sinks) {
  size_t increments_written = 0;
  std::vector<PendingFile> files = files_of(dir, model, results, output, sinks, increments_written);
  RunStatus ended = results.status;
  std::vector<std::string> written;
  for (size_t i = 0; i < files.size(); ++i) {
    if (sinks.stop && sinks.stop()) {
      std::vector<std::string> missing;
      for (size_t j = i; j < files.size(); ++j) missing.push_back(files[j].name);
      ended = {Status::cancelled, Reason::none,
               "stopped by a signal while the results were written (the analysis had ended " +
                   std::string(to_string(results.status.status)) + "): written " + joined(written) + "; not written " +
                   joined(missing)};
      break;
    }
    try {
      files[i].write();
    } catch (const WriteError& e) {
      ended = {Status::error, Reason::none, std::string(e.what()) + " (written before it: " + joined(written) + ")"};
      break;
    }
    written.push_back(files[i].name);
    if (files[i].name == "results.pvd" && increments_written < results.increments.size())
      written.back() += " (" + std::to_string(increments_written) + " of " + std::to_string(results.increments.size()) +
                        " increments)";
  }
  nlohmann::json summary = make_summary(model, results, info);
  if (ended.status != results.status.status) {
    summary["status"] = to_string(ended.status);
    summary["message"] = ended.message;
    if (!results.status.message.empty()) summary["analysis_message"] = results.status.message;
  }
  if (summary.contains("run")) summary["run"]["finished"] = utc_now();
  write_file_atomically(dir / "summary.json", summary.dump(2) + "\n");
  return ended;
}

}  // namespace rollsim
