// Runs in the worker thread: stage, progress and residual signals arrive queued on the GUI thread, the run finishes
// converged, and a cancel mid-run ends it "cancelled" with the worker ready for the next run.
#include <QSignalSpy>
#include <QThread>
#include <QtTest>

#include "AnalysisWorker.h"
#include "ProjectDocument.h"

using namespace rollsim;
using namespace rollsim::ui;

namespace {
Project sample(const char* name) { return load_project(std::string(ROLLSIM_SOURCE_DIR "/samples/") + name); }

QStringList strings(const QSignalSpy& spy) {
  QStringList out;
  for (const auto& args : spy) out << args.at(0).toString();
  return out;
}
}  // namespace

class TestAnalysisWorker : public QObject {
  Q_OBJECT

 private slots:
  void run_delivers_stages_progress_and_converges() {
    AnalysisWorker worker;
    QSignalSpy stages(&worker, &AnalysisWorker::stageStarted);
    QSignalSpy progress(&worker, &AnalysisWorker::progress);
    QSignalSpy finished(&worker, &AnalysisWorker::finished);
    QThread* gui = QThread::currentThread();
    bool off_thread = false;
    connect(
        &worker, &AnalysisWorker::stageStarted, this,
        [&off_thread, gui] { off_thread = QThread::currentThread() != gui; }, Qt::DirectConnection);
    QVERIFY(worker.start(sample("plate-hole-2d.json")));
    QVERIFY(worker.running());
    QVERIFY(!worker.start(sample("plate-hole-2d.json")));  // one run at a time
    QVERIFY(finished.wait(60000));
    QVERIFY(off_thread);  // the core ran on the worker thread
    QVERIFY(!worker.running());
    const auto outcome = finished.at(0).at(0).value<RunOutcome>();
    QCOMPARE(outcome.status, QStringLiteral("converged"));
    QVERIFY(outcome.results);
    QVERIFY(outcome.model);
    QCOMPARE(outcome.results->bodies.size(), outcome.model->bodies.size());
    QVERIFY(outcome.dofs > 0);
    const QStringList s = strings(stages);
    QCOMPARE(s, (QStringList{"build model", "assemble", "solve", "recover"}));
    QVERIFY(progress.count() >= 4);
    QCOMPARE(progress.last().at(0).toDouble(), 1.0);
    double last = 0;
    for (const auto& p : progress) {
      QVERIFY(p.at(0).toDouble() >= last);
      last = p.at(0).toDouble();
    }
  }

  void iterative_solver_reports_residuals() {
    AnalysisWorker worker;
    QSignalSpy iterations(&worker, &AnalysisWorker::iteration);
    QSignalSpy finished(&worker, &AnalysisWorker::finished);
    Project p = sample("block-push-2d-50x30.json");  // floating block: projected CG in `mixed`
    p.data["solver"]["mode"] = "mixed";
    QVERIFY(worker.start(p));
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(0).at(0).value<RunOutcome>().status, QStringLiteral("converged"));
    QVERIFY(iterations.count() > 0);
    QCOMPARE(iterations.at(0).at(0).toString(), QStringLiteral("cg"));
    QVERIFY(finished.at(0).at(0).value<RunOutcome>().cg_iterations > 0);
  }

  void cancel_mid_run_leaves_a_consistent_state() {
    AnalysisWorker worker;
    QSignalSpy finished(&worker, &AnalysisWorker::finished);
    // cancel as soon as the analysis starts assembling (a direct connection runs on the worker thread, so the core
    // sees the flag at its next safe point, before the solve)
    connect(
        &worker, &AnalysisWorker::stageStarted, this,
        [&worker](const QString& stage) {
          if (stage == QLatin1String("assemble")) worker.cancel();
        },
        Qt::DirectConnection);
    QVERIFY(worker.start(sample("plate-hole-2d.json")));
    QVERIFY(finished.wait(60000));
    const auto outcome = finished.at(0).at(0).value<RunOutcome>();
    QCOMPARE(outcome.status, QStringLiteral("cancelled"));
    QVERIFY(!outcome.results);  // no partial fields pretend to be a solution
    QVERIFY(outcome.model);
    QVERIFY(!worker.running());
    disconnect(&worker, &AnalysisWorker::stageStarted, this, nullptr);
    // the worker runs again after a cancel
    QVERIFY(worker.start(sample("plate-hole-2d.json")));
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(1).at(0).value<RunOutcome>().status, QStringLiteral("converged"));
  }

  void cancel_before_the_analysis() {
    AnalysisWorker worker;
    QSignalSpy finished(&worker, &AnalysisWorker::finished);
    connect(
        &worker, &AnalysisWorker::stageStarted, this,
        [&worker](const QString& stage) {
          if (stage == QLatin1String("build model")) worker.cancel();
        },
        Qt::DirectConnection);
    QVERIFY(worker.start(sample("plate-hole-2d.json")));
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(0).at(0).value<RunOutcome>().status, QStringLiteral("cancelled"));
  }

  void analysis_error_is_reported() {
    AnalysisWorker worker;
    QSignalSpy finished(&worker, &AnalysisWorker::finished);
    Project p = sample("plate-hole-2d.json");
    p.data["boundary_conditions"] = json::array();  // nothing holds the plate: singular
    QVERIFY(worker.start(p));
    QVERIFY(finished.wait(60000));
    const auto outcome = finished.at(0).at(0).value<RunOutcome>();
    QCOMPARE(outcome.status, QStringLiteral("error"));
    QVERIFY(!outcome.error.isEmpty());
  }

  void destroying_a_running_worker_cancels_and_joins() {
    auto worker = std::make_unique<AnalysisWorker>();
    QVERIFY(worker->start(sample("plate-hole-2d.json")));
    worker.reset();  // must not crash nor leave a thread behind
  }
};

QTEST_MAIN(TestAnalysisWorker)
#include "test_analysis_worker.moc"
