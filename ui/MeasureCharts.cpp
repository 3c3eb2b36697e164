#include "MeasureCharts.h"

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

/// The palette of the charts (and of the PNG chart sink's): blue, red, green, orange, purple.
QColor palette(int i) {
  static const QColor colours[] = {{31, 119, 180}, {214, 39, 40}, {44, 160, 44}, {255, 127, 14}, {148, 103, 189}};
  return colours[static_cast<size_t>(std::abs(i)) % std::size(colours)];
}

}  // namespace

QChart* make_chart(const ChartRequest& request, const MeasureTable& table) {
  QChart* c = new_chart(QString::fromStdString(request.title));
  QValueAxis* x = axis(c, Qt::AlignBottom, QString::fromStdString(request.x_title));
  const bool right =
      std::any_of(request.lines.begin(), request.lines.end(), [](const ChartLine& l) { return l.right_axis; });
  const auto side_colour = [&](bool on_right) {
    for (const ChartLine& l : request.lines)
      if (l.right_axis == on_right) return right ? palette(l.colour) : QColor(Qt::black);
    return QColor(Qt::black);
  };
  QValueAxis* y[2] = {
      axis(c, Qt::AlignLeft, QString::fromStdString(request.left_title), side_colour(false)),
      right ? axis(c, Qt::AlignRight, QString::fromStdString(request.right_title), side_colour(true)) : nullptr};
  const size_t xc = table.column(request.x);
  const double x0 = table.rows.empty() || xc == table.columns.size() ? 0 : table.rows.front()[xc];
  x->setRange(x0, x0);
  for (QValueAxis* a : y)
    if (a) a->setRange(0, 0);
  double end = x0;
  for (const ChartLine& l : request.lines) {
    const size_t yc = table.column(l.column);
    if (xc == table.columns.size() || yc == table.columns.size()) continue;
    std::vector<QPointF> points;
    for (const MeasureRow& row : table.rows) points.emplace_back(row[xc], row[yc] * l.scale);
    if (!points.empty()) end = std::max(end, points.back().x());
    add_line(c, QString::fromStdString(l.label), points, x, y[l.right_axis], palette(l.colour));
  }
  if (!table.rows.empty())
    for (const ChartReference& r : request.references)
      add_reference(c, QString::fromStdString(r.label), {x0, end}, r.value, x, y[r.right_axis && right],
                    palette(r.colour));
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

}  // namespace rollsim::ui
