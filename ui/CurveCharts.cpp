#include "CurveCharts.h"

#include <QChart>
#include <QLegend>
#include <QLineSeries>
#include <QPen>
#include <QScatterSeries>
#include <QValueAxis>
#include <algorithm>

#include "MeasureCharts.h"
#include "OffscreenQt.h"
#include "io/AtomicFile.h"

namespace rollsim::ui {

using namespace QtCharts;

namespace {

QColor palette(size_t i) {
  static const QColor colors[] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {148, 103, 189}, {255, 127, 14}};
  return colors[i % (sizeof colors / sizeof colors[0])];
}

QValueAxis* axis(QChart* c, Qt::Alignment where, const std::string& title, double lo, double hi) {
  auto* a = new QValueAxis;
  a->setTitleText(QString::fromStdString(title));
  a->setLabelFormat(QStringLiteral("%.3g"));
  a->setRange(lo, hi);
  a->applyNiceNumbers();
  c->addAxis(a, where);
  return a;
}

QXYSeries* make_series(const Curve& curve, QColor color) {
  QXYSeries* s = nullptr;
  if (curve.reference) {
    auto* rings = new QScatterSeries;
    rings->setMarkerSize(11);
    rings->setBrush(Qt::NoBrush);
    rings->setPen(QPen(Qt::black, 1.5));
    s = rings;
  } else {
    auto* line = new QLineSeries;
    line->setPen(QPen(color, 2));
    s = line;
  }
  s->setName(QString::fromStdString(curve.name));
  for (const auto& [x, y] : curve.points) s->append(x, y);
  return s;
}

QChart* make_chart(const std::string& title, const std::string& x_title, const std::string& y_title,
                   const std::vector<Curve>& curves, double y_min) {
  auto* c = new QChart;
  c->setTitle(QString::fromStdString(title));
  c->legend()->setAlignment(Qt::AlignRight);
  c->setBackgroundRoundness(0);
  double x0 = 0, x1 = 1e-300, y0 = 1e300, y1 = -1e300;
  for (const Curve& k : curves)
    for (const auto& [x, y] : k.points)
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  if (y1 < y0) y0 = 0, y1 = 1;
  QValueAxis* x = axis(c, Qt::AlignBottom, x_title, x0, x1);
  QValueAxis* y = axis(c, Qt::AlignLeft, y_title, std::min(y_min, y0), y1 + 0.02 * (y1 - std::min(y_min, y0)));
  size_t colour = 0;
  for (const Curve& k : curves) {
    QXYSeries* s = make_series(k, palette(colour));
    if (!k.reference) ++colour;
    c->addSeries(s);
    s->attachAxis(x);
    s->attachAxis(y);
  }
  return c;
}

}  // namespace

void write_curves_png(const std::filesystem::path& file, const std::string& title, const std::string& x_title,
                      const std::string& y_title, const std::vector<Curve>& curves, double y_min) {
  const OffscreenQt qt;
  const QByteArray png = render_png(make_chart(title, x_title, y_title, curves, y_min), QSize(1000, 600));
  write_file_atomically(file, std::string(png.constData(), static_cast<size_t>(png.size())));
}

}  // namespace rollsim::ui
