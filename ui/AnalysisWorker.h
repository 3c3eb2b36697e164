#pragma once
// Runs an analysis off the GUI thread along the batch command's path (project -> build_model -> make_solver ->
// run_linear_static). The core's AnalysisObserver calls arrive on the worker thread and leave it as Qt signals,
// which reach GUI-thread receivers queued. Cancel sets an atomic flag the core polls at its safe points.
#include <QObject>
#include <QString>
#include <atomic>
#include <memory>

#include "analysis/Results.h"
#include "model/Model.h"
#include "project/Project.h"

class QThread;

namespace rollsim::ui {

/// How a run ended, with what it produced.
struct RunOutcome {
  QString status;  // converged / diverged / cancelled / error
  QString error;   // the message when status is "error"
  std::shared_ptr<const Model> model;
  std::shared_ptr<const Results> results;  // null when cancelled before the analysis or on error
  long dofs = 0, cg_iterations = 0;
  double seconds = 0;
};

class AnalysisWorker : public QObject {
  Q_OBJECT

 public:
  explicit AnalysisWorker(QObject* parent = nullptr);
  /// Cancels a running analysis and waits for its thread.
  ~AnalysisWorker() override;

  /// Starts a run of a validated project on a new thread; false if a run is under way.
  bool start(const Project& project);
  /// Asks the run to stop at its next safe point (thread-safe; may be called from any thread).
  void cancel() { cancel_ = true; }
  bool cancel_requested() const { return cancel_; }
  bool running() const { return thread_ != nullptr; }

 signals:
  /// A stage starts: "build model", "assemble", "solve", "recover" (the core's names).
  void stageStarted(const QString& stage);
  /// One iteration of an iterative process ("cg", "newton", "active_set"), `residual` relative.
  void iteration(const QString& kind, int iteration, double residual);
  /// Fraction of the run done, in [0, 1].
  void progress(double fraction);
  /// The run ended (always emitted once per start, on the GUI thread, after the worker thread has ended).
  void finished(const rollsim::ui::RunOutcome& outcome);

 private:
  void thread_done();
  void run(const Project& project);  // on the worker thread

  QThread* thread_ = nullptr;
  std::atomic<bool> cancel_{false};
  RunOutcome outcome_;
};

}  // namespace rollsim::ui

Q_DECLARE_METATYPE(rollsim::ui::RunOutcome)
