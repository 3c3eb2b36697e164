#include "ResidualPlot.h"

#include <QFontMetrics>
#include <QLegend>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QValueAxis>
#include <algorithm>
#include <cmath>

#include "ChartStyle.h"

namespace rollsim::ui {

using namespace QtCharts;

namespace {
constexpr double kFloor =
    1e-300;  // a zero residual is drawn here, below the axis: a log axis shows positive values only

double plotted(double residual) { return residual > 0 && std::isfinite(residual) ? residual : kFloor; }

QColor kind_color(const QString& kind) {
  return kind == QLatin1String("newton") ? QColor(0xd6, 0x27, 0x28) : QColor(0x1f, 0x77, 0xb4);
}
}  // namespace

ResidualPlot::ResidualPlot(QWidget* parent) : QChartView(parent), x_(new QValueAxis), y_(new QLogValueAxis) {
  QChart* c = make_compact_chart(tr("relative residual"));
  c->legend()->setAlignment(Qt::AlignRight);
  c->legend()->show();
  style_axis(x_, tr("iteration (cumulative over solves)"));
  set_integer_range(x_, 10, 6);
  style_axis(y_, QString());
  y_->setLabelFormat(QStringLiteral("%.0e"));  // 1e-04
  c->addAxis(x_, Qt::AlignBottom);
  c->addAxis(y_, Qt::AlignLeft);
  setChart(c);
  setRenderHint(QPainter::Antialiasing);
  setMinimumSize(240, 150);
  fit_residual_axis();
}

void ResidualPlot::clear() {
  for (Curve& c : curves_) {
    chart()->removeSeries(c.line);
    delete c.line;
  }
  curves_.clear();
  order_.clear();
  ymin_ = ymax_ = 1;
  has_range_ = false;
  xmax_ = 0;
  set_integer_range(x_, 10, 6);
  fit_residual_axis();
}

ResidualPlot::Curve& ResidualPlot::curve(const QString& kind) {
  auto it = curves_.find(kind);
  if (it != curves_.end()) return *it;
  Curve c;
  c.line = new QLineSeries;
  c.line->setName(kind);
  c.line->setColor(kind_color(kind));
  chart()->addSeries(c.line);
  c.line->attachAxis(x_);
  c.line->attachAxis(y_);
  order_ << kind;
  return *curves_.insert(kind, c);
}

void ResidualPlot::refresh(const RunSeries& series) {
  bool any = false;
  for (const QString& kind : series.kinds()) {
    const QVector<ResidualSample>& s = series.residuals(kind);
    Curve& c = curve(kind);
    if (c.drawn > s.size()) c.drawn = 0;  // the series was cleared behind the plot's back: draw it again
    if (c.drawn == s.size()) continue;
    for (int i = c.drawn; i < s.size(); ++i) {
      const double r = s[i].residual;
      if (!(r > 0) || !std::isfinite(r)) continue;  // an exact zero is drawn below the axis, not stretching it
      if (!has_range_) ymin_ = ymax_ = r;
      has_range_ = true;
      ymin_ = std::min(ymin_, r);
      ymax_ = std::max(ymax_, r);
    }
    c.drawn = s.size();
    // one replace() per redraw: QXYSeries::append() of a list lays the whole series out again for every point
    c.line->replace(vertices(s));
    xmax_ = std::max(xmax_, s.isEmpty() ? 0 : s.last().x);
    any = true;
  }
  if (!any) return;
  // the x range grows in 1-2-5 steps (10, 20, 50, 100, ...): the axis is laid out again only when it must
  const double nice = std::pow(10.0, std::floor(std::log10(std::max(10, xmax_))));
  const double bound = xmax_ <= nice ? nice : xmax_ <= 2 * nice ? 2 * nice : xmax_ <= 5 * nice ? 5 * nice : 10 * nice;
  if (bound != x_->max()) set_integer_range(x_, bound, 6);
  fit_residual_axis();
}

void ResidualPlot::resizeEvent(QResizeEvent* event) {
  QChartView::resizeEvent(event);
  fit_residual_axis();
}

void ResidualPlot::fit_residual_axis() {
  // whole decades, at least two, so that the axis always carries labelled ticks
  const int lo = has_range_ ? static_cast<int>(std::floor(std::log10(std::max(ymin_, kFloor)))) : -8;
  const int hi = has_range_ ? std::max(static_cast<int>(std::ceil(std::log10(ymax_))), lo + 2) : 0;
  // Qt Charts elides a label taller than its share of the axis to "...": label every `step` decades so that each
  // label has room (the plot area is the view less the title and the x axis, about four text lines)
  const QFontMetrics fm(y_->labelsFont());
  const int plot_height = std::max(fm.height(), height() - 4 * fm.height() - 24);
  const int fit = std::max(1, plot_height / (fm.height() + 10));
  const int step = (hi - lo + fit - 1) / fit;
  const int first = static_cast<int>(std::floor(static_cast<double>(lo) / step)) * step;
  const int last = static_cast<int>(std::ceil(static_cast<double>(hi) / step)) * step;
  const double base = std::pow(10.0, step), low = std::pow(10.0, first), high = std::pow(10.0, last);
  if (base == y_->base() && low == y_->min() && high == y_->max()) return;  // no layout for nothing
  y_->setBase(base);
  y_->setMinorTickCount(step == 1 && hi - lo <= 4 ? -1 : 0);  // 2..9 multiples only where they are not clutter
  y_->setRange(low, high);
}

int ResidualPlot::points(const QString& kind) const {
  const auto it = curves_.find(kind);
  return it == curves_.end() ? 0 : it->drawn;
}

int ResidualPlot::vertices(const QString& kind) const {
  const auto it = curves_.find(kind);
  return it == curves_.end() ? 0 : it->line->count();
}

QVector<QPointF> ResidualPlot::vertices(const QVector<ResidualSample>& s) {
  const int n = s.size();
  QVector<QPointF> v;
  if (n <= 2 * kMaxBuckets) {
    v.reserve(n);
    for (int i = 0; i < n; ++i) v.append(QPointF(s[i].x, plotted(s[i].residual)));
    return v;
  }
  // more samples than pixels: the smallest and the largest residual of each bucket, in iteration order, keep the
  // envelope of the curve (spikes included) with at most 2 kMaxBuckets vertices
  const int bucket = (n + kMaxBuckets - 1) / kMaxBuckets;
  v.reserve(2 * kMaxBuckets);
  for (int b = 0; b < n; b += bucket) {
    int lo = b, hi = b;
    for (int i = b; i < std::min(n, b + bucket); ++i) {
      if (s[i].residual < s[lo].residual) lo = i;
      if (s[i].residual > s[hi].residual) hi = i;
    }
    for (const int i : {std::min(lo, hi), std::max(lo, hi)}) {
      v.append(QPointF(s[i].x, plotted(s[i].residual)));
      if (lo == hi) break;
    }
  }
  return v;
}

QStringList ResidualPlot::kinds() const { return order_; }

}  // namespace rollsim::ui
