#pragma once
// Runs an analysis off the GUI thread along the batch command's path (project -> build_model -> make_solver ->
// run_linear_static). The core's AnalysisObserver calls arrive on the worker thread and leave it as Qt signals,
// which reach GUI-thread receivers queued. Cancel sets an atomic flag the core polls at its safe points.
#include <QObject>
#include <QString>
#include <QVector>
#include <atomic>
#include <memory>

#include "analysis/Results.h"
#include "base/Observer.h"
#include "model/Model.h"
#include "project/Project.h"

class QThread;

namespace rollsim::ui {

/// One iteration of the interface (projected) CG: of linear solve `solve` (numbered over the run), 1-based.
struct CgIteration {
  int solve = 0, iteration = 0;
  double residual = 0;  // ‖P r_k‖ / ‖P r_0‖
};

/// How a run ended, with what it produced.
struct RunOutcome {
  QString status;   // converged / not_converged / diverged / cancelled / error (base/RunStatus.h)
  QString message;  // what stopped the run when it did not converge; why its process ended it early when it did
  std::shared_ptr<const Model> model;
  // null on error or when cancelled before the first solve; after a cancel, the last iterate's fields
  // (Results::status)
  std::shared_ptr<const Results> results;
  long dofs = 0, cg_iterations = 0;
  int solves = 0;  // linear solves started
  double seconds = 0;
};

class AnalysisWorker : public QObject {
  Q_OBJECT

 public:
  explicit AnalysisWorker(QObject* parent = nullptr);
  /// Cancels a running analysis and waits for its thread.
  ~AnalysisWorker() override;

  /// Starts a run of a validated project on a new thread; false if a run is under way. `given`: the project as the
  /// user wrote it (the document), from which a schedule's passes are made — each pass run in turn, as `rollsim run`
  /// runs them (without it a schedule runs its first pass).
  bool start(const Project& project, const nlohmann::json& given = nullptr);
  /// Asks the run to stop at its next safe point (thread-safe; may be called from any thread).
  void cancel() { cancel_ = true; }
  bool cancel_requested() const { return cancel_; }
  bool running() const { return thread_ != nullptr; }

  static constexpr int kBatchMs = 50;

 signals:
  /// A stage starts: "build model", "assemble", "solve", "recover" (the core's names).
  void stageStarted(const QString& stage);
  /// Load increment `increment` of `count` starts / is complete (the linear analysis: 1 of 1).
  void incrementStarted(int increment, int count);
  void incrementFinished(int increment, int count);
  /// How far the run is as an increment starts, in its process's terms: "increment 3, travel 2 of 120 mm done" (the
  /// load factor without a process) — a total that does not grow with every cut-back, as the increments' count does.
  void howFar(const QString& text);
  /// Newton iteration of an increment, relative out-of-balance residual (from the nonlinear driver, once it exists).
  void newtonIteration(int increment, int iteration, double residual);
  /// Newton iteration `iteration` of `increment` refactors some groups and keeps the others' factors: `choices` says
  /// which and why, e.g. "roll kept (share 0.0031 ≤ 0.01); slab refactored (share 0.43 > 0.01)".
  void tangentsChosen(int increment, int iteration, const QString& choices);
  /// The attempt at `increment` failed for `cause`; it is retried with half the step (Newton driver).
  void cutBack(int increment, const QString& cause);
  /// (Projected) CG iterations, in order: the first of each solve at once, then batches at most every kBatchMs, the
  /// rest of a solve before its solveFinished — the solver thread does not wake the GUI thread at every iteration.
  void cgIterations(const QVector<rollsim::ui::CgIteration>& batch);
  /// Linear solve `solve` ended after `cgIterations` CG iterations (0 for direct strategies).
  void solveFinished(int solve, int cgIterations);
  /// A numeric factorization of `group` (body or `body/<id>` subdomain).
  void factorized(const QString& group);
  /// Frictionless contact: active-set iteration `iteration` changed `changed` statuses.
  void activeSetIteration(int iteration, int changed);
  /// A process measures each increment (AnalysisObserver::on_measures_begin): the columns of its rows and the chart
  /// that plots them.
  void measuresBegun(const rollsim::MeasureTable& columns, const rollsim::ChartRequest& chart);
  /// A process's row of an increment that is complete (AnalysisObserver::on_measured): a rolling pass's travel [mm],
  /// roll force and torque (2D: per unit width, N/mm and N·mm/mm).
  void measured(const QVector<double>& row);
  /// Fraction of the run done, in [0, 1].
  void progress(double fraction);
  /// The run ended (always emitted once per start, on the GUI thread, after the worker thread has ended).
  void finished(const rollsim::ui::RunOutcome& outcome);

 private:
  void thread_done();
  void run(const Project& project, const nlohmann::json& given);  // on the worker thread
  /// A schedule's passes one after the other (project/SchedulePasses); the outcome is the last pass's, with the
  /// schedule's table and chart first among its process's.
  void run_schedule(const Project& project, const nlohmann::json& given, AnalysisObserver& obs, RunOutcome& out);
  /// A run's results into the outcome: status, message, counts, and the fields when every body has them.
  static void take(std::shared_ptr<Results> results, RunOutcome& out);

  QThread* thread_ = nullptr;
  std::atomic<bool> cancel_{false};
  RunOutcome outcome_;
};

}  // namespace rollsim::ui

Q_DECLARE_METATYPE(rollsim::ui::RunOutcome)
Q_DECLARE_METATYPE(rollsim::ui::CgIteration)
Q_DECLARE_METATYPE(rollsim::MeasureTable)
Q_DECLARE_METATYPE(rollsim::ChartRequest)
