#include "process/rolling/RollingFacts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "process/rolling/RollingMeasures.h"
#include "process/rolling/RollingTheory.h"

namespace rollsim {

namespace {
template <typename... Args>
std::string format(const char* f, Args... args) {
  char s[240];
  std::snprintf(s, sizeof s, f, args...);
  return s;
}

ProcessFact bite(const RollingPass& pass, double alpha) {
  if (pass.friction < 0) return {"bites", "yes", "sticking friction draws the slab in at any bite angle"};
  const double need = std::tan(alpha);
  if (pass.friction >= need)
    return {"bites", "yes", format("friction coefficient μ = %.3g ≥ tan α = %.3f", pass.friction, need)};
  return {"bites", "no",
          format("μ = %.3g < tan α = %.3f: the run ends no_bite before anything is solved", pass.friction, need), true};
}

/// Force and torque of the closed forms, per unit width in 2D (and over the slab's width, plane strain).
void loads(const RollingPass& pass, const RollingTheory& t, int dim, std::vector<ProcessFact>& facts) {
  if (dim == 2) {
    facts.push_back({"roll force (Sims)", format("%.4g kN/mm", t.sims_force / 1e3),
                     format("per unit width; %.3g MN over the slab's %g mm (plane strain, sticking friction)",
                            t.sims_force * pass.width / 1e6, pass.width)});
    facts.push_back(
        {"roll torque (Sims)", format("%.4g kN·m/mm", t.sims_torque / 1e6),
         format("per roll and unit width; %.3g MN·m over the slab's width", t.sims_torque * pass.width / 1e9)});
  } else {
    facts.push_back({"roll force (Sims)", format("%.4g MN", t.sims_force / 1e6),
                     "over the slab's width, plane strain, sticking friction"});
    facts.push_back({"roll torque (Sims)", format("%.4g MN·m", t.sims_torque / 1e9), "per roll"});
  }
}

/// With a roll speed: surface speed, time in the gap, mean strain rate, time of the pass, roll power.
void speed(const RollingPass& pass, const RollingTheory& t, int dim, std::vector<ProcessFact>& facts) {
  if (pass.rpm <= 0) return;
  const double omega = pass.rpm * 2 * M_PI / 60, v = omega * pass.radius;  // [1/s], [mm/s]
  const double strain = 2 / std::sqrt(3.0) * std::log(pass.entry_thickness / pass.exit_thickness);
  facts.push_back({"roll surface speed", format("%.3g m/s", v / 1e3), format("ωR at %g rpm", pass.rpm)});
  facts.push_back({"time in the roll gap", format("%.3g ms", 1e3 * t.contact_length / v), "L / v"});
  facts.push_back({"mean strain rate", format("%.3g 1/s", strain * v / t.contact_length),
                   "equivalent (von Mises, plane strain): (2/√3) ln(h0/h1) · v / L"});
  facts.push_back({"time of the pass", format("%.3g s", std::min(pass.travel, travel_through(pass)) / v),
                   "the travel the run covers / v"});
  const double power = t.sims_torque * omega / 1e6;  // [kW] (N·mm/s = 1e-6 kW)
  facts.push_back(
      {"roll power (Sims)", dim == 2 ? format("%.4g kW/mm", power) : format("%.4g kW", power),
       dim == 2 ? format("torque × ω per roll and unit width; %.3g MW over the slab's width", power * pass.width / 1e3)
                : "torque × ω per roll"});
}
/// A profiled roll: the radius's change across the slab and the exit thickness it leaves there.
void profile(const RollingPass& pass, std::vector<ProcessFact>& facts) {
  if (pass.profile.points.empty()) return;
  const double edge = pass.width / 2;
  double low = std::min(pass.profile.at(0), pass.profile.at(edge)),
         high = std::max(pass.profile.at(0), pass.profile.at(edge));
  for (const auto& [y, change] : pass.profile.points)
    if (y < edge) low = std::min(low, change), high = std::max(high, change);
  const double h1 = pass.exit_thickness;
  facts.push_back({"roll profile", format("Δr %.3g to %.3g mm", low, high),
                   format("across the slab's width: it leaves %.4g to %.4g mm thick (the roll's flattening aside)",
                          h1 - 2 * high, h1 - 2 * low)});
}
}  // namespace

std::vector<ProcessFact> rolling_facts(const RollingPass& pass, int dim) {
  const RollingTheory t = rolling_theory(pass);
  const double h0 = pass.entry_thickness, h1 = pass.exit_thickness;
  std::vector<ProcessFact> facts;
  facts.push_back({"reduction", format("%.1f %%", 100 * (h0 - h1) / h0), format("h0 %g → h1 %.4g mm", h0, h1)});
  facts.push_back({"roll", format("Ø %g mm", 2 * pass.radius),
                   format("R = %g mm", pass.radius) +
                       (pass.roll_fixed ? "; its mesh fixed, its surface turning: linear, factored once" : "")});
  facts.push_back({"bite angle", format("%.2f°", t.bite_angle * 180 / M_PI), "cos α = 1 − Δh / 2R"});
  facts.push_back({"contact length", format("%.1f mm", t.contact_length), "projected arc √(R Δh)"});
  facts.push_back(bite(pass, t.bite_angle));
  profile(pass, facts);
  if (!pass.flow_law.empty())
    facts.push_back(
        {"slab flow stress", format("%.4g MPa", pass.flow_stress),
         format("the %s law's mean over ε 0 → %.3f at ε̇ %.3g 1/s and %g °C (Sims's k = σ̄/√3)", pass.flow_law.c_str(),
                2 / std::sqrt(3.0) * std::log(h0 / h1), pass.mean_strain_rate, pass.temperature)});
  loads(pass, t, dim, facts);
  speed(pass, t, dim, facts);
  for (size_t k = 0; k < pass.schedule.size(); ++k)  // a schedule: the facts above are its first pass's
    facts.push_back({"pass " + std::to_string(k + 1), pass.schedule[k].first, pass.schedule[k].second});
  if (pass.ale) {  // the slab never runs out: the window is held while its material flows through
    const double column = (pass.ale_entry + pass.ale_exit) / std::max(pass.ale_columns, 1);
    const std::string grown =
        pass.ale_grading == 1 ? "" : format(" over the arc, growing by %g away from it", pass.ale_grading);
    facts.push_back(
        {"ALE window",
         format("x %.4g to %.4g mm, columns %.3g mm apart%s", -pass.ale_entry, pass.ale_exit, column, grown.c_str()),
         format("the slab's mesh held around the gap (exit plane at 0), its material flowing through; "
                "steps of up to half a column (%.3g mm of travel) bring no node into the arc",
                column / 2)});
    if (pass.stop_at_steady)
      facts.push_back({"end of the pass", format("travel ≈ %.0f mm", earliest_steady_travel(pass)),
                       shape_steady(pass) ? "steady at the earliest once the window's first material has left it "
                                            "(its length) and its side's spread has settled"
                                          : "steady at the earliest after two windows of half a contact length"});
    return facts;
  }
  const double through = travel_through(pass);
  if (through < pass.travel)
    facts.push_back({"end of the pass", format("travel ≈ %.0f of %g mm", through, pass.travel),
                     "the slab's rear end enters the roll gap there, and the run ends"});
  return facts;
}

}  // namespace rollsim
