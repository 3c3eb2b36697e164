#include "process/rolling/RollingProcess.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "base/SchemaFields.h"
#include "material/FlowStress.h"
#include "mesh/StructuredBlock.h"
#include "process/rolling/RollingHeat.h"
#include "process/rolling/RollingReport.h"
#include "process/rolling/RollingRun.h"
#include "process/rolling/RollingSchedule.h"

namespace rollsim {

namespace {
using namespace schema;

/// A number in (lo, hi] with its default.
Field number(std::string name, std::string unit, double d, double lo, double hi, std::string doc) {
  Field f = def(bounded(num(std::move(name), std::move(unit), std::move(doc)), lo, hi), d);
  f.min_exclusive = true;
  return f;
}
/// Poisson's ratio of a body of the pass. Metals are 0.26–0.35; the bound keeps a margin from 0.5, where the bulk
/// modulus is infinite (ν = 0.5 crashed the slab's Hencky update and made the roll's residual non-finite): at 0.49
/// the bulk modulus is 50 times the shear modulus. The slab's plastic flow is isochoric whatever ν (F-bar).
Field poisson(std::string name, std::string doc) {
  return number(std::move(name), "-", 0.3, -1, 0.49, std::move(doc) + " (−1 < ν ≤ 0.49; metals 0.26–0.35)");
}
Field count(std::string name, int d, std::string doc) {
  return def(schema::count(std::move(name), std::move(doc), 1e5), d);
}
/// A field without a default: either it or another field gives the value.
Field optional(Field f) {
  f.default_value = nullptr;
  return f;
}
}  // namespace

namespace {
const ObjectSchema& profile_point_schema() {
  static const ObjectSchema s{
      "roll profile point",
      "The roll radius's change at one distance from the barrel's centre.",
      {req([] {
         Field f = num("y", "length", "distance from the barrel's centre (the pass's width symmetry plane)");
         f.min = 0.0;
         return f;
       }()),
       req(num("radius_change", "length", "change of the radius from roll_radius there (≤ 0)"))},
      "",
      {}};
  return s;
}
}  // namespace

const ObjectSchema& rolling_process_schema() {
  static const ObjectSchema s{
      "rolling process",
      "A flat-rolling pass. Generates bodies `slab` (J2-plastic, finite strain, F-bar) and `roll` (elastic, finite "
      "strain), their materials, the contact `roll-slab` (slave: the slab's top, master: the roll's surface; large "
      "sliding) and the conditions: slab mid-plane symmetry (and width symmetry y = 0 in 3D) and the roll's hub "
      "turned as a rigid body about the roll's axis, so that its surface travels `travel` in increments of "
      "`travel_increment` (they set analysis.increments). Entry: the slab starts pre-bitten — its front end lies at "
      "the exit plane with its top cut to the roll's surface over the arc of contact, touching the roll along the "
      "whole arc, as a pusher would leave it once the roll grips; its rear end is free, so only friction draws it "
      "in. The run ends, converged and saying why, once the slab's rear end enters the roll gap, whatever travel "
      "is left. Units: mm and MPa (N/mm²).",
      {number("slab_length", "length", 300, 0, 1e6, "slab length along x (rolling direction)"),
       number("slab_width", "length", 350, 0, 1e6, "slab width (3D: along y; half is modelled)"),
       number("slab_thickness", "length", 100, 0, 1e6, "entry thickness h0 (half is modelled)"),
       optional(number("roll_radius", "length", 0, 0, 1e6, "roll radius R (default 300; or give roll_diameter)")),
       optional(number("roll_diameter", "length", 0, 0, 2e6, "roll diameter 2R, instead of `roll_radius`")),
       optional(number("roll_speed", "rpm", 0, 0, 1e4,
                       "roll speed [revolutions per minute]: the surface speed ωR, the time of the pass, the mean "
                       "strain rate and the roll power (torque × ω) follow from it; it sets analysis.duration, the "
                       "time a rate-dependent slab_flow_stress needs (without it: travel only)")),
       number("roll_hub_radius", "length", 150, 0, 1e6,
              "inner radius of the modelled roll ring (the hub, turned as a rigid body)"),
       number("barrel_width", "length", 400, 0, 1e6, "roll barrel width (3D; half is modelled)"),
       objects("roll_profile", profile_point_schema(),
               "3D: a crowned or grooved roll — the radius's change across the barrel by distance from its centre, "
               "linear between points and constant beyond them: a crown falls toward the edges (e.g. −0.2 mm "
               "there), a groove dips. roll_radius is the largest radius: every change ≤ 0, one of them 0; the exit "
               "thickness (or reduction) is the gap there, and the slab leaves thicker where the roll is smaller. "
               "Sampled at the roll's axial nodes (roll_n_axial over the half barrel): place them on the profile's "
               "corners. Empty: a straight barrel"),
       optional(number("reduction", "-", 0, 0, 0.9,
                       "thickness reduction (h0 − h1) / h0 (default 0.132, the paper's; or give exit_thickness)")),
       optional(number("exit_thickness", "length", 0, 0, 1e6,
                       "exit thickness h1 of the whole slab, instead of `reduction` (at least 10 % of h0, below it)")),
       count("slab_nx", 48, "slab elements along the length"),
       [] {
         Field f = number("grading", "-", 1, 1, 2,
                          "size ratio of each slab element along the length to its neighbour nearer the roll gap "
                          "(the slab's front end, where the roll touches it): the elements shrink geometrically "
                          "toward the gap, same count and length (1: uniform). The roll's circumferential spacing "
                          "stays uniform: its closed ring, graded from both sides toward the contact angle, would "
                          "span r^(n/2 − 1) between element sizes");
         f.min_exclusive = false;
         return f;
       }(),
       count("slab_nt", 8, "slab elements across the half thickness"),
       [] {
         Field f = number("thickness_grading", "-", 1, 1, 4,
                          "size ratio of each slab element across the thickness to its neighbour nearer the top "
                          "surface: the elements shrink geometrically toward the roll, same count (1: uniform) — "
                          "where heat_transfer's chill and the friction's shear are steepest");
         f.min_exclusive = false;
         return f;
       }(),
       count("slab_nw", 8, "slab elements across the half width (3D)"),
       count("roll_n_around", 120, "roll elements around the circumference"),
       count("roll_n_radial", 6, "roll elements across the ring"),
       count("roll_n_axial", 8, "roll elements along the half barrel (3D)"),
       number("slab_E", "stress", 1e5, 0, 1e12, "slab Young's modulus (hot steel)"),
       number("slab_yield_stress", "stress", 100, 0, 1e12, "slab flow stress σ_0 (hot steel near 1100 °C)"),
       [] {
         Field f =
             number("slab_hardening", "stress", 0, 0, 1e12, "slab linear hardening modulus H (0: perfectly plastic)");
         f.min_exclusive = false;
         return f;
       }(),
       [] {
         Field f = object("slab_flow_stress", flow_stress_schema(),
                          "the slab's flow stress law σ_f(ε, ε̇, T) (materials[].flow_stress: hensel_spittel, shida, "
                          "johnson_cook), instead of slab_yield_stress and slab_hardening; Sims's force and a Coulomb "
                          "pass's shear limit take its mean over the pass (at the mean strain rate, which needs "
                          "roll_speed when the law depends on it)");
         f.default_value = json();
         return f;
       }(),
       optional(number("slab_temperature", "°C", 0, -273.15, 5000,
                       "the slab's initial temperature, uniform (default 1100), with slab_flow_stress or "
                       "heat_transfer: constant unless plastic work (slab_heat_capacity) or heat_transfer change it")),
       optional(number("slab_heat_capacity", "stress/K", 0, 0, 1e3,
                       "the slab's volumetric heat capacity ρc (MPa/K; hot steel about 4.9, the default with "
                       "heat_transfer): with it, plastic work heats the slab (β = 0.9) — adiabatically, or "
                       "conducted with heat_transfer — and slab_flow_stress softens with it")),
       [] {
         Field f = object("heat_transfer", rolling_heat_schema(),
                          "heat in the pass: conduction in slab and roll, the contact's conductance, air cooling, "
                          "plastic and friction heat (needs roll_speed); absent: no conduction");
         f.default_value = json();
         return f;
       }(),
       poisson("slab_nu", "slab Poisson's ratio"),
       choice("roll", {"elastic", "rigid"}, "elastic",
              "the roll: elastic (its hub turned, the ring deforms: roll flattening) or rigid (every node of the ring "
              "turned as one body; nothing of the roll is factored: faster, and beside an elastic run a measure of "
              "what flattening changes)"),
       choice("roll_mesh", {"turning", "fixed"}, "turning",
              "the roll's mesh: turning with its hub (finite kinematics: its tangent assembled and factored anew as "
              "it turns) or fixed in place while its surface's material turns (contacts[].master_turns: an Eulerian "
              "roll — its elastic field is steady in space — with small kinematics: an elastic roll is assembled "
              "and factored once). Not with heat_transfer: the roll's heat would stay where its mesh is"),
       def(boolean(
               "width_symmetry",
               "3D: model half the width, with a symmetry plane at y = 0 (the pass is symmetric about it). false: the "
               "whole width, slab and roll mirrored (twice the elements of slab_nw and roll_n_axial), held in y only "
               "along the slab's centre line — what the symmetry saves, and a check of it"),
           true),
       number("roll_E", "stress", 2.1e5, 0, 1e12, "roll Young's modulus"),
       poisson("roll_nu", "roll Poisson's ratio"),
       choice("friction", {"sticking", "coulomb", "frictionless"}, "sticking",
              "roll–slab friction: sticking (the paper's: a point in contact holds to the roll and never slips; "
              "the friction stress is limited by the slab's surface layer yielding in shear at k = σ_0/√3, as the "
              "slab method's sticking friction assumes), coulomb (μ = friction_coefficient, capped at k) or "
              "frictionless. A pass whose μ is below tan α (the bite "
              "angle: cos α = 1 − Δh / 2R), or frictionless, ends `no_bite` before anything is solved"),
       [] {
         Field f = number("friction_coefficient", "-", 0, 0, 10,
                          "Coulomb's μ (friction: coulomb only, default 0.3; refused with sticking or frictionless, "
                          "where it would have no effect)");
         f.min_exclusive = false;
         f.default_value = nullptr;
         return f;
       }(),
       optional(number("slip_tolerance", "-", 0.005, 0, 0.1,
                       "friction: coulomb only, default 0.005: the roll–slab pair's elastic slip as a fraction of a "
                       "contact point's facet size (contacts[].slip_tolerance: a slipping point's friction force "
                       "points along its trial force; smaller is nearer Coulomb's law)")),
       choice("sliding", {"large", "large_every_iteration"}, "large",
              "the roll–slab pair's large sliding (contacts[].sliding): searched where each step begins, or at every "
              "Newton iteration (then with the contact's geometric stiffness, analysis.contact_tangent)"),
       number("travel", "length", 100, 0, 1e6,
              "distance the roll's surface travels over the analysis (the roll turns travel / R)"),
       number("travel_increment", "length", 2, 0, 1e6, "roll surface travel per increment"),
       choice("formulation", {"lagrangian", "ale"}, "lagrangian",
              "how the slab's mesh moves: lagrangian (with the material: the whole slab_length is rolled through the "
              "gap, its front from the exit plane on) or ale (arbitrary Lagrangian–Eulerian, one pass: "
              "the mesh is a window held around the roll gap, from ale_entry_length before the exit plane to "
              "ale_exit_length past it, cut to the roll over the arc and flat at the gap past it; the material "
              "flows through — after each step the nodes go back to their x, the top following the free surface or "
              "the roll, the state is advected and virgin material flows in at the entry — so the steady state "
              "comes without rolling a whole slab; slab_length and grading have no effect)"),
       optional(number("ale_entry_length", "length", 0, 0, 1e6,
                       "formulation ale: how far before the exit plane the window begins (default: the nominal "
                       "contact length √(R Δh) plus half the entry thickness h0 in plane strain, h0 in 3D)")),
       optional(number("ale_exit_length", "length", 0, 0, 1e6,
                       "formulation ale: how far past the exit plane the window ends (default: about half the "
                       "entry thickness h0 in plane strain, h0 in 3D; without ale_entry_length the columns are "
                       "spaced so that one lies half a spacing before the arc's nominal entry — steps of up to about "
                       "half a spacing then bring no column into the arc — and the arc holds a whole number of "
                       "spacings and a quarter, no column just before the exit plane, where the material leaves the "
                       "roll; with it, the first of the two)")),
       [] {
         Field f = number("ale_grading", "-", 1, 1, 2,
                          "formulation ale: the size ratio of neighbouring columns in the window's zones before the "
                          "arc and past the exit plane, growing away from it (1: uniform). The arc keeps the spacing "
                          "of the uniform window of slab_nx columns, from the column before its entry to the second "
                          "past the exit plane; the zones, elastic before the arc and nearly rigid past it, take "
                          "fewer columns");
         f.min_exclusive = false;
         return f;
       }(),
       def(boolean("stop_at_steady_state",
                   "end the pass once it is steady — the means of roll force and torque over the last two windows of "
                   "half a nominal contact length of travel agree within 2 % (results.rolling's steady_state rule) — "
                   "whatever travel is left, converged, saying so"),
           false),
       [] {
         Field f = objects("passes", pass_schema(),
                           "a schedule (plane strain): passes one after the other, each receiving the slab the pass "
                           "before left — its exit thickness, length, plastic strain and temperature profiles — after "
                           "its interpass_time in air; each pass's results in pass-<n>/, the schedule's in "
                           "schedule.csv and schedule.png. The section's reduction and exit_thickness then belong to "
                           "the passes");
         f.default_value = json();
         return f;
       }(),
       str("slab_partition", "subdomains of the slab for `feti` (as bodies[].partition)"),
       vec("slab_partition_map", "",
           "explicit element → subdomain map of the slab (as bodies[].partition_map, e.g. painted in the window)", -1)},
      "",
      {}};
  return s;
}

namespace {
constexpr double kPaperReduction = 0.132;
constexpr double kDefaultFriction = 0.3;  // Coulomb's μ when process.friction_coefficient is not given

constexpr double kDefaultRollRadius = 300;
double friction_coefficient(const json& p) { return p.value("friction_coefficient", kDefaultFriction); }

/// R: roll_radius, half of roll_diameter, or 300 mm when neither is given.
double roll_radius(const json& p) {
  if (p.contains("roll_diameter")) return p.at("roll_diameter").get<double>() / 2;
  return p.value("roll_radius", kDefaultRollRadius);
}

bool half_width(const json& process) { return process.value("width_symmetry", true); }

constexpr double kDefaultSlabTemperature = 1100;  // [°C]

/// The slab's material: J2 with slab_yield_stress and slab_hardening, or with slab_flow_stress, at slab_temperature,
/// heated by its plastic work with slab_heat_capacity.
MaterialData slab_material_data(const json& p) {
  MaterialData m;
  m.E = p.at("slab_E"), m.nu = p.at("slab_nu");
  if (p.contains("slab_flow_stress"))
    m.flow_stress = flow_stress_data(p.at("slab_flow_stress"));
  else
    m.yield_stress = p.at("slab_yield_stress"), m.hardening_modulus = p.at("slab_hardening");
  m.temperature = p.value("slab_temperature", kDefaultSlabTemperature);
  m.heat_capacity = p.value("slab_heat_capacity", 0.0);
  return m;
}

bool is_ale(const json& p) { return p.value("formulation", "lagrangian") == "ale"; }

/// The nominal contact length √(R Δh), Δh = h0 − h1.
double nominal_contact_length(const json& p);

/// Where the ALE window's columns lie by default against the arc's nominal entry and the exit plane, in shares of a
/// column spacing: one column half a spacing before the entry (steps of up to about half a spacing bring no node of it
/// into the arc; the next column, half a spacing inside the arc, lies on the roll), and the spacing such that the arc
/// holds a whole number of spacings and a quarter, so that the last column on the arc lies 3/4 of a spacing before the
/// exit plane and the next a quarter past it. A column at the entry diverged; a quarter of a spacing before it was
/// put onto the roll in longer steps; at 3/4 the column a quarter inside the arc added 1 % of volume to the window.
/// A column within about a millimetre before the exit plane, where the material leaves the roll, went in and out of
/// contact at every iteration (4 mm columns, 1 mm steps: 1178 Newton iterations instead of about 300; the force 1 %
/// off) (docs/BENCHMARKS-ROLLING.md).
constexpr double kEntryOffset = 0.5, kArcRemainder = 0.25;

/// How far the ALE window reaches before the arc and past the exit plane by default, in entry thicknesses h0. In plane
/// strain the paper's pass gave the same steady force within 0.1 % with h0 / 4, h0 / 2 and h0 on both sides (64 × 12
/// elements' spacing): what lies further is elastic and only costs elements. In 3D the zones change the spread: on
/// the 16 × 8 × 4 elements' spacing the mean spread was 1.45 mm with h0 on both sides, 3.55 with h0 / 2 before the
/// arc (the material bulging sideways before the arc reaches the entry face and flows in wider) and 1.90 with h0 / 2
/// past the exit (docs/BENCHMARKS-ROLLING.md).
double zone_thickness(int dim) { return dim == 2 ? 0.5 : 1.0; }

/// The ALE window's reach before and past the exit plane: ale_entry_length and ale_exit_length, by default about
/// zone_thickness h0 before the arc and past the exit plane with the columns placed as kEntryOffset and kArcRemainder
/// say (with ale_entry_length alone: the first only).
std::pair<double, double> ale_window(const json& p, int dim) {
  const double h0 = p.at("slab_thickness"), arc = nominal_contact_length(p), zone = zone_thickness(dim) * h0;
  const int nx = p.at("slab_nx");
  // about `spacings`, at least one and a whole number plus `share`
  const auto placed = [](double spacings, double share) { return std::max(1.0, std::round(spacings - share)) + share; };
  if (!p.contains("ale_entry_length")) {
    const double spacing = arc / placed(arc / ((arc + 2 * zone) / nx), kArcRemainder);
    const double zones = nx - arc / spacing;  // the spacings before the arc and past it, about as many on each side
    const double entry = arc + placed(zones / 2, kEntryOffset) * spacing;
    return {entry, p.contains("ale_exit_length") ? p.at("ale_exit_length").get<double>()
                                                 : std::max(nx * spacing - entry, spacing)};
  }
  const double entry = p.at("ale_entry_length");
  if (p.contains("ale_exit_length")) return {entry, p.at("ale_exit_length").get<double>()};
  const double before = entry - arc, spacing = (entry + zone) / nx;  // the columns before the arc, at about zone past
  return {entry, std::max(nx * before / placed(before / spacing, kEntryOffset) - entry, spacing)};
}

/// A zone of length `length` beside the arc's uniform columns (spacing h), its elements growing by `ratio` from h ·
/// ratio at the arc outward, scaled to fit: their sizes, nearest the arc first.
std::vector<double> growing_zone(double length, double h, double ratio) {
  if (length <= 1e-9 * h) return {};
  const double k = std::log1p(length * (ratio - 1) / (h * ratio)) / std::log(ratio);  // h r (r^k − 1)/(r − 1) = L
  const int n = std::max(1, static_cast<int>(std::lround(k)));
  std::vector<double> sizes;
  double sum = 0;
  for (int i = 1; i <= n; ++i) sum += sizes.emplace_back(h * std::pow(ratio, i));
  for (double& s : sizes) s *= length / sum;
  return sizes;
}

/// The ALE window's column planes along x, from −entry to exit: uniform (slab_nx of them), or with ale_grading r > 1
/// the uniform layout's spacing h kept over the arc — from the column before its entry to the second past the exit
/// plane, where the material leaves the roll and springs back — and the zones before and past it in elements
/// growing by r from there (the zones are elastic or nearly rigid: the arc's gradients are what need the columns).
std::vector<double> ale_planes(const json& p, int dim) {
  const auto [entry, exit] = ale_window(p, dim);
  const int nx = p.at("slab_nx");
  const double h = (entry + exit) / nx, r = p.value("ale_grading", 1.0);
  std::vector<double> uniform;
  for (int i = 0; i <= nx; ++i) uniform.push_back(-entry + (entry + exit) * i / nx);
  if (r == 1.0) return uniform;
  const double arc = nominal_contact_length(p), tol = 1e-6 * h;
  const auto first = std::find_if(uniform.rbegin(), uniform.rend(), [&](double x) { return x <= -arc - tol; });
  const auto last = std::find_if(uniform.begin(), uniform.end(), [&](double x) { return x >= h - tol; });
  const double from = first == uniform.rend() ? -entry : *first, to = last == uniform.end() ? exit : *last;
  std::vector<double> planes{-entry};
  const std::vector<double> before = growing_zone(from + entry, h, r);
  for (auto s = before.rbegin(); s != before.rend(); ++s) planes.push_back(planes.back() + *s);
  planes.back() = from;
  for (double x : uniform)
    if (x > from + tol && x < to - tol) planes.push_back(x);
  if (to > from + tol) planes.push_back(to);
  for (double s : growing_zone(exit - to, h, r)) planes.push_back(planes.back() + s);
  planes.back() = exit;
  return planes;
}

/// ω R [length/s], 0 without a roll speed.
double surface_speed(const json& p) { return p.value("roll_speed", 0.0) * 2 * M_PI / 60 * roll_radius(p); }

/// The pass's time, travel / ωR [s] (analysis.duration); 0 without a roll speed.
double pass_duration(const json& p) {
  const double v = surface_speed(p);
  return v > 0 ? p.at("travel").get<double>() / v : 0.0;
}

RadiusProfile roll_profile(const json& p) {
  RadiusProfile profile;
  for (const json& point : p.value("roll_profile", json::array()))
    profile.points.emplace_back(point.at("y").get<double>(), point.at("radius_change").get<double>());
  return profile;
}

/// The whole exit thickness h1: exit_thickness, or h0 (1 − reduction), the paper's reduction when neither is given.
double exit_thickness(const json& p) {
  if (p.contains("exit_thickness")) return p.at("exit_thickness").get<double>();
  return p.at("slab_thickness").get<double>() * (1 - p.value("reduction", kPaperReduction));
}

double nominal_contact_length(const json& p) {
  return std::sqrt(roll_radius(p) * (p.at("slab_thickness").get<double>() - exit_thickness(p)));
}

/// The pass's equivalent strain (2/√3) ln(h0/h1) (plane strain) and its mean rate over the arc √(R Δh) at ωR.
std::pair<double, double> pass_strain_and_rate(const json& p) {
  const double h0 = p.at("slab_thickness"), h1 = exit_thickness(p);
  const double strain = 2 / std::sqrt(3.0) * std::log(h0 / h1);
  return {strain, strain * surface_speed(p) / nominal_contact_length(p)};
}

}  // namespace

double pass_flow_stress(const json& p, double strain_before) {
  const MaterialData m = slab_material_data(p);
  if (m.flow_stress.law.empty()) return m.yield_stress;
  const auto flow = make_flow_stress(m);
  const auto [strain, rate] = pass_strain_and_rate(p);
  constexpr int n = 64;
  double sum = 0;
  for (int i = 0; i <= n; ++i)
    sum += (i == 0 || i == n ? 1
            : i % 2          ? 4
                             : 2) *
           flow->at(strain_before + strain * i / n, rate, m.temperature).stress;
  return sum / (3 * n);
}

namespace {
std::string mm(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%g mm", v);
  return s;
}

/// Keys and entries the pass would ignore: refused, so that nothing the user wrote is silently dropped.
void check_ignored(const json& project, std::vector<Issue>& issues) {
  const json& p = project.at("process");
  if (p.contains("friction_coefficient") && p.at("friction") != "coulomb")
    issues.push_back(
        {"process.friction_coefficient", "has no effect with process.friction: " + p.at("friction").get<std::string>() +
                                             " (μ is Coulomb's: set process.friction to coulomb, or remove it)"});
  if (p.contains("slip_tolerance") && p.at("friction") != "coulomb")
    issues.push_back(
        {"process.slip_tolerance", "has no effect with process.friction: " + p.at("friction").get<std::string>() +
                                       " (only Coulomb's points slip: set process.friction to coulomb, "
                                       "or remove it)"});
  if (p.contains("slab_flow_stress")) {
    if (p.at("slab_hardening").get<double>() > 0)
      issues.push_back({"process.slab_hardening",
                        "has no effect with process.slab_flow_stress (its law hardens the "
                        "slab): remove one"});
    if (p.at("slab_yield_stress") != find_field(rolling_process_schema(), "slab_yield_stress")->default_value)
      issues.push_back({"process.slab_yield_stress",
                        "has no effect with process.slab_flow_stress (its law gives "
                        "the slab's yield stress): remove one"});
  } else if (p.contains("slab_temperature") && !p.contains("heat_transfer")) {
    issues.push_back({"process.slab_temperature",
                      "has no effect without process.slab_flow_stress or process.heat_transfer "
                      "(slab_yield_stress does not depend on temperature): give the slab a flow stress law"});
  }
  if (p.at("roll_mesh") == "fixed" && p.contains("heat_transfer"))
    issues.push_back({"process.roll_mesh",
                      "fixed is not for a pass with heat_transfer: the roll's heat would stay "
                      "where its mesh is, not turn with its surface (set it to turning)"});
  if (p.at("roll_mesh") == "fixed" && project.at("analysis").value("remesh_quality", 0.0) > 0)
    issues.push_back({"process.roll_mesh",
                      "fixed is not for a pass that remeshes (analysis.remesh_quality): a remesh restarts every body "
                      "from its current shape, and the fixed roll, small-strain, would lose its stress (set it to "
                      "turning)"});
  if (project.at("analysis").value("duration", 0.0) > 0)
    issues.push_back({"analysis.duration",
                      "a rolling pass's time follows from process.roll_speed (the travel over "
                      "the roll's surface speed): give that instead"});
  const json& materials = project.at("materials");
  for (size_t i = 0; i < materials.size(); ++i) {
    const std::string name = materials[i].value("name", "");
    bool used = false;
    for (const json& b : project.at("bodies")) used = used || b.value("material", "") == name;
    if (!used)
      issues.push_back({"materials[" + std::to_string(i) + "]",
                        "'" + name +
                            "' is used by no body: a rolling pass makes its own materials from process.slab_E, "
                            "slab_nu, slab_yield_stress, slab_hardening, roll_E and roll_nu (set those instead)"});
  }
}

/// A roll profile: in 3D, within the barrel, by ascending distance, never above roll_radius and reaching it.
void check_profile(const json& project, std::vector<Issue>& issues) {
  const json& p = project.at("process");
  const json& points = p.value("roll_profile", json::array());
  if (points.empty()) return;
  if (project.at("dimension").get<int>() == 2) {
    issues.push_back({"process.roll_profile", "a roll profile varies across the width: 3D only"});
    return;
  }
  const double half_barrel = p.at("barrel_width").get<double>() / 2, R = roll_radius(p);
  for (size_t i = 0; i < points.size(); ++i) {
    const std::string at = "process.roll_profile[" + std::to_string(i) + "]";
    const double y = points[i].at("y"), change = points[i].at("radius_change");
    if (y > half_barrel)
      issues.push_back(
          {at + ".y", mm(y) + " is beyond the barrel's edge (half of process.barrel_width: " + mm(half_barrel) + ")"});
    if (i > 0 && !(y > points[i - 1].at("y").get<double>()))
      issues.push_back({at + ".y", "must be greater than the point before's (the points go from the centre out)"});
    if (change > 0)
      issues.push_back({at + ".radius_change", mm(change) + " is positive: roll_radius is the roll's largest radius "
                                                            "(raise it and lower the others)"});
  }
  const RadiusProfile profile = roll_profile(p);
  bool reaches = false;
  for (const auto& point : profile.points) reaches = reaches || point.second == 0.0;
  if (!reaches)
    issues.push_back({"process.roll_profile",
                      "no point has radius_change 0: roll_radius is the roll's largest "
                      "radius, where the gap is the exit thickness"});
  if (R + profile.lowest() <= p.at("roll_hub_radius").get<double>())
    issues.push_back({"process.roll_profile", "takes the roll's radius down to its hub (process.roll_hub_radius)"});
}

/// An ALE pass: what it cannot do yet, the keys it would ignore, and a window that holds the arc; the ALE keys of a
/// Lagrangian pass.
void check_ale(const json& project, std::vector<Issue>& issues) {
  const json& p = project.at("process");
  if (!is_ale(p)) {
    for (const char* key : {"ale_entry_length", "ale_exit_length"})
      if (p.contains(key))
        issues.push_back({std::string("process.") + key,
                          "has no effect with process.formulation: lagrangian (the "
                          "window is an ALE pass's): set formulation to ale, or "
                          "remove it"});
    if (p.value("ale_grading", 1.0) != 1.0)
      issues.push_back({"process.ale_grading",
                        "has no effect with process.formulation: lagrangian (it grades an ALE window's columns; a "
                        "Lagrangian slab's is process.grading): set formulation to ale, or remove it"});
    return;
  }
  const std::string why = "process.formulation";
  if (p.contains("heat_transfer"))
    issues.push_back({why,
                      "ale does not carry conducted temperatures yet: remove process.heat_transfer, or use "
                      "lagrangian"});
  if (p.at("grading").get<double>() != 1)
    issues.push_back({"process.grading",
                      "has no effect with process.formulation: ale (the window's elements are "
                      "uniform along x): remove it"});
  const auto [entry, exit] = ale_window(p, project.at("dimension").get<int>());
  const double arc = nominal_contact_length(p);
  if (entry <= arc)
    issues.push_back({"process.ale_entry_length", mm(entry) + " does not reach before the arc of contact (it starts " +
                                                      mm(arc) + " before the exit plane): the window must hold it"});
  if (exit <= 0)
    issues.push_back({"process.ale_exit_length", "must be positive: the window must reach past the exit plane"});
}

/// analysis.remesh_quality where a pass cannot take it: an ALE window (placed back after every step) and a schedule
/// (each pass hands on its rolled part by where it lay before the pass, which a remesh moves).
void check_rolling_remesh(const json& project, std::vector<Issue>& issues) {
  const auto a = project.find("analysis");
  if (a == project.end() || a->value("remesh_quality", 0.0) <= 0.0) return;
  const std::string why = "analysis.remesh_quality";
  if (is_schedule(project))
    issues.push_back({why,
                      "a schedule (process.passes) hands each pass's rolled part on by where it lay before the pass, "
                      "which a remesh moves: remove it, or roll the passes one at a time"});
  else if (is_ale(project.at("process")))
    issues.push_back({why,
                      "has no effect with process.formulation: ale (the window's nodes are placed back after every "
                      "step): remove it, or use lagrangian"});
}

/// The generated bodies' geometry, checked in the process's terms (never a generated body's path).
void check_geometry(const json& project, std::vector<Issue>& issues) {
  const json& p = project.at("process");
  const double R = roll_radius(p), hub = p.at("roll_hub_radius");
  const std::string radius = p.contains("roll_diameter") ? "half of process.roll_diameter" : "process.roll_radius";
  if (hub >= R)
    issues.push_back({"process.roll_hub_radius", mm(hub) + " must be smaller than " + radius + " (" + mm(R) +
                                                     "): the hub is the inner edge of the roll's ring"});
  const double W = p.at("slab_width"), barrel = p.at("barrel_width");
  if (project.at("dimension").get<int>() == 3 && W > barrel)
    issues.push_back({"process.slab_width", mm(W) + " is wider than the roll barrel (process.barrel_width: " +
                                                mm(barrel) + "): the slab's edges would pass beside the roll"});
}
/// The slab's flow stress law in the process's terms: its coefficients, a positive flow stress at slab_temperature,
/// and the roll speed a rate-dependent law needs.
void check_slab_law(const json& p, std::vector<Issue>& issues) {
  if (!p.contains("slab_flow_stress")) return;
  const MaterialData slab = slab_material_data(p);
  for (const Issue& i : check_flow_stress(slab, pass_duration(p))) {
    if (i.path == "flow_stress")  // the rate needs time: the roll's speed gives it
      issues.push_back({"process.roll_speed", "is needed: the slab's flow stress law (" + slab.flow_stress.law +
                                                  ") depends on the strain rate, which the roll's speed sets"});
    else if (i.path == "temperature")
      issues.push_back({"process.slab_temperature", i.message});
    else
      issues.push_back({"process.slab_" + i.path, i.message});
  }
}
}  // namespace

void check_rolling(const json& project, std::vector<Issue>& issues) {
  check_rolling_remesh(project, issues);
  if (is_schedule(project)) {
    if (is_ale(project.at("process")))
      issues.push_back({"process.formulation", "ale rolls one pass: a schedule (process.passes) is lagrangian"});
    check_schedule(project, issues);
    return;
  }
  check_ignored(project, issues);
  check_ale(project, issues);
  check_slab_law(project.at("process"), issues);
  check_rolling_heat(project.at("process"), issues);
  check_geometry(project, issues);
  check_profile(project, issues);
  const json& p = project.at("process");
  const double h0 = p.at("slab_thickness").get<double>();
  if (p.contains("roll_radius") && p.contains("roll_diameter"))
    issues.push_back({"process.roll_diameter", "give either process.roll_radius or process.roll_diameter, not both"});
  if (p.contains("reduction") && p.contains("exit_thickness"))
    issues.push_back({"process.exit_thickness", "give either process.reduction or process.exit_thickness, not both"});
  else if (p.contains("exit_thickness") && !(exit_thickness(p) < h0 && exit_thickness(p) >= 0.1 * h0))
    issues.push_back({"process.exit_thickness", "must be below the entry thickness (" + std::to_string(h0) +
                                                    ") and at least 10 % of it (reduction ≤ 0.9)"});
  if (auto why = grading_problem(p.at("grading").get<double>(), p.at("slab_nx").get<int>()); !why.empty())
    issues.push_back({"process.grading", why});
  if (auto why = grading_problem(p.at("thickness_grading").get<double>(), p.at("slab_nt").get<int>()); !why.empty())
    issues.push_back({"process.thickness_grading", why});
  const double travel = p.at("travel").get<double>(), step = p.at("travel_increment").get<double>();
  if (step > travel)
    issues.push_back({"process.travel_increment", "is larger than process.travel (" + std::to_string(travel) + ")"});
  else if (travel / step > 1000)
    issues.push_back(
        {"process.travel_increment", "gives " + std::to_string(std::ceil(travel / step)) +
                                         " increments over process.travel: at most 1000 (analysis.increments)"});
}

namespace {
/// The roll profile at the roll mesh's axial nodes (y from its y0, the change at |y|): what the roll's surface is
/// and what the slab's pre-bitten top is cut to (empty without a profile).
json sampled_profile(const json& p, const json& roll_mesh) {
  const RadiusProfile profile = roll_profile(p);
  json sampled = json::array();
  if (profile.points.empty()) return sampled;
  const int n = roll_mesh.at("n_axial");
  const double y0 = roll_mesh.at("y0"), length = roll_mesh.at("length");
  for (int k = 0; k <= n; ++k) {
    const double y = y0 + length * k / n;
    sampled.push_back({{"y", y}, {"radius_change", profile.at(std::abs(y))}});
  }
  return sampled;
}
}  // namespace

json expand_rolling(const json& project) {
  const json first = is_schedule(project) ? pass_section(project.at("process"), 0) : project.at("process");
  const json& p = first;  // a schedule is shown (checked, meshed, drawn) as its first pass
  const int dim = project.at("dimension").get<int>();
  const double L = p.at("slab_length"), W = p.at("slab_width"), h0 = p.at("slab_thickness");
  const double R = roll_radius(p);
  const double h1 = exit_thickness(p), dh = (h0 - h1) / 2;
  const double axis = h1 / 2 + R;  // roll axis height above the slab's mid-plane
  json out = project;
  // every field written out, defaults included: the generated entries skip schema validation
  json slab_material = {{"name", "slab"}, {"model", "j2_plasticity"}, {"E", p.at("slab_E")}, {"nu", p.at("slab_nu")}};
  if (p.contains("slab_flow_stress")) {
    slab_material["flow_stress"] = p.at("slab_flow_stress");
  } else {
    slab_material["yield_stress"] = p.at("slab_yield_stress");
    if (p.at("slab_hardening").get<double>() > 0) slab_material["hardening_modulus"] = p.at("slab_hardening");
  }
  if (p.contains("slab_heat_capacity")) slab_material["heat_capacity"] = p.at("slab_heat_capacity");
  if (p.contains("slab_flow_stress") || p.contains("slab_heat_capacity") || p.contains("heat_transfer"))
    slab_material["temperature"] = p.value("slab_temperature", kDefaultSlabTemperature);
  out["materials"].push_back(slab_material);
  out["materials"].push_back(
      {{"name", "roll"}, {"model", "linear_elastic"}, {"E", p.at("roll_E")}, {"nu", p.at("roll_nu")}});
  const int around = p.at("roll_n_around");
  const bool fixed_roll = p.at("roll_mesh") == "fixed";  // its contact holds the slab to its circle, not its chords
  // the slab from −L to the exit plane, or an ALE window from −entry to exit, flat at the gap past the exit plane
  const auto [entry, exit] = is_ale(p) ? ale_window(p, dim) : std::pair{L, 0.0};
  json slab_mesh = {{"type", "block"},
                    {"nx", p.at("slab_nx")},
                    {"lx", entry + exit},
                    {"x_grading", p.at("grading")},
                    {"roll_cut", {{"center", {0.0, axis}}, {"radius", R}, {"n_around", fixed_roll ? 0 : around}}}};
  if (is_ale(p)) {
    slab_mesh["roll_cut"]["flat_exit"] = true;
    const std::vector<double> planes = ale_planes(p, dim);
    slab_mesh["nx"] = planes.size() - 1;
    if (p.value("ale_grading", 1.0) != 1.0) slab_mesh["x_planes"] = planes;
  }
  json roll_mesh = {{"inner_radius", p.at("roll_hub_radius")},
                    {"outer_radius", R},
                    {"n_radial", p.at("roll_n_radial")},
                    {"n_around", p.at("roll_n_around")}};
  if (dim == 2) {
    slab_mesh.update({{"ny", p.at("slab_nt")}, {"ly", h0 / 2}, {"origin", {-entry, 0.0}}});
    if (p.at("thickness_grading").get<double>() != 1) slab_mesh["y_grading"] = p.at("thickness_grading");
    roll_mesh.update({{"type", "annulus"}, {"center", {0.0, axis}}});
  } else {
    const int halves = half_width(p) ? 1 : 2;  // the modelled width: half (from y = 0) or whole (about y = 0)
    const double barrel = p.at("barrel_width");
    slab_mesh.update({{"ny", halves * p.at("slab_nw").get<int>()},
                      {"ly", halves * W / 2},
                      {"nz", p.at("slab_nt")},
                      {"lz", h0 / 2},
                      {"origin", {-entry, halves == 1 ? 0.0 : -W / 2, 0.0}}});
    if (p.at("thickness_grading").get<double>() != 1) slab_mesh["z_grading"] = p.at("thickness_grading");
    roll_mesh.update({{"type", "cylinder"},
                      {"center", {0.0, axis}},
                      {"y0", halves == 1 ? 0.0 : -barrel / 2},
                      {"length", halves * barrel / 2},
                      {"n_axial", halves * p.at("roll_n_axial").get<int>()}});
    if (const json sampled = sampled_profile(p, roll_mesh); !sampled.empty()) {
      roll_mesh["outer_profile"] = sampled;
      slab_mesh["roll_cut"]["profile"] = sampled;
    }
  }
  json slab = {{"name", "slab"},         {"material", "slab"}, {"formulation", "bbar"},
               {"kinematics", "finite"}, {"mesh", slab_mesh},  {"node_sets", json::array()}};
  if (dim == 3 && !half_width(p))
    slab["node_sets"].push_back({{"name", "centre_line"},
                                 {"box_min", {-slab_mesh.at("lx").get<double>() - 1, -1e-6 * W, -1e-6 * h0}},
                                 {"box_max", {slab_mesh.at("lx").get<double>() + 1, 1e-6 * W, 1e-6 * h0}}});
  if (p.contains("slab_partition")) slab["partition"] = p.at("slab_partition");
  if (p.contains("slab_partition_map")) slab["partition_map"] = p.at("slab_partition_map");
  out["bodies"].push_back(slab);
  roll_mesh.update({{"start_angle", 0.0}, {"end_angle", 360.0}});
  out["bodies"].push_back({{"name", "roll"},
                           {"material", "roll"},
                           {"formulation", "full"},
                           {"kinematics", fixed_roll ? "small" : "finite"},
                           {"mesh", roll_mesh},
                           {"node_sets", json::array()}});
  const std::string top = dim == 2 ? "ymax" : "zmax", mid = dim == 2 ? "ymin" : "zmin";
  out["contacts"].push_back({{"name", "roll-slab"},
                             {"type", "frictionless"},
                             {"slave_body", "slab"},
                             {"slave_surface", top},
                             {"master_body", "roll"},
                             {"master_surface", "outer"},
                             {"search_distance", 4 * dh + 1e-3 * h0},
                             {"sliding", p.at("sliding")}});
  const std::string friction = p.at("friction");
  out["contacts"].back()["type"] = friction;
  if (friction == "coulomb") out["contacts"].back()["friction"] = friction_coefficient(p);
  if (p.contains("slip_tolerance")) out["contacts"].back()["slip_tolerance"] = p.at("slip_tolerance");
  // Coulomb's friction stress never exceeds the slab's shear yield stress k = σ_0/√3. Sticking has no cap: the slab's
  // surface layer, yielding in shear, is what limits it (a cap made the arc chatter between stick and slip)
  if (friction == "coulomb") out["contacts"].back()["shear_limit"] = pass_flow_stress(p) / std::sqrt(3.0);
  json& bcs = out["boundary_conditions"];
  bcs.push_back({{"type", "symmetry"}, {"body", "slab"}, {"set", mid}, {"normal", dim == 2 ? "y" : "z"}});
  // the hub turns so that the roll's lowest point moves along +x: counter-clockwise about z in 2D, about −y in 3D
  const double turn = p.at("travel").get<double>() / R * 180.0 / M_PI;
  const std::string turned = p.at("roll") == "rigid" ? "all" : "inner";
  // a fixed roll's hub stays (a rotation by 0: its centre and axis are the pass's measures'), its surface turns
  json hub = {{"type", "rotation"}, {"body", "roll"}, {"set", turned}, {"angle", fixed_roll ? 0.0 : turn}};
  if (dim == 2) {
    hub["center"] = {0.0, axis};
  } else {
    hub["center"] = {0.0, 0.0, axis};
    hub["axis"] = {0.0, -1.0, 0.0};
    // the whole width: the centre line (y = 0 on the mid-plane) holds the slab's sideways motion and yaw
    bcs.push_back(
        {{"type", "symmetry"}, {"body", "slab"}, {"set", half_width(p) ? "ymin" : "centre_line"}, {"normal", "y"}});
    // and half the roll: its barrel's centre plane stays in place as the slab's does (left free, the cut face bulged
    // sideways under the arc's pressure: the half-width pass was not the whole width's)
    if (half_width(p) && p.at("roll") != "rigid")
      bcs.push_back({{"type", "symmetry"}, {"body", "roll"}, {"set", "ymin"}, {"normal", "y"}});
  }
  if (fixed_roll) {
    json turns = {{"center", hub.at("center")}, {"angle", turn}};
    if (dim == 3) turns["axis"] = hub.at("axis");
    out["contacts"].back()["master_turns"] = turns;
  }
  bcs.push_back(hub);
  out["analysis"]["increments"] =
      static_cast<int>(std::ceil(p.at("travel").get<double>() / p.at("travel_increment").get<double>() - 1e-9));
  // an ALE window starts stress-free with its exit zone in place: a whole first step takes it to a distorted state
  // on fine meshes (64 × 12), an eighth of one does not; in 3D (24 × 12 × 8) an eighth still did, a 64th does not —
  // the default where the user gave none (the 16 × 8 × 4 window rolls from an eighth and inverts an element at 3.8 mm
  // from a 64th: a 3D window's start is the user's to choose)
  if (is_ale(p) && out["analysis"].value("first_step_halvings", 0) == 0)
    out["analysis"]["first_step_halvings"] = dim == 2 ? 3 : 6;
  if (pass_duration(p) > 0) out["analysis"]["duration"] = pass_duration(p);
  expand_rolling_heat(p, dim, out);
  return out;
}

namespace {
/// Each pass of a schedule in mill terms: its nominal draft, and its roll and time in air before it.
std::vector<std::pair<std::string, std::string>> schedule_facts(const json& section) {
  std::vector<std::pair<std::string, std::string>> out;
  double h = section.at("slab_thickness");
  for (size_t k = 0; k < section.at("passes").size(); ++k) {
    const json s = pass_section(section, k);
    const double h1 =
        s.contains("exit_thickness") ? s.at("exit_thickness").get<double>() : h * (1 - s.at("reduction").get<double>());
    char draft[64], roll[160];
    std::snprintf(draft, sizeof draft, "%.4g → %.4g mm", h, h1);
    std::snprintf(roll, sizeof roll, "%.1f %% nominal, R %g mm, %g rpm, %g s in air before", 100 * (h - h1) / h,
                  roll_radius(s), s.value("roll_speed", 0.0), section.at("passes").at(k).value("interpass_time", 0.0));
    out.emplace_back(draft, roll);
    h = h1;
  }
  return out;
}
}  // namespace

RollingPass rolling_pass(const json& section, const Model& model) {
  const json p = section.contains("passes") ? pass_section(section, 0) : section;
  RollingPass pass;
  auto body = [&](const std::string& name) {
    for (size_t b = 0; b < model.bodies.size(); ++b)
      if (model.bodies[b].name == name) return static_cast<int>(b);
    throw std::logic_error("rolling pass without body '" + name + "'");
  };
  pass.slab = body("slab");
  pass.roll = body("roll");
  for (size_t i = 0; i < model.displacements.size(); ++i)
    if (model.displacements[i].body == pass.roll && model.displacements[i].rotation) pass.hub = static_cast<int>(i);
  pass.thickness_axis = model.dim - 1;
  pass.width_axis = model.dim == 3 ? 1 : -1;
  pass.half_width = model.dim == 3 && half_width(p);
  pass.radius = roll_radius(p);
  pass.slab_length = p.at("slab_length");
  pass.ale = is_ale(p);
  if (pass.ale) {
    std::tie(pass.ale_entry, pass.ale_exit) = ale_window(p, model.dim);
    pass.ale_columns = p.at("slab_nx");
    pass.ale_grading = p.value("ale_grading", 1.0);
  }
  pass.stop_at_steady = p.value("stop_at_steady_state", false);
  if (p.contains("roll_speed")) pass.rpm = p.at("roll_speed");
  pass.entry_thickness = p.at("slab_thickness");
  pass.exit_thickness = exit_thickness(p);
  pass.width = p.at("slab_width");
  pass.travel = p.at("travel");
  pass.flow_stress = pass_flow_stress(p);
  if (p.contains("slab_flow_stress") || p.contains("heat_transfer"))
    pass.temperature = p.value("slab_temperature", kDefaultSlabTemperature);
  if (p.contains("slab_flow_stress")) {
    pass.flow_law = p.at("slab_flow_stress").at("law").get<std::string>();
    pass.mean_strain_rate = pass_strain_and_rate(p).second;
  }
  if (p.at("roll") == "elastic") pass.roll_E = p.at("roll_E"), pass.roll_nu = p.at("roll_nu");
  pass.roll_fixed = p.at("roll_mesh") == "fixed";
  const std::string friction = p.at("friction");
  if (friction != "sticking") pass.friction = friction == "coulomb" ? friction_coefficient(p) : 0.0;
  if (model.dim == 3) pass.profile = roll_profile(p);
  if (section.contains("passes")) pass.schedule = schedule_facts(section);
  return pass;
}

std::string RollingProcess::smaller_steps(const json& section) const {
  return "a smaller process.travel_increment (now " + mm(section.at("travel_increment").get<double>()) + ")";
}

std::string RollingProcess::progress(const json& section, double fraction) const {
  const double travel = section.at("travel").get<double>();
  char s[96];
  std::snprintf(s, sizeof s, "travel %.4g of %g mm", fraction * travel, travel);
  return s;
}

std::vector<std::string> RollingProcess::outputs() const {
  return {kHistoryTable + std::string(".csv"),
          kHistoryTable + std::string(".png"),
          kProfileTable + std::string(".csv"),
          kProfileTable + std::string(".png"),
          "schedule.csv",
          "schedule.png"};
}

std::unique_ptr<ProcessRun> RollingProcess::start(const json& section, const Model& model) const {
  return std::make_unique<RollingRun>(rolling_pass(section, model), model);
}

}  // namespace rollsim
