// Runs in the worker thread: stage, increment, progress, CG residual, solve and factorization signals arrive queued
// on the GUI thread and reach the live plots, the run finishes converged, and a cancel mid-run (before the analysis,
// between CG iterations) ends it "cancelled" with valid partial results and the worker ready for the next run; a
// Newton step cut back is signalled with its cause; a rolling pass's progress counts its travel.
#include <QSignalSpy>
#include <QThread>
#include <QtTest>
#include <cmath>
#include <fstream>

#include "../common/BentBeam.h"
#include "AnalysisWorker.h"
#include "FactorizationPlot.h"
#include "ProjectDocument.h"
#include "ResidualPlot.h"
#include "RunPanel.h"
#include "RunPlots.h"
#include "SolvePlot.h"
#include "project/RunProject.h"
#include "project/SchedulePasses.h"

using namespace rollsim;
using namespace rollsim::ui;

namespace {
Project sample(const char* name) { return load_project(std::string(ROLLSIM_SOURCE_DIR "/samples/") + name); }

/// The CG iterations carried by every batch the spy saw, in order.
QVector<CgIteration> iterations(const QSignalSpy& spy) {
  QVector<CgIteration> all;
  for (const auto& args : spy) all += args.at(0).value<QVector<CgIteration>>();
  return all;
}

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

  void iterative_solver_reports_residuals_and_the_plots_receive_them() {
    AnalysisWorker worker;
    RunPlots plots;
    plots.watch(&worker);
    QSignalSpy cg(&worker, &AnalysisWorker::cgIterations);
    QSignalSpy solves(&worker, &AnalysisWorker::solveFinished);
    QSignalSpy factorized(&worker, &AnalysisWorker::factorized);
    QSignalSpy increments(&worker, &AnalysisWorker::incrementStarted);
    QSignalSpy increments_done(&worker, &AnalysisWorker::incrementFinished);
    QSignalSpy finished(&worker, &AnalysisWorker::finished);
    ProjectDocument doc;
    RunPanel panel(&doc);
    connect(&worker, &AnalysisWorker::howFar, &panel, &RunPanel::set_progress_text);
    QVERIFY(panel.progress_text().isEmpty());
    Project p = sample("block-push-2d-50x30.json");  // floating block: projected CG in `mixed`
    p.data["solver"]["mode"] = "mixed";
    QVERIFY(worker.start(p));
    QVERIFY(finished.wait(60000));
    const auto outcome = finished.at(0).at(0).value<RunOutcome>();
    QCOMPARE(outcome.status, QStringLiteral("converged"));
    const QVector<CgIteration> its = iterations(cg);
    QVERIFY(!its.isEmpty());
    QCOMPARE(cg.at(0).at(0).value<QVector<CgIteration>>().size(), 1);  // the first iteration comes at once
    for (int i = 0; i < its.size(); ++i) {                             // then every iteration, in order, in batches
      QCOMPARE(its[i].solve, 1);
      QCOMPARE(its[i].iteration, i + 1);
    }
    QVERIFY(cg.count() < its.size() || its.size() == 1);  // fewer signals than iterations
    QCOMPARE(static_cast<long>(its.size()), outcome.cg_iterations);
    QCOMPARE(solves.count(), outcome.solves);
    QCOMPARE(solves.last().at(1).toInt(), its.size());  // one solve: all its iterations
    QCOMPARE(factorized.count(), 2);                    // base and block, once each
    QCOMPARE(increments.count(), 1);
    QCOMPARE(increments.at(0).at(1).toInt(), 1);
    QCOMPARE(increments_done.count(), 1);
    QCOMPARE(panel.progress_text(), QStringLiteral("increment 1, load factor 0 of 1 done"));
    // the plots got every point: after the throttle's last redraw they hold as many as the worker signalled
    QTRY_COMPARE_WITH_TIMEOUT(plots.residual_plot()->points(QStringLiteral("cg")), its.size(),
                              5 * RunPlots::kRefreshMs);
    QTRY_COMPARE_WITH_TIMEOUT(plots.solve_plot()->solves(), solves.count(), 5 * RunPlots::kRefreshMs);
    int bars = 0;
    for (const GroupFactorizations& g : plots.factorization_plot()->bars()) bars += g.count;
    QCOMPARE(bars, factorized.count());
  }

  void cancel_from_the_first_cg_residual_keeps_valid_partial_results() {
    AnalysisWorker worker;
    QSignalSpy cg(&worker, &AnalysisWorker::cgIterations);
    QSignalSpy finished(&worker, &AnalysisWorker::finished);
    // a direct connection runs on the worker thread: the core sees the flag at its next safe point, the next CG
    // iteration
    connect(
        &worker, &AnalysisWorker::cgIterations, this, [&worker] { worker.cancel(); }, Qt::DirectConnection);
    Project p = sample("block-indent-dd-2d-50x30.json");  // feti without preconditioner: about a hundred iterations
    p.data["solver"]["preconditioner"] = "none";
    p.data["solver"]["cg_tolerance"] = 1e-12;
    QVERIFY(worker.start(p));
    QVERIFY(finished.wait(60000));
    disconnect(&worker, &AnalysisWorker::cgIterations, this, nullptr);
    const auto outcome = finished.at(0).at(0).value<RunOutcome>();
    QCOMPARE(outcome.status, QStringLiteral("cancelled"));
    QCOMPARE(iterations(cg).size(), 1);  // stopped at the next iteration
    QCOMPARE(outcome.cg_iterations, 1L);
    // the fields of that iterate: every body, finite, contact resultants from the same multipliers
    QVERIFY(outcome.results);
    QCOMPARE(std::string(to_string(outcome.results->status.status)), std::string("cancelled"));
    QCOMPARE(outcome.results->bodies.size(), outcome.model->bodies.size());
    for (const BodyResults& b : outcome.results->bodies) {
      QVERIFY(b.displacement.allFinite());
      QVERIFY(b.nodal_force.allFinite());
      QVERIFY(b.contact_pressure.allFinite());
      for (const auto& s : b.nodal_stress)
        for (const double v : s) QVERIFY(std::isfinite(v));
    }
    QCOMPARE(outcome.results->contacts.size(), size_t{1});
    QVERIFY(std::isfinite(outcome.results->contacts[0].normal_force));
    // and the worker runs the same project to convergence afterwards
    QVERIFY(worker.start(p));
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(1).at(0).value<RunOutcome>().status, QStringLiteral("converged"));
    QVERIFY(iterations(cg).size() > 50);  // far past the cancelled run's one
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
    QVERIFY(!outcome.message.isEmpty());
  }

  void not_converged_is_reported_with_its_reason_and_no_fields() {
    AnalysisWorker worker;
    QSignalSpy finished(&worker, &AnalysisWorker::finished);
    Project p = sample("block-indent-2d-50x30.json");
    p.data["solver"]["mode"] = "mixed";
    p.data["solver"]["cg_tolerance"] = 1e-300;  // below round-off: the CG cannot get there
    QVERIFY(worker.start(p));
    QVERIFY(finished.wait(60000));
    const auto outcome = finished.at(0).at(0).value<RunOutcome>();
    QCOMPARE(outcome.status, QStringLiteral("not_converged"));
    QVERIFY2(outcome.message.contains(QStringLiteral("round-off")), qPrintable(outcome.message));
    QVERIFY(!outcome.results);  // nothing to colour the view with
  }

  void a_cut_back_is_signalled_with_its_cause() {
    // the bent beam (tests/common/BentBeam.h): every full step is cut back once, and the window's log hears each
    // with its cause
    const json j = testing_support::bent_beam();
    AnalysisWorker worker;
    QSignalSpy cut(&worker, &AnalysisWorker::cutBack);
    QSignalSpy finished(&worker, &AnalysisWorker::finished);
    QVERIFY(worker.start(parse_project(j.dump(), "beam.json")));
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(0).at(0).value<RunOutcome>().status, QStringLiteral("converged"));
    QVERIFY(cut.count() >= 2);
    for (const auto& args : cut) {
      QVERIFY(args.at(0).toInt() >= 1);
      QVERIFY2(args.at(1).toString().contains(QStringLiteral("no convergence in 4 iterations")),
               qPrintable(args.at(1).toString()));
    }
  }

  void a_rolling_pass_counts_its_progress_in_travel() {
    // issue 38: the bar said "increment i of n", whose n grows with every cut-back; a pass counts its travel
    AnalysisWorker worker;
    QSignalSpy far(&worker, &AnalysisWorker::howFar);
    QSignalSpy finished(&worker, &AnalysisWorker::finished);
    std::ifstream file(ROLLSIM_SOURCE_DIR "/samples/rolling-2d-36x6.json");
    json j = json::parse(file);
    j["process"]["travel"] = 3;
    QVERIFY(worker.start(parse_project(j.dump(), "pass.json")));
    QVERIFY(finished.wait(60000));
    QCOMPARE(finished.at(0).at(0).value<RunOutcome>().status, QStringLiteral("converged"));
    // the first step is cut back (an element folds at the entry): the total stays the pass's 3 mm
    QCOMPARE(strings(far), (QStringList{QStringLiteral("increment 1, travel 0 of 3 mm done"),
                                        QStringLiteral("increment 1, travel 0 of 3 mm done"),
                                        QStringLiteral("increment 2, travel 0.5 of 3 mm done"),
                                        QStringLiteral("increment 3, travel 1 of 3 mm done"),
                                        QStringLiteral("increment 4, travel 2 of 3 mm done")}));
  }

  void a_schedule_runs_every_pass_with_the_batch_commands_numbers() {
    // issue 33: the window runs a schedule's passes as `rollsim run` does (project/SchedulePasses), and shows the
    // schedule's chart first among the ended run's
    std::ifstream file(ROLLSIM_SOURCE_DIR "/samples/rolling-2d-schedule.json");
    json j = json::parse(file);
    j["process"]["travel"] = 8;  // each pass's front element past the exit: something rolled to hand on
    j["process"]["travel_increment"] = 2;
    const Project project = parse_project(j.dump(), "schedule.json");
    AnalysisWorker worker;
    QSignalSpy finished(&worker, &AnalysisWorker::finished);
    QVERIFY(worker.start(project, j));
    QVERIFY(finished.wait(120000));
    const RunOutcome out = finished.at(0).at(0).value<RunOutcome>();
    QVERIFY2(out.status == QStringLiteral("converged"), qPrintable(out.message));
    QVERIFY2(out.message.startsWith(QStringLiteral("schedule of 3 passes")), qPrintable(out.message));
    QVERIFY(out.results && out.results->process);
    const MeasureTable& table = out.results->process->tables.at(0);
    QCOMPARE(QString::fromStdString(table.name), QStringLiteral("schedule"));
    QCOMPARE(table.rows.size(), size_t{3});
    QCOMPARE(QString::fromStdString(out.results->process->charts.at(0).file), QStringLiteral("schedule.png"));
    // the batch command's path, pass by pass: the same forces
    ScheduleRun batch(project.data, j);
    for (size_t k = 0; k < batch.passes(); ++k) {
      const PassSetup pass = set_up_pass(batch, k, project);
      batch.finish(k, pass.model, run_project(pass.project, pass.model));
    }
    for (size_t k = 0; k < 3; ++k) QCOMPARE(table.rows[k][table.column("roll_force")], batch.records()[k].roll_force);
    // without the document (the old call), the first pass alone, and it says so
    AnalysisWorker single;
    QSignalSpy done(&single, &AnalysisWorker::finished);
    QVERIFY(single.start(project));
    QVERIFY(done.wait(60000));
    QVERIFY(done.at(0).at(0).value<RunOutcome>().message.contains(QStringLiteral("the window ran its first pass")));
  }

  void destroying_a_running_worker_cancels_and_joins() {
    auto worker = std::make_unique<AnalysisWorker>();
    QVERIFY(worker->start(sample("plate-hole-2d.json")));
    worker.reset();  // must not crash nor leave a thread behind
  }
};

QTEST_MAIN(TestAnalysisWorker)
#include "test_analysis_worker.moc"
