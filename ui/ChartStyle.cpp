#include "ChartStyle.h"

#include <QAbstractAxis>
#include <QChart>
#include <QFont>
#include <QGraphicsLayout>
#include <QLegend>
#include <QValueAxis>
#include <algorithm>
#include <cmath>

namespace rollsim::ui {

using namespace QtCharts;

namespace {
QFont small_font(bool bold = false) {
  QFont f;
  f.setPointSizeF(std::max(6.0, f.pointSizeF() * 0.85));
  f.setBold(bold);
  return f;
}
}  // namespace

QChart* make_compact_chart(const QString& title) {
  auto* c = new QChart;
  c->setTitle(title);
  c->legend()->hide();
  make_compact(c);
  return c;
}

void make_compact(QChart* c) {
  c->setTitleFont(small_font(true));
  c->legend()->setFont(small_font());
  c->setMargins(QMargins(2, 2, 2, 2));
  c->layout()->setContentsMargins(0, 0, 0, 0);
  c->setBackgroundRoundness(0);
  for (QAbstractAxis* a : c->axes()) style_axis(a, a->titleText());
}

void set_integer_range(QValueAxis* axis, double max, int ticks) {
  const double raw = std::max(1.0, max / ticks);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * p;
  for (const double m : {5.0, 2.0, 1.0})
    if (m * p >= raw) step = m * p;
  axis->setLabelFormat(QStringLiteral("%d"));
  axis->setTickType(QValueAxis::TicksDynamic);
  axis->setTickAnchor(0);
  axis->setTickInterval(step);
  axis->setRange(0, std::max(step, std::ceil(max / step) * step));
}

void style_axis(QAbstractAxis* axis, const QString& title) {
  axis->setLabelsFont(small_font());
  axis->setTitleFont(small_font());
  axis->setTitleText(title);
  axis->setTitleVisible(!title.isEmpty());
}

}  // namespace rollsim::ui
