#pragma once
// CG iterations of every linear solve of a run (Qt Charts): one marker per solve, joined, so that a growing number
// of solves (active-set iterations today, Newton iterations of every increment later) stays readable. Direct
// strategies and a dense interface show 0 per solve, and the title says so. It draws a RunSeries when RunPlots says
// so.
#include <QChartView>

#include "RunSeries.h"

namespace QtCharts {
class QLineSeries;
class QScatterSeries;
class QValueAxis;
}  // namespace QtCharts

namespace rollsim::ui {

class SolvePlot : public QtCharts::QChartView {
  Q_OBJECT

 public:
  explicit SolvePlot(QWidget* parent = nullptr);

  /// Draws the solves `series` gained since the last call.
  void refresh(const RunSeries& series);
  void clear();
  /// Solves drawn so far.
  int solves() const;

 private:
  QtCharts::QLineSeries* line_;
  QtCharts::QScatterSeries* markers_;
  QtCharts::QValueAxis* x_;
  QtCharts::QValueAxis* y_;
  int drawn_ = 0;
  static constexpr int kMaxMarkers = 100;  // more solves than this: the line alone
};

}  // namespace rollsim::ui
