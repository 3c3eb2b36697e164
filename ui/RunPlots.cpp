#include "RunPlots.h"

#include <QHBoxLayout>
#include <QSplitter>

#include "AnalysisWorker.h"
#include "FactorizationPlot.h"
#include "ProcessPlot.h"
#include "ResidualPlot.h"
#include "SolvePlot.h"

namespace rollsim::ui {

RunPlots::RunPlots(QWidget* parent)
    : QWidget(parent),
      residuals_(new ResidualPlot),
      solves_(new SolvePlot),
      factorizations_(new FactorizationPlot),
      process_(new ProcessPlot) {
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(residuals_);
  split->addWidget(solves_);
  split->addWidget(factorizations_);
  split->addWidget(process_);
  split->setStretchFactor(0, 3);
  split->setStretchFactor(1, 1);
  split->setStretchFactor(2, 1);
  split->setStretchFactor(3, 4);
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(split);
  timer_.setInterval(kRefreshMs);
  timer_.setSingleShot(true);
  connect(&timer_, &QTimer::timeout, this, &RunPlots::flush);
}

void RunPlots::watch(const AnalysisWorker* worker) {
  connect(worker, &AnalysisWorker::incrementStarted, this, &RunPlots::begin_increment);
  connect(worker, &AnalysisWorker::cgIterations, this, &RunPlots::add_cg_iterations);
  connect(worker, &AnalysisWorker::newtonIteration, this, &RunPlots::add_newton_iteration);
  connect(worker, &AnalysisWorker::solveFinished, this, &RunPlots::end_solve);
  connect(worker, &AnalysisWorker::factorized, this, &RunPlots::add_factorization);
  connect(worker, &AnalysisWorker::measuresBegun, process_, &ProcessPlot::begin);
  connect(worker, &AnalysisWorker::measured, process_, &ProcessPlot::add_row);
  connect(worker, &AnalysisWorker::finished, this, &RunPlots::end_run);
}

void RunPlots::end_run(const RunOutcome& outcome) {
  if (outcome.results && outcome.results->process) process_->set_results(*outcome.results->process);
}

void RunPlots::clear() {
  timer_.stop();
  process_->clear();
  series_.clear();
  residuals_->clear();
  solves_->clear();
  factorizations_->clear();
}

void RunPlots::flush() {
  timer_.stop();
  residuals_->refresh(series_);
  solves_->refresh(series_);
  factorizations_->refresh(series_);
}

void RunPlots::schedule() {
  if (!timer_.isActive()) timer_.start();
}

void RunPlots::begin_increment(int increment, int /*count*/) { series_.begin_increment(increment); }

void RunPlots::add_cg_iteration(int solve, int iteration, double residual) {
  series_.add_cg_iteration(solve, iteration, residual);
  schedule();
}

void RunPlots::add_cg_iterations(const QVector<CgIteration>& batch) {
  for (const CgIteration& c : batch) series_.add_cg_iteration(c.solve, c.iteration, c.residual);
  schedule();
}

void RunPlots::add_newton_iteration(int increment, int iteration, double residual) {
  series_.add_newton_iteration(increment, iteration, residual);
  schedule();
}

void RunPlots::end_solve(int solve, int cg_iterations) {
  series_.end_solve(solve, cg_iterations);
  schedule();
}

void RunPlots::add_factorization(const QString& group) {
  series_.add_factorization(group);
  schedule();
}

}  // namespace rollsim::ui
