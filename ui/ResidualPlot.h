#pragma once
// Live residual history (Qt Charts, log-scale y): one series per iteration kind ("cg" of the interface solves,
// "newton" of the nonlinear driver). Points arrive at solver speed and are buffered; the chart repaints at most
// 20 times a second, so plotting never slows the solver.
#include <QChartView>
#include <QMap>
#include <QTimer>
#include <QVector>

namespace QtCharts {
class QLineSeries;
class QLogValueAxis;
class QValueAxis;
}  // namespace QtCharts

namespace rollsim::ui {

class ResidualPlot : public QtCharts::QChartView {
  Q_OBJECT

 public:
  explicit ResidualPlot(QWidget* parent = nullptr);

  /// Forgets every series (a new run starts).
  void clear();
  /// Points plotted so far, per kind (after flush()).
  int points(const QString& kind) const;
  QStringList kinds() const;
  /// The plotted series as CSV: kind,index,iteration,residual (index counts the points of a kind across solves).
  QString csv() const;
  /// Moves buffered points into the chart now (the timer does it at most every 50 ms).
  void flush();

 public slots:
  /// One iteration: `residual` relative (dimensionless). Kinds other than cg/newton are not residuals
  /// ("active_set" counts changed contact statuses) and are not plotted.
  void add_iteration(const QString& kind, int iteration, double residual);

 private:
  struct Sample {
    int index, iteration;
    double residual;
  };
  struct Track {
    QtCharts::QLineSeries* series = nullptr;
    QVector<Sample> samples;  // every point, plotted or pending
    int plotted = 0;
  };
  Track& track(const QString& kind);

  QMap<QString, Track> tracks_;
  QtCharts::QValueAxis* x_;
  QtCharts::QLogValueAxis* y_;
  QTimer timer_;
  double ymin_ = 1, ymax_ = 1;
  bool has_range_ = false;
  int xmax_ = 1;
};

}  // namespace rollsim::ui
