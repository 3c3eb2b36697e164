#pragma once
// Numeric factorizations per group of a run (Qt Charts bar chart: one bar per group, the count of its
// factorizations), from the strategies' reports: `mixed`/`feti` factor each group once per stiffness, `direct`/
// `skyline` the global matrix (every group) at every active-set iteration. The x axis names the bodies under their
// groups' bars (subdomains `body/<id>` side by side, too many to label one by one); a bar's tooltip names its group.
// It draws a RunSeries when RunPlots says so.
#include <QChartView>
#include <QStringList>

#include "RunSeries.h"

namespace QtCharts {
class QBarSeries;
class QBarSet;
class QCategoryAxis;
class QValueAxis;
}  // namespace QtCharts

namespace rollsim::ui {

class FactorizationPlot : public QtCharts::QChartView {
  Q_OBJECT

 public:
  explicit FactorizationPlot(QWidget* parent = nullptr);

  /// Redraws the bars when the counts of `series` changed since the last call.
  void refresh(const RunSeries& series);
  void clear();
  /// Bars drawn: group → factorizations.
  QVector<GroupFactorizations> bars() const;
  /// The body labels under the bars, left to right.
  QStringList body_labels() const;

 private:
  void show_tooltip(bool shown, int index);

  QtCharts::QBarSeries* bars_;
  QtCharts::QBarSet* counts_;
  QtCharts::QCategoryAxis* x_;
  QtCharts::QValueAxis* y_;
  QStringList groups_;
};

}  // namespace rollsim::ui
