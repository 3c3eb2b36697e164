#include "CairoChartSink.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <vector>

namespace rollsim::charts {

namespace {

struct Rgb {
  double r, g, b;
};
// the palette of the window's charts (matplotlib's first colours): blue, red, green, orange, purple
const Rgb kPalette[] = {
    {0.122, 0.467, 0.706}, {0.839, 0.153, 0.157}, {0.173, 0.627, 0.173}, {1.0, 0.498, 0.055}, {0.580, 0.404, 0.741}};

Rgb colour(int i) { return kPalette[static_cast<size_t>(std::abs(i)) % std::size(kPalette)]; }

/// An axis range with its tick step: nice numbers (1, 2, 5 × 10^k) around [lo, hi].
struct Axis {
  double lo = 0, hi = 1, step = 0.2;
};

Axis nice_axis(double lo, double hi) {
  if (!(hi > lo)) hi = lo + (lo == 0 ? 1 : std::abs(lo) * 0.1);
  const double raw = (hi - lo) / 8;  // 5 to 10 ticks
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  return {std::floor(lo / step) * step, std::ceil(hi / step) * step, step};
}

std::string tick_label(double v, double step) {
  if (std::abs(v) < step * 1e-9) v = 0;
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

/// Cairo's context and surface, released together.
struct Canvas {
  cairo_surface_t* surface;
  cairo_t* cr;
  Canvas(int w, int h) : surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h)), cr(cairo_create(surface)) {}
  ~Canvas() {
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;
};

void text(cairo_t* cr, double x, double y, const std::string& s, double align_x = 0, double align_y = 0,
          double angle = 0) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  cairo_save(cr);
  cairo_translate(cr, x, y);
  cairo_rotate(cr, angle);
  cairo_move_to(cr, -align_x * e.width - e.x_bearing, -align_y * e.height - e.y_bearing);
  cairo_show_text(cr, s.c_str());
  cairo_restore(cr);
}

/// The plot area and the map from data to pixels.
struct Frame {
  double left, top, width, height;
  Axis x, y;
  double px(double v) const { return left + (v - x.lo) / (x.hi - x.lo) * width; }
  double py(double v) const { return top + height - (v - y.lo) / (y.hi - y.lo) * height; }
};

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

/// A line's points (x, scaled y) from the table; rows with a non-finite value are left out.
std::vector<std::pair<double, double>> points(const MeasureTable& t, size_t x, size_t y, double scale) {
  std::vector<std::pair<double, double>> p;
  for (const MeasureRow& row : t.rows)
    if (std::isfinite(row[x]) && std::isfinite(row[y] * scale)) p.emplace_back(row[x], row[y] * scale);
  return p;
}

void draw_axis_ticks(cairo_t* cr, const Frame& f, bool right) {
  const Axis& a = f.y;
  for (double v = a.lo; v <= a.hi + a.step * 1e-6; v += a.step) {
    const double y = f.py(v);
    const double x0 = right ? f.left + f.width : f.left;
    cairo_move_to(cr, x0, y);
    cairo_line_to(cr, x0 + (right ? 5 : -5), y);
    cairo_stroke(cr);
    text(cr, x0 + (right ? 8 : -8), y, tick_label(v, a.step), right ? 0 : 1, 0.5);
  }
}

}  // namespace

std::string CairoChartSink::png(const ChartRequest& chart, const MeasureTable& table) const {
  const size_t x = table.column(chart.x);
  if (x == table.columns.size())
    throw std::runtime_error(chart.file + ": the table '" + table.name + "' has no column '" + chart.x + "'");
  struct Line {
    const ChartLine* spec;
    std::vector<std::pair<double, double>> p;
  };
  std::vector<Line> lines;
  double xlo = INFINITY, xhi = -INFINITY, ylo[2] = {0, 0}, yhi[2] = {0, 0};
  for (const ChartLine& l : chart.lines) {
    const size_t y = table.column(l.column);
    if (y == table.columns.size())
      throw std::runtime_error(chart.file + ": the table '" + table.name + "' has no column '" + l.column + "'");
    lines.push_back({&l, points(table, x, y, l.scale)});
    for (const auto& [px, py] : lines.back().p) {
      xlo = std::min(xlo, px), xhi = std::max(xhi, px);
      ylo[l.right_axis] = std::min(ylo[l.right_axis], py * 1.1),
      yhi[l.right_axis] = std::max(yhi[l.right_axis], py * 1.1);
    }
  }
  for (const ChartReference& r : chart.references) {
    ylo[r.right_axis] = std::min(ylo[r.right_axis], r.value * 1.1);
    yhi[r.right_axis] = std::max(yhi[r.right_axis], r.value * 1.1);
  }
  if (!(xhi >= xlo)) xlo = 0, xhi = 1;  // an empty table: the axes alone
  const bool right =
      std::any_of(chart.lines.begin(), chart.lines.end(), [](const ChartLine& l) { return l.right_axis; });
  Canvas canvas(width_, height_);
  cairo_t* cr = canvas.cr;
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_line_width(cr, 1);
  const Axis xaxis = nice_axis(xlo, xhi);
  Frame frames[2];
  for (int side = 0; side < 2; ++side)
    frames[side] = {90, 50, width_ - (right ? 180.0 : 120.0), height_ - 160.0, xaxis, nice_axis(ylo[side], yhi[side])};
  const Frame& f = frames[0];
  // title, frame, x ticks
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_font_size(cr, 16);
  text(cr, width_ / 2.0, 20, chart.title, 0.5, 0.5);
  cairo_set_font_size(cr, 12);
  cairo_rectangle(cr, f.left, f.top, f.width, f.height);
  cairo_stroke(cr);
  for (double v = xaxis.lo; v <= xaxis.hi + xaxis.step * 1e-6; v += xaxis.step) {
    cairo_move_to(cr, f.px(v), f.top + f.height);
    cairo_line_to(cr, f.px(v), f.top + f.height + 5);
    cairo_stroke(cr);
    text(cr, f.px(v), f.top + f.height + 8, tick_label(v, xaxis.step), 0.5, 0);
  }
  text(cr, f.left + f.width / 2, f.top + f.height + 32, chart.x_title, 0.5, 0);
  // y axes in the colour of their first line
  for (int side = 0; side < 1 + right; ++side) {
    const auto first = std::find_if(chart.lines.begin(), chart.lines.end(),
                                    [&](const ChartLine& l) { return l.right_axis == (side == 1); });
    const Rgb c = first != chart.lines.end() && right ? colour(first->colour) : Rgb{0, 0, 0};
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    draw_axis_ticks(cr, frames[side], side == 1);
    const double at = side == 0 ? 20 : width_ - 20.0;
    text(cr, at, f.top + f.height / 2, side == 0 ? chart.left_title : chart.right_title, 0.5, 0.5, -M_PI / 2);
  }
  // lines with their points marked, then the dashed references
  std::vector<std::pair<std::string, std::pair<Rgb, bool>>> legend;
  cairo_set_line_width(cr, 2);
  for (const Line& l : lines) {
    const Frame& lf = frames[l.spec->right_axis];
    const Rgb c = colour(l.spec->colour);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    for (size_t i = 0; i < l.p.size(); ++i)
      (i == 0 ? cairo_move_to : cairo_line_to)(cr, lf.px(l.p[i].first), lf.py(l.p[i].second));
    cairo_stroke(cr);
    for (const auto& [px, py] : l.p) {
      cairo_arc(cr, lf.px(px), lf.py(py), 3, 0, 2 * M_PI);
      cairo_fill(cr);
    }
    legend.push_back({l.spec->label, {c, false}});
  }
  const double dash[] = {8, 5};
  for (const ChartReference& r : chart.references) {
    const Frame& rf = frames[r.right_axis];
    const Rgb c = colour(r.colour);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_set_dash(cr, dash, 2, 0);
    cairo_move_to(cr, rf.px(xaxis.lo), rf.py(r.value));
    cairo_line_to(cr, rf.px(xaxis.hi), rf.py(r.value));
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    legend.push_back({r.label, {c, true}});
  }
  // the legend, in one row under the x axis title
  double lx = f.left;
  const double ly = height_ - 30.0;
  for (const auto& [label, style] : legend) {
    cairo_set_source_rgb(cr, style.first.r, style.first.g, style.first.b);
    if (style.second) cairo_set_dash(cr, dash, 2, 0);
    cairo_move_to(cr, lx, ly);
    cairo_line_to(cr, lx + 30, ly);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_text_extents_t e;
    cairo_text_extents(cr, label.c_str(), &e);
    text(cr, lx + 36, ly, label, 0, 0.5);
    lx += 56 + e.x_advance;
  }
  std::string bytes;
  if (cairo_status(cr) != CAIRO_STATUS_SUCCESS ||
      cairo_surface_write_to_png_stream(canvas.surface, append, &bytes) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(chart.file + ": cairo could not draw the chart (" +
                             cairo_status_to_string(cairo_status(cr)) + ")");
  return bytes;
}

}  // namespace rollsim::charts
