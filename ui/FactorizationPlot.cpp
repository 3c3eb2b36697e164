#include "FactorizationPlot.h"

#include <QBarSeries>
#include <QBarSet>
#include <QCategoryAxis>
#include <QCursor>
#include <QToolTip>
#include <QValueAxis>
#include <algorithm>

#include "ChartStyle.h"

namespace rollsim::ui {

using namespace QtCharts;

FactorizationPlot::FactorizationPlot(QWidget* parent)
    : QChartView(parent),
      bars_(new QBarSeries),
      counts_(new QBarSet(tr("factorizations"))),
      x_(new QCategoryAxis),
      y_(new QValueAxis) {
  QChart* c = make_compact_chart(tr("factorizations per group"));
  style_axis(x_, QString());
  style_axis(y_, QString());
  x_->setLabelsPosition(QCategoryAxis::AxisLabelsPositionCenter);
  const QColor colour(0x2c, 0xa0, 0x2c);
  counts_->setColor(colour);
  counts_->setBorderColor(colour);
  bars_->append(counts_);
  bars_->setBarWidth(0.8);
  c->addSeries(bars_);
  c->addAxis(x_, Qt::AlignBottom);
  c->addAxis(y_, Qt::AlignLeft);
  bars_->attachAxis(x_);
  bars_->attachAxis(y_);
  setChart(c);
  setMinimumSize(160, 150);
  connect(counts_, &QBarSet::hovered, this, &FactorizationPlot::show_tooltip);
  clear();
}

void FactorizationPlot::clear() {
  counts_->remove(0, counts_->count());
  groups_.clear();
  for (const QString& label : x_->categoriesLabels()) x_->remove(label);
  x_->setStartValue(-0.5);
  x_->setRange(-0.5, 0.5);
  set_integer_range(y_, 2, 4);
}

void FactorizationPlot::refresh(const RunSeries& series) {
  const QVector<GroupFactorizations>& f = series.factorizations();
  if (f.size() == groups_.size()) {  // usually only counts change, or nothing: compare before touching the chart
    bool same = true;
    for (int i = 0; i < f.size() && same; ++i) same = counts_->at(i) == f[i].count;
    if (same) return;
  }
  QList<qreal> values;
  groups_.clear();
  int ymax = 1;
  for (const GroupFactorizations& g : f) {
    groups_ << g.group;
    values << g.count;
    ymax = std::max(ymax, g.count);
  }
  counts_->remove(0, counts_->count());
  counts_->append(values);
  // one label per run of groups of the same body ("base" under base/0 ... base/14), centred under its bars
  for (const QString& label : x_->categoriesLabels()) x_->remove(label);
  for (int i = 0; i < groups_.size(); ++i) {
    const QString body = groups_[i].section('/', 0, 0);
    if (i + 1 < groups_.size() && groups_[i + 1].section('/', 0, 0) == body) continue;
    QString label = body;
    while (x_->categoriesLabels().contains(label)) label += ' ';  // labels must be unique
    x_->append(label, i + 0.5);
  }
  x_->setRange(-0.5, std::max(0.5, groups_.size() - 0.5));
  set_integer_range(y_, ymax + 1, 4);
}

QVector<GroupFactorizations> FactorizationPlot::bars() const {
  QVector<GroupFactorizations> out;
  for (int i = 0; i < counts_->count() && i < groups_.size(); ++i)
    out.append({groups_[i], static_cast<int>(counts_->at(i))});
  return out;
}

QStringList FactorizationPlot::body_labels() const {
  QStringList labels;
  for (const QString& l : x_->categoriesLabels()) labels << l.trimmed();
  return labels;
}

void FactorizationPlot::show_tooltip(bool shown, int index) {
  if (!shown || index < 0 || index >= groups_.size()) {
    QToolTip::hideText();
    return;
  }
  const int n = static_cast<int>(counts_->at(index));
  QToolTip::showText(QCursor::pos(), tr("%1: %n factorization(s)", nullptr, n).arg(groups_[index]), this);
}

}  // namespace rollsim::ui
