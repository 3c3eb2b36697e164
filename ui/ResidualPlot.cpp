#include "ResidualPlot.h"

#include <QLineSeries>
#include <QLogValueAxis>
#include <QValueAxis>
#include <algorithm>
#include <cmath>

namespace rollsim::ui {

using namespace QtCharts;

namespace {
constexpr int kRepaintMs = 50;  // at most 20 repaints per second
}

ResidualPlot::ResidualPlot(QWidget* parent) : QChartView(parent), x_(new QValueAxis), y_(new QLogValueAxis) {
  auto* c = new QChart;
  c->legend()->setAlignment(Qt::AlignRight);
  c->setMargins(QMargins(4, 4, 4, 4));
  x_->setTitleText(tr("iteration (cumulative over solves)"));
  x_->setTickCount(6);
  x_->setLabelFormat(QStringLiteral("%d"));
  x_->setRange(0, 10);
  y_->setTitleText(tr("relative residual"));
  y_->setLabelFormat(QStringLiteral("%.0e"));
  y_->setBase(10);
  y_->setRange(1e-8, 1);
  c->addAxis(x_, Qt::AlignBottom);
  c->addAxis(y_, Qt::AlignLeft);
  setChart(c);
  setRenderHint(QPainter::Antialiasing);
  setMinimumHeight(160);
  timer_.setInterval(kRepaintMs);
  timer_.setSingleShot(true);
  connect(&timer_, &QTimer::timeout, this, &ResidualPlot::flush);
}

void ResidualPlot::clear() {
  timer_.stop();
  for (Track& t : tracks_) {
    chart()->removeSeries(t.series);
    delete t.series;
  }
  tracks_.clear();
  ymin_ = ymax_ = 1;
  has_range_ = false;
  xmax_ = 1;
  x_->setRange(0, 10);
  y_->setRange(1e-8, 1);
}

ResidualPlot::Track& ResidualPlot::track(const QString& kind) {
  auto it = tracks_.find(kind);
  if (it != tracks_.end()) return *it;
  Track t;
  t.series = new QLineSeries;
  t.series->setName(kind);
  chart()->addSeries(t.series);
  t.series->attachAxis(x_);
  t.series->attachAxis(y_);
  return *tracks_.insert(kind, t);
}

void ResidualPlot::add_iteration(const QString& kind, int iteration, double residual) {
  if (kind != QLatin1String("cg") && kind != QLatin1String("newton")) return;
  if (!(residual > 0) || !std::isfinite(residual)) residual = 1e-300;  // a log axis shows positive values only
  Track& t = track(kind);
  t.samples.push_back({static_cast<int>(t.samples.size()) + 1, iteration, residual});
  if (!timer_.isActive()) timer_.start();
}

void ResidualPlot::flush() {
  bool any = false;
  for (Track& t : tracks_) {
    if (t.plotted == t.samples.size()) continue;
    QList<QPointF> points;
    for (int i = t.plotted; i < t.samples.size(); ++i) {
      const Sample& s = t.samples[i];
      points.append(QPointF(s.index, s.residual));
      if (!has_range_) ymin_ = ymax_ = s.residual;
      has_range_ = true;
      ymin_ = std::min(ymin_, s.residual);
      ymax_ = std::max(ymax_, s.residual);
      xmax_ = std::max(xmax_, s.index);
      any = true;
    }
    t.series->append(points);
    t.plotted = t.samples.size();
  }
  if (!any) return;
  x_->setRange(0, std::max(10, xmax_));
  const double lo = std::pow(10.0, std::floor(std::log10(std::max(ymin_, 1e-300))));
  const double hi = std::pow(10.0, std::ceil(std::log10(ymax_)));
  y_->setRange(lo, hi > lo ? hi : lo * 10);
}

int ResidualPlot::points(const QString& kind) const {
  const auto it = tracks_.find(kind);
  return it == tracks_.end() ? 0 : it->series->count();
}

QStringList ResidualPlot::kinds() const { return tracks_.keys(); }

QString ResidualPlot::csv() const {
  QString s = QStringLiteral("kind,index,iteration,residual\n");
  for (auto it = tracks_.begin(); it != tracks_.end(); ++it)
    for (const Sample& p : it->samples)
      s += QStringLiteral("%1,%2,%3,%4\n").arg(it.key()).arg(p.index).arg(p.iteration).arg(p.residual, 0, 'g', 17);
  return s;
}

}  // namespace rollsim::ui
