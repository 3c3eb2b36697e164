#include "RollingCharts.h"

#include <QBuffer>
#include <QChart>
#include <QGraphicsScene>
#include <QImage>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPainter>
#include <QPen>
#include <QScatterSeries>
#include <QValueAxis>
#include <algorithm>

#include "OffscreenQt.h"
#include "io/AtomicFile.h"

namespace rollsim::ui {

using namespace QtCharts;

namespace {

QValueAxis* axis(QChart* c, Qt::Alignment where, const QString& title, QColor color = Qt::black) {
  auto* a = new QValueAxis;
  a->setTitleText(title);
  a->setLabelFormat(QStringLiteral("%.4g"));
  a->setLabelsColor(color);
  a->setTitleBrush(color);
  c->addAxis(a, where);
  return a;
}

/// A line with its points marked, attached to the axes x and y, whose ranges grow to hold it (from 0 for y).
void add_line(QChart* c, const QString& name, const std::vector<QPointF>& points, QValueAxis* x, QValueAxis* y,
              QColor color) {
  auto* line = new QLineSeries;
  line->setName(name);
  line->setColor(color);
  auto* marks = new QScatterSeries;
  marks->setColor(color);
  marks->setMarkerSize(6);
  double lo = 0, hi = 0, xlo = points.empty() ? 0 : points.front().x(), xhi = xlo;
  for (const QPointF& p : points) {
    line->append(p);
    marks->append(p);
    lo = std::min(lo, p.y()), hi = std::max(hi, p.y());
    xlo = std::min(xlo, p.x()), xhi = std::max(xhi, p.x());
  }
  for (QXYSeries* s : {static_cast<QXYSeries*>(line), static_cast<QXYSeries*>(marks)}) {
    c->addSeries(s);
    s->attachAxis(x);
    s->attachAxis(y);
  }
  c->legend()->markers(marks).front()->setVisible(false);
  y->setRange(std::min(lo * 1.1, y->min()), std::max(hi * 1.1, y->max()));
  x->setRange(std::min(xlo, x->min()), std::max(xhi, x->max()));
  x->applyNiceNumbers();
  y->applyNiceNumbers();
}

/// A dashed horizontal line at `value` over [from, to] (a closed form beside the measured line).
void add_reference(QChart* c, const QString& name, std::pair<double, double> range, double value, QValueAxis* x,
                   QValueAxis* y, QColor color) {
  auto* line = new QLineSeries;
  line->setName(name);
  QPen pen(color);
  pen.setStyle(Qt::DashLine);
  pen.setWidthF(1.5);
  line->setPen(pen);
  line->append(range.first, value);
  line->append(range.second, value);
  c->addSeries(line);
  line->attachAxis(x);
  line->attachAxis(y);
  y->setRange(std::min(y->min(), value * 1.1), std::max(y->max(), value * 1.1));
  y->applyNiceNumbers();
}

QChart* new_chart(const QString& title) {
  auto* c = new QChart;
  c->setTitle(title);
  c->legend()->setAlignment(Qt::AlignBottom);
  c->setBackgroundRoundness(0);
  return c;
}

QString increment_label(int increment) {
  return increment > 0 ? QString::number(increment) : QStringLiteral("not reached");
}

}  // namespace

QChart* make_history_chart(const RollingResults& r, int dim, const RollingTheory* sims) {
  const bool plane = dim == 2;
  QChart* c = new_chart(QStringLiteral("Roll force and torque against travel (bite: increment %1, steady state: %2)")
                            .arg(increment_label(r.bite_increment), increment_label(r.steady_state_increment)));
  QValueAxis* x = axis(c, Qt::AlignBottom, QStringLiteral("roll travel [mm]"));
  const QColor force_color(31, 119, 180), torque_color(214, 39, 40);
  QValueAxis* f = axis(c, Qt::AlignLeft, plane ? "roll force [MN/m]" : "roll force [kN]", force_color);
  QValueAxis* t = axis(c, Qt::AlignRight, plane ? "torque per roll [kN·m/m]" : "torque per roll [kN·m]", torque_color);
  x->setRange(0, 0), f->setRange(0, 0), t->setRange(0, 0);
  std::vector<QPointF> force, torque;
  for (const RollingIncrement& i : r.increments) {
    force.emplace_back(i.travel, i.roll_force * 1e-3);                     // N/mm → MN/m, N → kN
    torque.emplace_back(i.travel, i.roll_torque * (plane ? 1e-3 : 1e-6));  // N·mm/mm → kN·m/m, N·mm → kN·m
  }
  add_line(c, QStringLiteral("roll force"), force, x, f, force_color);
  add_line(c, QStringLiteral("torque"), torque, x, t, torque_color);
  if (sims && !r.increments.empty()) {
    const double end = r.increments.back().travel;
    add_reference(c, QStringLiteral("Sims's force"), {0, end}, sims->sims_force * 1e-3, x, f, force_color);
    add_reference(c, QStringLiteral("Sims's torque"), {0, end}, sims->sims_torque * (plane ? 1e-3 : 1e-6), x, t,
                  torque_color);
  }
  return c;
}

QChart* make_arc_chart(const std::vector<ArcPoint>& arc) {
  QChart* c = new_chart(QStringLiteral("Contact along the arc, last increment (entry left, exit plane at x = 0)"));
  QValueAxis* x = axis(c, Qt::AlignBottom, QStringLiteral("x [mm]"));
  QValueAxis* s = axis(c, Qt::AlignLeft, QStringLiteral("stress on the slab [MPa]"));
  const double x0 = arc.empty() ? 0 : arc.front().x;
  x->setRange(x0, x0), s->setRange(0, 0);
  std::vector<QPointF> pressure, shear;
  for (const ArcPoint& p : arc) {
    pressure.emplace_back(p.x, p.pressure);
    shear.emplace_back(p.x, p.shear);
  }
  add_line(c, QStringLiteral("pressure"), pressure, x, s, QColor(31, 119, 180));
  add_line(c, QStringLiteral("friction stress (+: toward the exit)"), shear, x, s, QColor(44, 160, 44));
  return c;
}

QByteArray render_png(QChart* chart, QSize size) {
  QGraphicsScene scene;  // owns the chart from here
  scene.addItem(chart);
  chart->setGeometry(0, 0, size.width(), size.height());
  QImage image(size, QImage::Format_ARGB32);
  image.fill(Qt::white);
  {
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    scene.render(&painter, QRectF(QPointF(0, 0), size), QRectF(QPointF(0, 0), size));
  }
  QByteArray bytes;
  QBuffer buffer(&bytes);
  buffer.open(QIODevice::WriteOnly);
  image.save(&buffer, "PNG");
  return bytes;
}

void write_rolling_plots(const std::filesystem::path& dir, const RollingResults& r, int dim,
                         const RollingTheory& sims) {
  const OffscreenQt qt;
  const QSize size(1000, 600);
  auto write = [&](const char* file, QChart* chart) {
    const QByteArray png = render_png(chart, size);
    write_file_atomically(dir / file, std::string(png.constData(), static_cast<size_t>(png.size())));
  };
  write("rolling.png", make_history_chart(r, dim, &sims));
  write("contact_profile.png", make_arc_chart(r.profile));
}

}  // namespace rollsim::ui
