#pragma once
// A pass's results as every front end and writer shows them: the tables of rolling.csv (every increment, the
// columns of rolling_measures()) and contact_profile.csv (the arc), their charts, summary.json's results.rolling
// (steady values with their units, where the roll bit and settled, the closed forms) and the lines `rollsim run`
// prints. Units come from the measures' table: each is written there once.
#include <string>
#include <vector>

#include "base/Measures.h"
#include "process/rolling/RollingPass.h"
#include "process/rolling/RollingResults.h"

namespace rollsim {

/// The tables' names: <name>.csv, and <name>.png for their charts.
inline constexpr const char* kHistoryTable = "rolling";
inline constexpr const char* kProfileTable = "contact_profile";

/// rolling.csv's table: the increment number, then every measure of rolling_measures() (the temperatures only when
/// the slab has one).
MeasureTable history_table(const RollingResults& r, int dim);
/// contact_profile.csv's table: the slab's contact nodes along the arc at the last increment.
MeasureTable profile_table(const RollingResults& r);
/// The force and torque chart (Sims's values beside them when `with_theory`) and the arc's.
ChartRequest history_chart(const RollingPass& pass, int dim, const RollingResults& r, bool with_theory);
ChartRequest profile_chart();
/// summary.json's results.rolling.
nlohmann::json rolling_summary(const RollingPass& pass, int dim, const RollingResults& r);
/// What `rollsim run` prints of a pass: its steady (or last) values and Sims's beside them.
std::vector<std::string> rolling_report(const RollingPass& pass, int dim, const RollingResults& r);

/// Everything above, as the process's results.
ProcessResults rolling_results(const RollingPass& pass, int dim, const RollingResults& r);

}  // namespace rollsim
