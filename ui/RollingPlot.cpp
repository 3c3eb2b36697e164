#include "RollingPlot.h"

#include <QAbstractAxis>
#include <QChart>
#include <QChartView>
#include <QHBoxLayout>

#include "ChartStyle.h"
#include "RollingCharts.h"

namespace rollsim::ui {

using namespace QtCharts;

RollingPlot::RollingPlot(QWidget* parent) : QWidget(parent), history_(new QChartView), arc_(new QChartView) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  for (QChartView* v : {history_, arc_}) {
    v->setRenderHint(QPainter::Antialiasing);
    layout->addWidget(v);
  }
  history_->setObjectName(QStringLiteral("rollingHistory"));
  arc_->setObjectName(QStringLiteral("rollingArc"));
  arc_->hide();
  hide();
}

void RollingPlot::clear(int dim) {
  pass_ = RollingResults{};
  dim_ = dim;
  arc_->hide();
  hide();
}

void RollingPlot::show_chart(QChartView* view, QChart* chart, const QString& title) {
  make_compact(chart);
  chart->setTitle(title);  // the units in the title: a vertical axis title this short a chart would elide
  for (QAbstractAxis* a : chart->axes(Qt::Vertical)) a->setTitleVisible(false);
  QChart* old = view->chart();
  view->setChart(chart);  // the view releases the old chart without deleting it
  delete old;
  view->show();
  show();
}

void RollingPlot::add_increment(double travel, double roll_force, double roll_torque) {
  RollingIncrement i;
  i.travel = travel, i.roll_force = roll_force, i.roll_torque = roll_torque;
  pass_.increments.push_back(i);
  show_chart(history_, make_history_chart(pass_, dim_), history_title());
}

QString RollingPlot::history_title() const {
  const QString units = dim_ == 2 ? tr("force [MN/m], torque [kN·m/m]") : tr("force [kN], torque [kN·m]");
  const int steady = pass_.steady_state_increment;
  return tr("roll %1; steady: %2").arg(units, steady ? tr("from increment %1").arg(steady) : tr("not yet"));
}

void RollingPlot::set_results(const RollingResults& pass, int dim, const RollingTheory& sims) {
  pass_ = pass;
  dim_ = dim;
  show_chart(history_, make_history_chart(pass_, dim_, &sims), history_title());
  if (!pass_.profile.empty())
    show_chart(arc_, make_arc_chart(pass_.profile), tr("pressure, friction [MPa] along the arc"));
}

}  // namespace rollsim::ui
