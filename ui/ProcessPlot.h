#pragma once
// A process's measures in the run's plots: its live chart growing with every increment while the run goes on (a
// rolling pass: roll force and torque against travel), then its charts as the run ended (the pass's history with
// Sims's values, the arc) — the requests the process makes, drawn compact. Hidden for a project without a process.
#include <QWidget>
#include <vector>

#include "base/Measures.h"

namespace QtCharts {
class QChart;
class QChartView;
}  // namespace QtCharts

namespace rollsim::ui {

class ProcessPlot : public QWidget {
  Q_OBJECT

 public:
  explicit ProcessPlot(QWidget* parent = nullptr);

  /// Forgets the last run and hides.
  void clear();
  /// Increments drawn so far (live, then every one of the ended run).
  int increments() const { return increments_; }

 public slots:
  /// A run starts measuring: the columns of each increment's row and the chart that plots them.
  void begin(const rollsim::MeasureTable& columns, const rollsim::ChartRequest& chart);
  /// One more increment's row.
  void add_row(const QVector<double>& row);
  /// The run ended: the process's charts from its tables (the first two: history and profile).
  void set_results(const rollsim::ProcessResults& results);

 private:
  void show_chart(QtCharts::QChartView* view, QtCharts::QChart* chart, const std::string& title);

  MeasureTable live_;
  ChartRequest live_chart_;
  int increments_ = 0;
  std::vector<QtCharts::QChartView*> views_;
};

}  // namespace rollsim::ui
