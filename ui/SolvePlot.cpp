#include "SolvePlot.h"

#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>
#include <algorithm>

#include "ChartStyle.h"

namespace rollsim::ui {

using namespace QtCharts;

SolvePlot::SolvePlot(QWidget* parent)
    : QChartView(parent), line_(new QLineSeries), markers_(new QScatterSeries), x_(new QValueAxis), y_(new QValueAxis) {
  QChart* c = make_compact_chart(tr("CG iterations per solve"));
  style_axis(x_, tr("solve"));
  style_axis(y_, QString());
  const QColor colour(0x1f, 0x77, 0xb4);
  line_->setColor(colour);
  markers_->setColor(colour);
  markers_->setBorderColor(colour);
  markers_->setMarkerSize(7);
  c->addAxis(x_, Qt::AlignBottom);
  c->addAxis(y_, Qt::AlignLeft);
  for (QXYSeries* s : {static_cast<QXYSeries*>(line_), static_cast<QXYSeries*>(markers_)}) {
    c->addSeries(s);
    s->attachAxis(x_);
    s->attachAxis(y_);
  }
  setChart(c);
  setRenderHint(QPainter::Antialiasing);
  setMinimumSize(160, 150);
  clear();
}

void SolvePlot::clear() {
  chart()->setTitle(tr("CG iterations per solve"));
  line_->clear();
  markers_->clear();
  drawn_ = 0;
  set_integer_range(x_, 1, 4);
  set_integer_range(y_, 10, 4);
}

void SolvePlot::refresh(const RunSeries& series) {
  const QVector<SolveRecord>& s = series.solves();
  if (drawn_ == s.size()) return;
  QVector<QPointF> points;
  points.reserve(s.size());
  int ymax = 1;
  bool any = false;
  for (const SolveRecord& r : s) {
    points.append(QPointF(r.solve, r.cg_iterations));
    ymax = std::max(ymax, r.cg_iterations);
    any = any || r.cg_iterations > 0;
  }
  // a flat line at 0 says nothing on its own: the interface (or the whole system) was solved directly
  chart()->setTitle(s.isEmpty() || any ? tr("CG iterations per solve") : tr("no CG: direct solves"));
  line_->replace(points);  // one layout for the batch (append() lays the series out once per point)
  markers_->replace(points);
  markers_->setVisible(points.size() <= kMaxMarkers);
  drawn_ = s.size();
  set_integer_range(x_, points.isEmpty() ? 1 : points.last().x() + 1, 4);  // room right of the last marker
  set_integer_range(y_, ymax * 1.1, 4);
}

int SolvePlot::solves() const { return drawn_; }

}  // namespace rollsim::ui
