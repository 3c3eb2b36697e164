#pragma once
// Residual history of a run (Qt Charts, log10 y axis with "1e-04" labels, a labelled tick every decade or every few
// decades when the plot is short): one series per iteration kind ("cg" of the interface solves, "newton" of the
// nonlinear driver), against the cumulative iteration of that kind. It draws a RunSeries; RunPlots decides when (at
// most every 100 ms), so that plotting does not slow the solver.
#include <QChartView>
#include <QMap>

#include "RunSeries.h"

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

  /// Draws what `series` gained since the last call (every point again after clear()).
  void refresh(const RunSeries& series);
  /// Removes every curve (a new run starts).
  void clear();
  /// Samples drawn so far, per kind (every sample of the series after a refresh).
  int points(const QString& kind) const;
  /// Vertices of the curve of a kind: the samples, or past 2 kMaxBuckets of them the min and max of each bucket.
  int vertices(const QString& kind) const;
  static constexpr int kMaxBuckets = 1000;
  /// The kinds drawn, in the order they arrived.
  QStringList kinds() const;
  /// The y axis (tests read its range and label format).
  const QtCharts::QLogValueAxis* residual_axis() const { return y_; }

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  /// Range in whole decades around the data; a labelled tick every decade, or every few when the plot is too short.
  void fit_residual_axis();
  struct Curve {
    QtCharts::QLineSeries* line = nullptr;
    int drawn = 0;  // samples of the kind already in `line`
  };
  Curve& curve(const QString& kind);
  static QVector<QPointF> vertices(const QVector<ResidualSample>& samples);

  QMap<QString, Curve> curves_;
  QStringList order_;
  QtCharts::QValueAxis* x_;
  QtCharts::QLogValueAxis* y_;
  double ymin_ = 1, ymax_ = 1;
  bool has_range_ = false;
  int xmax_ = 0;
};

}  // namespace rollsim::ui
