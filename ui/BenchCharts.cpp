#include "BenchCharts.h"

#include <QChart>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QPen>
#include <QScatterSeries>
#include <algorithm>
#include <cmath>

#include "MeasureCharts.h"
#include "OffscreenQt.h"
#include "io/AtomicFile.h"

namespace rollsim::ui {

using namespace QtCharts;

namespace {

constexpr double kSmallestError = 1e-16;  // an exact answer is drawn at round-off

QColor palette(size_t i) {
  static const QColor colors[] = {{31, 119, 180},  {255, 127, 14}, {44, 160, 44},   {214, 39, 40},
                                  {148, 103, 189}, {140, 86, 75},  {227, 119, 194}, {127, 127, 127}};
  return colors[i % (sizeof colors / sizeof colors[0])];
}

QPointF at(const TimeErrorPoint& p) { return {p.time, std::max(p.error, kSmallestError)}; }

/// The points no other point beats in both time and error, by increasing time.
std::vector<TimeErrorPoint> own_front(std::vector<TimeErrorPoint> p) {
  std::sort(p.begin(), p.end(),
            [](auto& a, auto& b) { return a.time < b.time || (a.time == b.time && a.error < b.error); });
  std::vector<TimeErrorPoint> front;
  for (const TimeErrorPoint& q : p)
    if (front.empty() || q.error < front.back().error) front.push_back(q);
  return front;
}

QLogValueAxis* log_axis(QChart* c, Qt::Alignment where, const QString& title, double lo, double hi) {
  auto* a = new QLogValueAxis;
  a->setTitleText(title);
  a->setBase(10);
  a->setLabelFormat(QStringLiteral("%.0e"));
  a->setMinorTickCount(-1);
  // whole decades, a hair wider so that both end labels are drawn
  a->setRange(0.9999 * std::pow(10, std::floor(std::log10(lo))), 1.0001 * std::pow(10, std::ceil(std::log10(hi))));
  c->addAxis(a, where);
  return a;
}

void attach(QChart* c, QXYSeries* s, QAbstractAxis* x, QAbstractAxis* y) {
  c->addSeries(s);
  s->attachAxis(x);
  s->attachAxis(y);
}

QChart* make_chart(const std::string& title, const std::vector<TimeErrorSeries>& series,
                   std::vector<TimeErrorPoint> front) {
  auto* c = new QChart;
  c->setTitle(QString::fromStdString(title));
  c->legend()->setAlignment(Qt::AlignRight);
  c->setBackgroundRoundness(0);
  double t0 = 1e300, t1 = 0, e0 = 1e300, e1 = 0;
  for (const auto& s : series)
    for (const auto& p : s.points) {
      const QPointF q = at(p);
      t0 = std::min(t0, q.x()), t1 = std::max(t1, q.x()), e0 = std::min(e0, q.y()), e1 = std::max(e1, q.y());
    }
  if (t1 <= 0) t0 = 1e-3, t1 = 1, e0 = 1e-6, e1 = 1;
  QLogValueAxis* x = log_axis(c, Qt::AlignBottom, QStringLiteral("wall time [s]"), t0, t1);
  QLogValueAxis* y = log_axis(c, Qt::AlignLeft, QStringLiteral("relative error"), e0, e1);
  for (size_t i = 0; i < series.size(); ++i) {
    auto* marks = new QScatterSeries;
    marks->setName(QString::fromStdString(series[i].name));
    marks->setColor(palette(i));
    marks->setBorderColor(palette(i));
    marks->setMarkerSize(7);
    for (const auto& p : series[i].points) marks->append(at(p));
    auto* line = new QLineSeries;
    line->setColor(palette(i));
    for (const auto& p : own_front(series[i].points)) line->append(at(p));
    attach(c, marks, x, y);
    attach(c, line, x, y);
    c->legend()->markers(line).front()->setVisible(false);
  }
  front = own_front(front);
  auto* dashed = new QLineSeries;
  dashed->setName(QStringLiteral("Pareto front"));
  QPen pen(Qt::black);
  pen.setStyle(Qt::DashLine);
  pen.setWidthF(1.5);
  dashed->setPen(pen);
  auto* rings = new QScatterSeries;
  rings->setMarkerSize(15);
  rings->setBrush(Qt::NoBrush);
  rings->setPen(QPen(Qt::black, 1.5));
  for (const auto& p : front) dashed->append(at(p)), rings->append(at(p));
  attach(c, dashed, x, y);
  attach(c, rings, x, y);
  c->legend()->markers(rings).front()->setVisible(false);
  return c;
}

}  // namespace

void write_time_error_png(const std::filesystem::path& file, const std::string& title,
                          const std::vector<TimeErrorSeries>& series, std::vector<TimeErrorPoint> front) {
  const OffscreenQt qt;
  const QByteArray png = render_png(make_chart(title, series, std::move(front)), QSize(1000, 650));
  write_file_atomically(file, std::string(png.constData(), static_cast<size_t>(png.size())));
}

}  // namespace rollsim::ui
