#pragma once
// A process's charts in the window (core's ChartRequest over a MeasureTable, the same requests `rollsim run` draws
// as PNG through its chart sink), and the offscreen PNG rendering of any chart (the bench and curve charts').
#include <QByteArray>
#include <QSize>

#include "base/Measures.h"

namespace QtCharts {
class QChart;
}  // namespace QtCharts

namespace rollsim::ui {

/// The chart `request` asks for, drawn from `table`: its lines with their points marked (left or right axis, in the
/// palette's colours), its references dashed.
QtCharts::QChart* make_chart(const ChartRequest& request, const MeasureTable& table);
/// `chart` rendered to PNG bytes of `size` pixels on white; the chart is deleted.
QByteArray render_png(QtCharts::QChart* chart, QSize size);

}  // namespace rollsim::ui
