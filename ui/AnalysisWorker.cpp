#include "AnalysisWorker.h"

#include <QThread>
#include <chrono>

#include "analysis/LinearStatic.h"
#include "project/ModelBuilder.h"
#include "solve/Blas.h"
#include "solve/SolverStrategy.h"

namespace rollsim::ui {

namespace {

/// Progress by stage while the core reports none itself (its on_progress, once it exists, is forwarded too).
double stage_fraction(const std::string& stage) {
  if (stage == "build model") return 0.02;
  if (stage == "assemble") return 0.05;
  if (stage == "solve") return 0.2;
  if (stage == "recover") return 0.9;
  return -1;
}

/// The observer on the worker thread: every call becomes a signal of the worker.
class ForwardingObserver final : public AnalysisObserver {
 public:
  explicit ForwardingObserver(AnalysisWorker& worker) : w_(worker) {}
  void on_stage(const std::string& stage) override {
    emit w_.stageStarted(QString::fromStdString(stage));
    const double f = stage_fraction(stage);
    if (f > done_) emit w_.progress(done_ = f);
  }
  void on_iteration(const std::string& kind, int iteration, double residual) override {
    emit w_.iteration(QString::fromStdString(kind), iteration, residual);
  }
  void on_progress(double fraction) override {
    if (fraction > done_) emit w_.progress(done_ = fraction);
  }
  bool cancel_requested() const override { return w_.cancel_requested(); }

 private:
  AnalysisWorker& w_;
  double done_ = 0;
};

/// The solver section's options (fields the schema does not have yet keep SolverOptions' defaults).
SolverOptions solver_options(const json& s) {
  SolverOptions o;
  o.cg_tolerance = s.value("cg_tolerance", o.cg_tolerance);
  o.threads = s.value("threads", o.threads);
  o.preconditioner = s.value("preconditioner", o.preconditioner);
  o.multipliers = s.value("multipliers", o.multipliers);
  return o;
}

}  // namespace

AnalysisWorker::AnalysisWorker(QObject* parent) : QObject(parent) { qRegisterMetaType<RunOutcome>(); }

AnalysisWorker::~AnalysisWorker() {
  if (thread_) {
    cancel_ = true;
    thread_->wait();
    delete thread_;
  }
}

bool AnalysisWorker::start(const Project& project) {
  if (thread_) return false;
  cancel_ = false;
  outcome_ = RunOutcome{};
  thread_ = QThread::create([this, project] { run(project); });
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

void AnalysisWorker::run(const Project& project) {
  const auto start = std::chrono::steady_clock::now();
  ForwardingObserver obs(*this);
  RunOutcome out;
  try {
    obs.on_stage("build model");
    auto model = std::make_shared<const Model>(build_model(project));
    out.model = model;
    const json& s = project.data.at("solver");
    const SolverOptions options = solver_options(s);
    set_blas_threads(options.threads);
    auto solver = make_solver(s.at("mode").get<std::string>(), options);
    if (obs.cancel_requested()) {
      out.status = QStringLiteral("cancelled");
    } else {
      auto results = std::make_shared<Results>(run_linear_static(*model, *solver, &obs));
      out.status = QString::fromStdString(results->status);
      out.dofs = results->dofs;
      out.cg_iterations = solver->stats().cg_iterations;
      if (results->bodies.size() == model->bodies.size()) out.results = std::move(results);
    }
  } catch (const std::exception& e) {  // AnalysisError, ProjectError, std::invalid_argument: said to the user
    out.status = QStringLiteral("error");
    out.error = QString::fromUtf8(e.what());
  }
  if (out.status == QLatin1String("converged")) obs.on_progress(1.0);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome_ = std::move(out);  // read on the GUI thread after the thread has finished
}

}  // namespace rollsim::ui
