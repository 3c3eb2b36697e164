// The live residual plot: points buffered and drawn at most 20 times a second, one series per kind, CSV export.
#include <QSignalSpy>
#include <QtTest>

#include "ResidualPlot.h"

using namespace rollsim::ui;

class TestResidualPlot : public QObject {
  Q_OBJECT

 private slots:
  void buffers_then_plots_per_kind() {
    ResidualPlot plot;
    plot.show();
    for (int i = 1; i <= 200; ++i) plot.add_iteration(QStringLiteral("cg"), i, std::pow(10.0, -i / 20.0));
    plot.add_iteration(QStringLiteral("newton"), 1, 1e-2);
    plot.add_iteration(QStringLiteral("active_set"), 1, 3);  // a count, not a residual: not plotted
    QCOMPARE(plot.points(QStringLiteral("cg")), 0);          // not drawn point by point
    QTRY_COMPARE_WITH_TIMEOUT(plot.points(QStringLiteral("cg")), 200, 2000);
    QCOMPARE(plot.points(QStringLiteral("newton")), 1);
    QCOMPARE(plot.kinds(), (QStringList{"cg", "newton"}));
    plot.add_iteration(QStringLiteral("cg"), 1, 0.0);  // a zero residual stays plottable on the log axis
    plot.flush();
    QCOMPARE(plot.points(QStringLiteral("cg")), 201);
  }

  void csv_lists_every_point() {
    ResidualPlot plot;
    plot.add_iteration(QStringLiteral("cg"), 1, 0.5);
    plot.add_iteration(QStringLiteral("cg"), 2, 0.25);
    plot.add_iteration(QStringLiteral("cg"), 1, 0.125);  // a second solve: the index keeps counting
    const QStringList lines = plot.csv().trimmed().split('\n');
    QCOMPARE(lines.size(), 4);
    QCOMPARE(lines[0], QStringLiteral("kind,index,iteration,residual"));
    QCOMPARE(lines[3], QStringLiteral("cg,3,1,0.125"));
    plot.clear();
    QVERIFY(plot.kinds().isEmpty());
    QCOMPARE(plot.csv().trimmed(), QStringLiteral("kind,index,iteration,residual"));
  }
};

QTEST_MAIN(TestResidualPlot)
#include "test_residual_plot.moc"
