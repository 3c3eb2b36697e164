#include "ProcessPlot.h"

#include <QAbstractAxis>
#include <QChart>
#include <QChartView>
#include <QHBoxLayout>
#include <QXYSeries>

#include "ChartStyle.h"
#include "MeasureCharts.h"

namespace rollsim::ui {

using namespace QtCharts;

namespace {
constexpr int kViews = 2;  // the history and one more (a pass's arc)

/// The chart's curves as a legend of its title: "<br>■ roll force ■ torque<br>╌ Sims's force …", a curve's mark in its
/// colour (dashed: a reference line), two a line while they fit in about 36 characters.
QString legend_html(QChart* chart) {
  QString html;
  int line = 0;  // characters on the current line
  for (QAbstractSeries* s : chart->series()) {
    auto* xy = qobject_cast<QXYSeries*>(s);
    if (!xy || xy->name().isEmpty()) continue;
    const bool dashed = xy->pen().style() != Qt::SolidLine;
    const bool next = line == 0 || line + xy->name().size() > 36;
    line = next ? static_cast<int>(xy->name().size()) : 0;
    html += (next ? QStringLiteral("<br>") : QStringLiteral(" &nbsp; ")) +
            QStringLiteral("<span style='color:%1'>%2</span>&nbsp;%3")
                .arg(xy->pen().color().name(), dashed ? QStringLiteral("╌") : QStringLiteral("■"),
                     xy->name().toHtmlEscaped());
  }
  return html.isEmpty() ? html : QStringLiteral("<span style='font-weight:normal'>") + html + QStringLiteral("</span>");
}
}  // namespace

ProcessPlot::ProcessPlot(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  for (int i = 0; i < kViews; ++i) {
    auto* v = new QChartView;
    v->setRenderHint(QPainter::Antialiasing);
    v->setObjectName(i == 0 ? QStringLiteral("processHistory") : QStringLiteral("processProfile"));
    v->hide();
    layout->addWidget(v);
    views_.push_back(v);
  }
  hide();
}

void ProcessPlot::clear() {
  live_ = MeasureTable{};
  increments_ = 0;
  for (QChartView* v : views_) v->hide();
  hide();
}

void ProcessPlot::show_chart(QChartView* view, QChart* chart, const std::string& title) {
  make_compact(chart);
  // the units in the title (a short vertical axis title is elided), its parts ("; ") one per line, and the legend
  // under it two curves a line (Qt's legend is one row, and elided the names at the window's 1280 × 800): never cut
  chart->setTitle(QString::fromStdString(title).toHtmlEscaped().replace(QStringLiteral("; "), QStringLiteral("<br>")) +
                  legend_html(chart));
  chart->legend()->hide();
  for (QAbstractAxis* a : chart->axes(Qt::Vertical)) a->setTitleVisible(false);
  QChart* old = view->chart();
  view->setChart(chart);  // the view releases the old chart without deleting it
  delete old;
  view->show();
  show();
}

void ProcessPlot::begin(const MeasureTable& columns, const ChartRequest& chart) {
  clear();
  live_ = columns;
  live_chart_ = chart;
}

void ProcessPlot::add_row(const QVector<double>& row) {
  live_.rows.emplace_back(row.begin(), row.end());
  increments_ = static_cast<int>(live_.rows.size());
  show_chart(views_[0], make_chart(live_chart_, live_), live_chart_.short_title);
}

void ProcessPlot::set_results(const ProcessResults& results) {
  for (size_t i = 0; i < results.charts.size() && i < views_.size(); ++i) {
    const ChartRequest& c = results.charts[i];
    const MeasureTable* t = results.table(c.table);
    if (!t || t->rows.empty()) continue;
    if (i == 0) increments_ = static_cast<int>(t->rows.size());  // every increment, the last one included
    show_chart(views_[i], make_chart(c, *t), c.short_title);
  }
}

}  // namespace rollsim::ui
