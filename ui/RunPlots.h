#pragma once
// The live plots of a run, side by side: residual history (log scale, per kind), CG iterations per solve,
// factorizations per group. Worker signals (CG iterations in batches) are recorded in a RunSeries at once and the
// charts redraw from it at most every 100 ms, so that plotting costs the solver next to nothing
// (docs/BENCHMARKS-GUI.md).
#include <QTimer>
#include <QWidget>

#include "RunSeries.h"

namespace rollsim::ui {

class AnalysisWorker;
struct CgIteration;
class FactorizationPlot;
class ResidualPlot;
class ProcessPlot;
struct RunOutcome;
class SolvePlot;

class RunPlots : public QWidget {
  Q_OBJECT

 public:
  explicit RunPlots(QWidget* parent = nullptr);

  /// Records the run reports of `worker` (queued connections: the worker's signals come from its thread).
  void watch(const AnalysisWorker* worker);
  /// Forgets the last run (a new run starts).
  void clear();
  /// Redraws the charts now from what was recorded (the timer does it at most every kRefreshMs).
  void flush();
  /// Every recorded series as CSV (RunSeries::csv).
  QString csv() const { return series_.csv(); }

  const RunSeries& series() const { return series_; }
  ResidualPlot* residual_plot() const { return residuals_; }
  SolvePlot* solve_plot() const { return solves_; }
  FactorizationPlot* factorization_plot() const { return factorizations_; }
  ProcessPlot* process_plot() const { return process_; }

  static constexpr int kRefreshMs = 100;

 public slots:
  void begin_increment(int increment, int count);
  void add_cg_iteration(int solve, int iteration, double residual);
  void add_cg_iterations(const QVector<rollsim::ui::CgIteration>& batch);
  void add_newton_iteration(int increment, int iteration, double residual);
  void end_solve(int solve, int cg_iterations);
  void add_factorization(const QString& group);
  /// A run ended: a process's plot takes its final charts (a rolling pass: its history and the arc).
  void end_run(const rollsim::ui::RunOutcome& outcome);

 private:
  void schedule();

  RunSeries series_;
  ResidualPlot* residuals_;
  SolvePlot* solves_;
  FactorizationPlot* factorizations_;
  ProcessPlot* process_;
  QTimer timer_;
};

}  // namespace rollsim::ui
