#pragma once
// The look shared by the run's charts: compact margins and fonts so that three charts fit the bottom dock, a
// chart title instead of long axis titles (a vertical title longer than the plot is elided to "...").
#include <QString>

namespace QtCharts {
class QAbstractAxis;
class QChart;
class QValueAxis;
}  // namespace QtCharts

namespace rollsim::ui {

/// A new chart titled `title`, legend hidden, small margins.
QtCharts::QChart* make_compact_chart(const QString& title);
/// The compact look (small fonts and margins, every axis styled with its own title) on a chart built elsewhere; the
/// legend stays as it is.
void make_compact(QtCharts::QChart* chart);
/// Small label and title fonts on `axis`, titled `title` (empty: no title).
void style_axis(QtCharts::QAbstractAxis* axis, const QString& title);
/// Range [0, ≥ max] with about `ticks` ticks at integer multiples of 1, 2 or 5 × 10^k ("%d" labels).
void set_integer_range(QtCharts::QValueAxis* axis, double max, int ticks);

}  // namespace rollsim::ui
