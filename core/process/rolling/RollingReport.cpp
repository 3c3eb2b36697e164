#include "process/rolling/RollingReport.h"

#include <cmath>
#include <cstdio>

#include "process/rolling/RollingMeasures.h"
#include "process/rolling/RollingTheory.h"

namespace rollsim {

namespace {
std::string increment_label(int increment) {
  return increment > 0 ? std::to_string(increment) : std::string("not reached");
}

/// The closed forms beside the pass's values (RollingTheory), in the same units; angles in degrees.
nlohmann::json theory_section(const RollingPass& pass) {
  const RollingTheory t = rolling_theory(pass);
  return {{"sims_roll_force", t.sims_force},
          {"sims_roll_torque", t.sims_torque},
          {"sims_forward_slip", t.sims_forward_slip},
          {"sims_neutral_angle", t.neutral_angle * 180 / M_PI},
          {"friction_hill_roll_force", t.friction_hill_force},
          {"bite_angle", t.bite_angle * 180 / M_PI},
          {"projected_contact_length", t.contact_length},
          {"hitchcock_radius_ratio", t.hitchcock_radius_ratio},
          {"wusatowski_spread", t.wusatowski_spread}};
}

}  // namespace

MeasureTable history_table(const RollingResults& r, int dim) {
  MeasureTable t{kHistoryTable, {{"increment", "increment", "-"}}, {}};
  for (const RollingMeasure& m : rolling_measures())
    if (!m.thermal || r.thermal) t.columns.push_back(m.in(dim));
  for (size_t i = 0; i < r.increments.size(); ++i) {
    MeasureRow row{static_cast<double>(i + 1)};
    for (const RollingMeasure& m : rolling_measures())
      if (!m.thermal || r.thermal) row.push_back(r.increments[i].*m.field);
    t.rows.push_back(std::move(row));
  }
  return t;
}

MeasureTable profile_table(const RollingResults& r) {
  MeasureTable t{kProfileTable,
                 {{"angle", "angle from the roll's lowest point, positive toward the entry", "degree"},
                  {"x", "position along the rolling direction (exit plane at 0)", "mm"},
                  {"width", "position across the width (3D; symmetry plane at 0)", "mm"},
                  {"pressure", "contact pressure", "MPa"},
                  {"shear", "friction stress on the slab (+: toward the exit)", "MPa"}},
                 {}};
  for (const ArcPoint& p : r.profile) t.rows.push_back({p.angle, p.x, p.width, p.pressure, p.shear});
  return t;
}

ChartRequest history_chart(const RollingPass& pass, int dim, const RollingResults& r, bool with_theory) {
  const bool plane = dim == 2;
  ChartRequest c;
  c.file = kHistoryTable + std::string(".png");
  c.title = "Roll force and torque against travel (bite: increment " + increment_label(r.bite_increment) +
            ", steady state: " + increment_label(r.steady_state_increment) + ")";
  c.short_title = std::string("roll ") + (plane ? "force [MN/m], torque [kN·m/m]" : "force [kN], torque [kN·m]") +
                  "; steady: " +
                  (r.steady_state_increment ? "from increment " + std::to_string(r.steady_state_increment)
                                            : std::string("not yet"));
  c.table = kHistoryTable;
  c.x = "travel";
  c.x_title = "roll travel [mm]";
  c.left_title = plane ? "roll force [MN/m]" : "roll force [kN]";
  c.right_title = plane ? "torque per roll [kN·m/m]" : "torque per roll [kN·m]";
  const double torque_scale = plane ? 1e-3 : 1e-6;  // N·mm/mm → kN·m/m, N·mm → kN·m
  c.lines = {{"roll_force", "roll force", 1e-3, false, 0}, {"roll_torque", "torque", torque_scale, true, 1}};
  if (with_theory) {
    const RollingTheory t = rolling_theory(pass);
    c.references = {{"Sims's force", t.sims_force * 1e-3, false, 0},
                    {"Sims's torque", t.sims_torque * torque_scale, true, 1}};
  }
  return c;
}

ChartRequest profile_chart() {
  ChartRequest c;
  c.file = kProfileTable + std::string(".png");
  c.title = "Contact along the arc, last increment (entry left, exit plane at x = 0)";
  c.short_title = "pressure, friction [MPa] along the arc";
  c.table = kProfileTable;
  c.x = "x";
  c.x_title = "x [mm]";
  c.left_title = "stress on the slab [MPa]";
  c.lines = {{"pressure", "pressure", 1, false, 0}, {"shear", "friction stress (+: toward the exit)", 1, false, 2}};
  return c;
}

nlohmann::json rolling_summary(const RollingPass& pass, int dim, const RollingResults& r) {
  nlohmann::json out, units;
  for (const RollingMeasure& m : rolling_measures()) {
    const Measure shown = m.in(dim);
    if (shown.name == "travel" || (m.thermal && !r.thermal)) continue;
    out[shown.name] = r.steady.*m.field;  // a 3D contact is an area: contact_area (RollingMeasure::in)
    units[shown.name] = shown.unit;
  }
  out["bite_increment"] = r.bite_increment;
  out["steady_state_increment"] = r.steady_state_increment;
  out["units"] = units;
  out["values"] =
      r.steady_state_increment ? "travel-weighted mean from the steady state on" : "last increment (not steady)";
  out["theory"] = theory_section(pass);
  return out;
}

std::vector<std::string> rolling_report(const RollingPass& pass, int dim, const RollingResults& r) {
  if (r.increments.empty()) return {};
  const RollingIncrement& s = r.steady;
  const RollingTheory t = rolling_theory(pass);
  const bool plane = dim == 2;
  const char* force = plane ? "N/mm" : "N";
  const char* torque = plane ? "N·mm/mm" : "N·mm";
  char state[120];
  if (r.steady_state_increment)
    std::snprintf(state, sizeof state, "steady from %.4g mm of travel: means from there on",
                  r.increments[static_cast<size_t>(r.steady_state_increment - 1)].travel);
  else
    std::snprintf(state, sizeof state, "last completed increment, %.4g mm of travel: not steady yet",
                  r.increments.back().travel);
  char line[600];
  std::vector<std::string> lines;
  std::snprintf(line, sizeof line,
                "rolling: roll force %.4g %s, torque %.4g %s, forward slip %.2f %%, exit thickness %.3f mm, slab "
                "volume change %.1e (%s; rolling.csv, contact_profile.csv and their PNG plots)",
                s.roll_force, force, s.roll_torque, torque, 100 * s.forward_slip, s.exit_thickness, s.volume_change,
                state);
  lines.emplace_back(line);
  std::snprintf(line, sizeof line,
                "rolling: Sims (sticking friction): roll force %.4g %s, torque %.4g %s, forward slip %.2f %%",
                t.sims_force, force, t.sims_torque, torque, 100 * t.sims_forward_slip);
  lines.emplace_back(line);
  if (plane) return lines;
  std::snprintf(line, sizeof line,
                "rolling: spread %.3g mm at the widest point, %.3g mm of the mean width; Wusatowski %.3g mm", s.spread,
                s.mean_spread, t.wusatowski_spread);
  lines.emplace_back(line);
  return lines;
}

ProcessResults rolling_results(const RollingPass& pass, int dim, const RollingResults& r) {
  ProcessResults p;
  p.process = "rolling";
  p.clock = {"travel", "length", pass.travel};
  p.tables = {history_table(r, dim), profile_table(r)};
  p.charts = {history_chart(pass, dim, r, true), profile_chart()};
  p.summary = rolling_summary(pass, dim, r);
  p.report = rolling_report(pass, dim, r);
  // the roll gap: from two contact lengths before the exit plane to one after it, the slab's half thickness and a
  // margin above it (the roll's lowest part), its whole modelled width
  const double contact = rolling_theory(pass).contact_length, h = pass.entry_thickness / 2;
  const double up = h + 0.5 * contact;
  std::array<double, 6> box{-2 * contact, contact, 0, up, 0, 0};
  if (dim == 3) box = {-2 * contact, contact, pass.half_width ? 0 : -pass.width / 2, pass.width / 2, 0, up};
  p.view = {box, "plastic_strain", true};
  return p;
}

}  // namespace rollsim
