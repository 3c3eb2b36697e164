#include "AnalysisWorker.h"

#include <QThread>
#include <chrono>

#include "analysis/LinearStatic.h"
#include "process/rolling/RollingSchedule.h"
#include "project/ModelBuilder.h"
#include "project/RunProject.h"
#include "project/SchedulePasses.h"

namespace rollsim::ui {

namespace {

/// Progress by stage; the increments (the core's on_progress) fill the band of the "solve" stage.
double stage_fraction(const std::string& stage) {
  if (stage == "build model") return 0.02;
  if (stage == "assemble") return 0.05;
  if (stage == "solve") return 0.2;
  if (stage == "recover") return 0.9;
  return -1;
}
constexpr double kIncrementsBegin = 0.2, kIncrementsEnd = 0.9;

/// The observer on the worker thread: every call becomes a signal of the worker (queued to GUI-thread receivers).
/// CG iterations travel in batches (AnalysisWorker::cgIterations): a queued signal per iteration would wake the GUI
/// thread at solver speed. Whatever is pending goes out before any other signal, so the order is kept.
class ForwardingObserver final : public AnalysisObserver {
 public:
  ForwardingObserver(AnalysisWorker& worker, RunConfig config) : w_(worker), config_(std::move(config)) {}
  void on_stage(const std::string& stage) override {
    flush();
    emit w_.stageStarted(QString::fromStdString(stage));
    advance(stage_fraction(stage));
  }
  void on_increment_begin(int increment, int count) override {
    flush();
    emit w_.incrementStarted(increment, count);
    emit w_.howFar(QString::fromStdString("increment " + std::to_string(increment) + ", " +
                                          progress_text(config_, load_done_) + " done"));
  }
  void on_increment_end(int increment, int count) override {
    flush();
    emit w_.incrementFinished(increment, count);
  }
  void on_newton_iteration(int increment, int iteration, double residual) override {
    flush();
    emit w_.newtonIteration(increment, iteration, residual);
  }
  void on_tangents(int increment, int iteration, const std::vector<TangentChoice>& choices) override {
    emit w_.tangentsChosen(increment, iteration, QString::fromStdString(describe(choices)));
  }
  void on_cg_iteration(int solve, int iteration, double residual) override {
    pending_.append({solve, iteration, residual});
    // the first iteration of a solve at once (the plot starts moving), then at most every kBatch
    if (iteration == 1 || Clock::now() - last_batch_ >= kBatch) flush();
  }
  void on_solve_end(int solve, int cg_iterations) override {
    flush();
    emit w_.solveFinished(solve, cg_iterations);
  }
  void on_factorization(const std::string& group) override {
    flush();
    emit w_.factorized(QString::fromStdString(group));
  }
  void on_active_set_iteration(int iteration, int changed) override {
    flush();
    emit w_.activeSetIteration(iteration, changed);
  }
  void on_cutback(int increment, const std::string& cause) override {
    flush();
    emit w_.cutBack(increment, QString::fromStdString(cause));
  }
  void on_measures_begin(const MeasureTable& columns, const ChartRequest& chart) override {
    flush();
    emit w_.measuresBegun(columns, chart);
  }
  void on_measured(int /*increment*/, const MeasureRow& row) override {
    flush();
    emit w_.measured(QVector<double>(row.begin(), row.end()));
  }
  void on_progress(double fraction) override {
    flush();
    load_done_ = fraction;
    advance(kIncrementsBegin + (kIncrementsEnd - kIncrementsBegin) * fraction);
  }
  bool cancel_requested() const override { return w_.cancel_requested(); }
  /// The run ended (whatever way): sends what is pending; `converged` fills the progress bar.
  void done(bool converged) {
    flush();
    if (converged) advance(1.0);
  }

 private:
  using Clock = std::chrono::steady_clock;
  static constexpr auto kBatch = std::chrono::milliseconds(AnalysisWorker::kBatchMs);

  void flush() {
    if (pending_.isEmpty()) return;
    emit w_.cgIterations(pending_);
    pending_.clear();
    last_batch_ = Clock::now();
  }
  void advance(double fraction) {  // the bar never moves back
    if (fraction > done_) emit w_.progress(done_ = fraction);
  }
  AnalysisWorker& w_;
  const RunConfig config_;  // the process's terms of progress ("travel 12 of 120 mm")
  double load_done_ = 0;    // the load factor of the last completed increment
  QVector<CgIteration> pending_;
  Clock::time_point last_batch_ = Clock::now();
  double done_ = 0;
};

}  // namespace

AnalysisWorker::AnalysisWorker(QObject* parent) : QObject(parent) {
  qRegisterMetaType<RunOutcome>();
  qRegisterMetaType<QVector<CgIteration>>();
  qRegisterMetaType<MeasureTable>();
  qRegisterMetaType<ChartRequest>();
}

AnalysisWorker::~AnalysisWorker() {
  if (thread_) {
    cancel_ = true;
    thread_->wait();
    delete thread_;
  }
}

bool AnalysisWorker::start(const Project& project, const nlohmann::json& given) {
  if (thread_) return false;
  cancel_ = false;
  outcome_ = RunOutcome{};
  thread_ = QThread::create([this, project, given] { run(project, given); });
  connect(thread_, &QThread::finished, this, &AnalysisWorker::thread_done, Qt::QueuedConnection);
  thread_->start();
  return true;
}

void AnalysisWorker::thread_done() {
  if (!thread_) return;
  thread_->wait();
  delete thread_;
  thread_ = nullptr;
  emit finished(outcome_);
}

void AnalysisWorker::run(const Project& project, const nlohmann::json& given) {
  const auto start = std::chrono::steady_clock::now();
  RunOutcome out;
  ForwardingObserver obs(*this, project.config());
  try {
    if (is_schedule(project.data) && !given.is_null()) {
      run_schedule(project, given, obs, out);
    } else {
      obs.on_stage("build model");
      auto model = std::make_shared<const Model>(build_model(project));
      out.model = model;
      if (obs.cancel_requested())
        out.status = QStringLiteral("cancelled");
      else
        take(std::make_shared<Results>(run_project(project, *model, &obs)), out);
      if (is_schedule(project.data))  // run without the document: say which pass it was
        out.message = QStringLiteral(
                          "a schedule: the window ran its first pass (without the document to make the "
                          "others from); `rollsim run` runs them all. ") +
                      out.message;
    }
  } catch (const std::exception& e) {  // AnalysisError, ProjectError, std::invalid_argument: said to the user
    out.status = QStringLiteral("error");
    out.message = QString::fromUtf8(e.what());
  }
  obs.done(out.status == QLatin1String("converged"));
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome_ = std::move(out);  // read on the GUI thread after the thread has finished
}

void AnalysisWorker::take(std::shared_ptr<Results> results, RunOutcome& out) {
  out.status = QString::fromUtf8(to_string(results->status.status));
  // a run that did not converge says what stopped it; one the process ended early says why (Results::status)
  out.message = QString::fromStdString(results->status.message);
  out.dofs = results->dofs;
  out.cg_iterations += results->solver.cg_iterations;
  out.solves += results->solver.solves;
  if (results->bodies.size() == out.model->bodies.size()) out.results = std::move(results);
}

void AnalysisWorker::run_schedule(const Project& project, const nlohmann::json& given, AnalysisObserver& obs,
                                  RunOutcome& out) {
  ScheduleRun schedule(project.data, given);
  for (size_t k = 0; k < schedule.passes(); ++k) {
    obs.on_stage("pass " + std::to_string(k + 1) + " of " + std::to_string(schedule.passes()) + ": build model");
    const PassSetup pass = set_up_pass(schedule, k, project);
    out.model = std::make_shared<const Model>(pass.model);
    if (obs.cancel_requested()) {
      out.status = QStringLiteral("cancelled");
      return;
    }
    take(std::make_shared<Results>(run_project(pass.project, *out.model, &obs)), out);
    if (!out.results || out.results->status.status != Status::converged) {
      out.message = QStringLiteral("pass %1 of %2: ").arg(k + 1).arg(schedule.passes()) + out.message;
      return;
    }
    schedule.finish(k, *out.model, *out.results);
  }
  // the window shows the last pass's fields and, first among its charts, the schedule's
  auto last = std::make_shared<Results>(*out.results);
  if (!last->process) return;
  last->process->tables.insert(last->process->tables.begin(), schedule.table());
  last->process->charts.insert(last->process->charts.begin(), schedule.chart());
  out.results = last;
  out.message = QStringLiteral("schedule of %1 passes; the view shows the last pass").arg(schedule.passes());
}

}  // namespace rollsim::ui
