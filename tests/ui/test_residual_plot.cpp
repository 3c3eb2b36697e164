// The live plots of a run (RunPlots): reports are recorded at once and drawn at most every 100 ms; one residual
// series per kind on a log10 axis with "1e-04" labels spanning whole decades; CG iterations per solve; factorizations
// per group; the CSV export of every series.
#include <QElapsedTimer>
#include <QLogValueAxis>
#include <QSignalSpy>
#include <QtTest>
#include <cmath>

#include "FactorizationPlot.h"
#include "ResidualPlot.h"
#include "RunPlots.h"
#include "SolvePlot.h"

using namespace rollsim::ui;

class TestResidualPlot : public QObject {
  Q_OBJECT

 private slots:
  void buffers_then_plots_per_kind() {
    RunPlots plots;
    plots.show();
    ResidualPlot* plot = plots.residual_plot();
    for (int i = 1; i <= 200; ++i) plots.add_cg_iteration(1, i, std::pow(10.0, -i / 20.0));
    plots.add_newton_iteration(1, 1, 1e-2);
    QCOMPARE(plots.series().residuals(QStringLiteral("cg")).size(), 200);  // recorded at once
    QCOMPARE(plot->points(QStringLiteral("cg")), 0);                       // drawn later, in one go
    QTRY_COMPARE_WITH_TIMEOUT(plot->points(QStringLiteral("cg")), 200, 2000);
    QCOMPARE(plot->points(QStringLiteral("newton")), 1);
    QCOMPARE(plot->kinds(), (QStringList{"cg", "newton"}));
    plots.add_cg_iteration(2, 1, 0.0);  // a zero residual stays plottable on the log axis
    plots.flush();
    QCOMPARE(plot->points(QStringLiteral("cg")), 201);
  }

  void a_long_history_is_drawn_with_a_bounded_number_of_vertices() {
    RunPlots plots;
    plots.resize(900, 250);
    plots.show();
    constexpr int n = 100000;  // e.g. the CG iterations of every Newton step of a long rolling pass
    for (int i = 1; i <= n; ++i) plots.add_cg_iteration(1 + i / 500, 1 + i % 500, std::pow(10.0, -(i % 500) / 50.0));
    plots.add_cg_iteration(999, 1, 1e-20);  // a spike: the envelope keeps it
    QElapsedTimer t;
    t.start();
    plots.flush();
    const qint64 ms = t.elapsed();
    ResidualPlot* plot = plots.residual_plot();
    QCOMPARE(plot->points(QStringLiteral("cg")), n + 1);
    QVERIFY(plot->vertices(QStringLiteral("cg")) <= 2 * ResidualPlot::kMaxBuckets);
    QVERIFY(plot->vertices(QStringLiteral("cg")) >= ResidualPlot::kMaxBuckets);
    QVERIFY(plot->residual_axis()->min() <= 1e-20);
    qInfo("flush of %d samples: %lld ms", n + 1, ms);  // printed, not asserted
  }

  void log_axis_spans_whole_decades_with_short_labels() {
    RunPlots plots;
    plots.resize(900, 300);
    plots.show();
    plots.add_cg_iteration(1, 1, 0.5);
    plots.add_cg_iteration(1, 2, 3e-5);
    plots.flush();
    const auto* y = plots.residual_plot()->residual_axis();
    QCOMPARE(y->labelFormat(), QStringLiteral("%.0e"));  // 1e-04, not 0.000100000
    QCOMPARE(y->base(), 10.0);
    QCOMPARE(y->min(), 1e-5);
    QCOMPARE(y->max(), 1.0);
    plots.add_cg_iteration(1, 3, 0.9);  // a narrow range still shows two decades
    plots.clear();
    plots.add_cg_iteration(1, 1, 0.9);
    plots.flush();
    QCOMPARE(y->min(), 0.1);
    QCOMPARE(y->max(), 10.0);
    // a short plot labels every few decades, so that no label is elided to "..."
    for (int i = 1; i <= 6; ++i) plots.add_cg_iteration(1, i, std::pow(10.0, -i));
    plots.flush();
    QCOMPARE(y->base(), 10.0);
    QCOMPARE(y->min(), 1e-6);
    plots.resize(900, 160);
    QTRY_VERIFY(y->base() > 10.0);
    QVERIFY(y->min() <= 1e-6);
    QVERIFY(y->max() >= 0.9);
  }

  void plots_cg_iterations_per_solve_and_factorizations_per_group() {
    RunPlots plots;
    plots.add_factorization(QStringLiteral("base/0"));
    plots.add_factorization(QStringLiteral("block"));
    plots.add_factorization(QStringLiteral("base/0"));
    plots.end_solve(1, 42);
    plots.end_solve(2, 7);
    plots.flush();
    QCOMPARE(plots.solve_plot()->solves(), 2);
    const QVector<GroupFactorizations> bars = plots.factorization_plot()->bars();
    QCOMPARE(bars.size(), 2);
    QCOMPARE(bars[0].group, QStringLiteral("base/0"));
    QCOMPARE(bars[0].count, 2);
    QCOMPARE(bars[1].group, QStringLiteral("block"));
    QCOMPARE(bars[1].count, 1);
    QCOMPARE(plots.factorization_plot()->body_labels(), (QStringList{"base", "block"}));
    QCOMPARE(plots.solve_plot()->chart()->title(), QStringLiteral("CG iterations per solve"));
    plots.clear();
    QCOMPARE(plots.solve_plot()->solves(), 0);
    QVERIFY(plots.factorization_plot()->bars().isEmpty());
    plots.end_solve(1, 0);  // solved directly (direct, or mixed with a dense interface): the title says why it is flat
    plots.end_solve(2, 0);
    plots.flush();
    QCOMPARE(plots.solve_plot()->chart()->title(), QStringLiteral("no CG: direct solves"));
  }

  void csv_lists_every_series() {
    RunPlots plots;
    plots.begin_increment(1, 1);
    plots.add_factorization(QStringLiteral("block"));
    plots.add_cg_iteration(1, 1, 0.5);
    plots.add_cg_iteration(1, 2, 0.25);
    plots.end_solve(1, 2);
    plots.add_cg_iteration(2, 1, 0.125);
    plots.end_solve(2, 1);
    plots.add_newton_iteration(1, 1, 1e-3);
    const QStringList lines = plots.csv().trimmed().split('\n');
    const QStringList want{
        "series,kind,increment,solve,iteration,group,value",
        "residual,cg,1,1,1,,0.5",
        "residual,cg,1,1,2,,0.25",
        "residual,cg,1,2,1,,0.125",
        "residual,newton,1,2,1,,0.001",
        "cg_iterations,cg,1,1,,,2",
        "cg_iterations,cg,1,2,,,1",
        "factorizations,,,,,block,1",
    };
    QCOMPARE(lines, want);
    plots.clear();
    QVERIFY(plots.series().kinds().isEmpty());
    QCOMPARE(plots.csv().trimmed(), want[0]);
  }
};

QTEST_MAIN(TestResidualPlot)
#include "test_residual_plot.moc"
