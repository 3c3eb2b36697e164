#pragma once
// The rolling pass in the run's plots: roll force and torque against travel, growing with every increment while the
// pass runs, and the pressure and friction along the arc once it ends (the charts of RollingCharts, compact). Hidden
// for a project that is not a rolling pass.
#include <QWidget>

#include "analysis/RollingResults.h"
#include "analysis/RollingTheory.h"

namespace QtCharts {
class QChart;
class QChartView;
}  // namespace QtCharts

namespace rollsim::ui {

class RollingPlot : public QWidget {
  Q_OBJECT

 public:
  explicit RollingPlot(QWidget* parent = nullptr);

  /// Forgets the last pass and hides; the next pass is of dimension `dim` (2: per unit width).
  void clear(int dim);
  /// Increments drawn so far.
  int increments() const { return static_cast<int>(pass_.increments.size()); }

 public slots:
  /// One more increment of the running pass (2D: per unit width).
  void add_increment(double travel, double roll_force, double roll_torque);
  /// The pass as it ended: every increment, the bite and steady state, the arc of the last increment, and Sims's
  /// force and torque beside them.
  void set_results(const rollsim::RollingResults& pass, int dim, const rollsim::RollingTheory& sims);

 private:
  void show_chart(QtCharts::QChartView* view, QtCharts::QChart* chart, const QString& title);
  QString history_title() const;

  RollingResults pass_;
  int dim_ = 2;
  QtCharts::QChartView* history_;
  QtCharts::QChartView* arc_;
};

}  // namespace rollsim::ui
