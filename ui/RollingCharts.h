#pragma once
// The rolling pass drawn: roll force and torque against travel, pressure and friction stress along the arc, in the
// paper's units (MN/m and kN·m/m in plane strain). `rollsim run` writes them as rolling.png and contact_profile.png,
// rendered offscreen (no display needed); the window shows the same charts after a run.
#include <QByteArray>
#include <QSize>
#include <filesystem>
#include <vector>

#include "analysis/RollingResults.h"
#include "analysis/RollingTheory.h"

namespace QtCharts {
class QChart;
}  // namespace QtCharts

namespace rollsim::ui {

/// Roll force (left axis) and torque (right axis) against roll travel; the bite and steady-state increments in the
/// title; Sims's force and torque dashed when `sims` is given. `dim` 2: per unit width.
QtCharts::QChart* make_history_chart(const RollingResults& r, int dim, const RollingTheory* sims = nullptr);
/// Pressure and friction stress against x along the arc of the last increment (entry left, exit plane at 0).
QtCharts::QChart* make_arc_chart(const std::vector<ArcPoint>& arc);
/// `chart` rendered to PNG bytes of `size` pixels on white; the chart is deleted.
QByteArray render_png(QtCharts::QChart* chart, QSize size);
/// rolling.png and contact_profile.png of a pass into `dir`, each written atomically. Runs its own offscreen
/// QApplication when none exists (the batch command). Throws std::runtime_error when a file cannot be written.
void write_rolling_plots(const std::filesystem::path& dir, const RollingResults& r, int dim, const RollingTheory& sims);

}  // namespace rollsim::ui
