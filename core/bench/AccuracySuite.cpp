#include "bench/AccuracySuite.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "bench/ProjectBuilders.h"
#include "bench/Quantities.h"

namespace rollsim::bench {

namespace {

struct Sweep {
  std::vector<int> levels;         // mesh parameter per refinement
  int reference_level = 0;         // a much finer mesh, solved by direct (0: a closed form instead)
  std::vector<double> tolerances;  // CG tolerances of the iterative modes
};

Sweep sweep_for(SuiteSize size, std::vector<int> tiny, std::vector<int> quick, std::vector<int> full) {
  switch (size) {
    case SuiteSize::tiny:
      return {tiny, 2 * tiny.back(), {1e-6}};
    case SuiteSize::quick:
      return {quick, 2 * quick.back(), {1e-4, 1e-8}};
    default:
      return {full, 2 * full.back(), {1e-4, 1e-6, 1e-8}};
  }
}

std::string label(const char* key, double v) {
  char s[48];
  std::snprintf(s, sizeof s, "%s=%g", key, v);
  return s;
}

/// One family: every mode at every level and (iterative modes) tolerance, plus its reference case.
struct Family {
  std::string name, quantity, reference_kind, key;
  std::vector<std::string> modes;
  std::function<json(int)> project;
  std::function<MeasureFn(int)> measure;
  double level_scale = 1;  // level shown = parameter × scale (e.g. h = scale / parameter)
  bool closed_form = false;
};

void add_family(const Family& f, const Sweep& s, std::vector<SuiteCase>& out) {
  SuiteCase base;
  base.suite = "accuracy", base.family = f.name, base.quantity = f.quantity, base.reference_kind = f.reference_kind;
  if (!f.closed_form) {
    SuiteCase ref = base;
    ref.variant = "reference " + label(f.key.c_str(), f.level_scale * s.reference_level);
    ref.mode = "direct", ref.level = f.level_scale * s.reference_level, ref.reference_only = true;
    ref.project = f.project(s.reference_level);
    ref.project["solver"] = solver_json("direct", 0);
    ref.measure = f.measure(s.reference_level);
    base.reference_case = ref.name();
    out.push_back(ref);
  }
  for (const int level : s.levels)
    for (const std::string& mode : f.modes)
      for (const double tol : is_iterative(mode) ? s.tolerances : std::vector<double>{0.0}) {
        SuiteCase c = base;
        c.variant = label(f.key.c_str(), f.level_scale * level);
        c.level = f.level_scale * level;
        c.mode = mode, c.cg_tolerance = tol;
        c.project = f.project(level);
        c.project["solver"] = solver_json(mode, tol);
        c.measure = f.measure(level);
        out.push_back(c);
      }
}

const std::vector<std::string> kOneBody = {"skyline", "direct", "feti-none", "feti-lumped", "feti-dirichlet"};
const std::vector<std::string> kContact = {"direct", "mixed", "feti-none", "feti-lumped", "feti-dirichlet"};

json plastic_project(int scale) {  // Paper Example 2 (samples/cylinder-plastic-2d.json, scale 2) at `scale` / 2
  json p = project_skeleton(2, 1e7, 0.35);
  p["name"] = "cylinder-plastic";
  p["materials"] = {
      {{"name", "m"}, {"E", 1e7}, {"nu", 0.35}},
      {{"name", "base"}, {"E", 1e6}, {"nu", 0.35}, {"yield_stress", 3333.0}, {"hardening_modulus", 1010.0}}};
  json base = block_body("base", 14 * scale, (21 * scale + 1) / 2, 0.4, 0.3, {0.0, -0.3}, "2x2");
  base["material"] = "base", base["formulation"] = "bbar", base["kinematics"] = "finite";
  p["bodies"].push_back(base);
  p["bodies"].push_back({{"name", "cylinder"},
                         {"material", "m"},
                         {"kinematics", "finite"},
                         {"mesh",
                          {{"type", "annulus"},
                           {"center", {0.0, 0.4}},
                           {"inner_radius", 0.04},
                           {"outer_radius", 0.4},
                           {"n_radial", 6 * scale},
                           {"n_around", 12 * scale},
                           {"start_angle", 270.0},
                           {"end_angle", 360.0}}}});
  p["contacts"] = {{{"name", "cylinder-base"},
                    {"type", "frictionless"},
                    {"slave_body", "base"},
                    {"slave_surface", "ymax"},
                    {"master_body", "cylinder"},
                    {"master_surface", "outer"},
                    {"search_distance", 0.1},
                    {"sliding", "small"}}};
  p["boundary_conditions"] = {{{"type", "displacement"}, {"body", "base"}, {"set", "ymin"}, {"ux", 0.0}, {"uy", 0.0}},
                              {{"type", "symmetry"}, {"body", "base"}, {"set", "xmin"}, {"normal", "x"}},
                              {{"type", "symmetry"}, {"body", "cylinder"}, {"set", "start"}, {"normal", "x"}},
                              {{"type", "displacement"}, {"body", "cylinder"}, {"set", "end"}, {"uy", -0.05}}};
  p["analysis"] = {{"increments", scale > 2 ? 40 : 10}};  // the finer reference in smaller steps (10 invert an element)
  return p;
}

}  // namespace

std::vector<SuiteCase> accuracy_cases(SuiteSize size) {
  std::vector<SuiteCase> out;
  add_family({"cantilever", "tip deflection uy(8, 0)", "direct, 2x finer mesh", "n_depth", kOneBody,
              [](int n) { return cantilever_project(n); },
              [](int) {
                return displacement_at(0, {8, 0, 0}, 1);
              }},
             sweep_for(size, {2}, {2, 4, 8, 16}, {2, 4, 8, 16, 32}), out);
  add_family({"kirsch", "sigma_yy at the hole A = (1, 0)", "direct, 2x finer mesh", "n_around", kOneBody,
              [](int n) { return plate_hole_project(n); },
              [](int) {
                return nodal_stress_at(0, {1, 0, 0}, 1);
              }},
             sweep_for(size, {8}, {8, 16, 32, 64}, {8, 16, 32, 64, 128}), out);
  Family hertz{"hertz",
               "peak contact pressure p0",
               "closed form (Hertz p0 = 2P/(pi a))",
               "h",
               kContact,
               [](int n) { return hertz_project(1.0 / n); },
               [](int) { return hertz_peak_pressure(1, 1000, 0.3, 1000, 0.3); }};
  hertz.level_scale = -1, hertz.closed_form = true;  // levels are 1/h; shown as h below
  Sweep hs = sweep_for(size, {12}, {12, 25, 50}, {12, 25, 50, 100});
  std::vector<SuiteCase> hertz_cases;
  add_family(hertz, hs, hertz_cases);
  for (SuiteCase& c : hertz_cases) {
    c.level = 1.0 / -c.level;
    c.variant = label("h", c.level);
  }
  out.insert(out.end(), hertz_cases.begin(), hertz_cases.end());
  if (size != SuiteSize::tiny)
    add_family(
        {"plastic",
         "contact force on the cylinder at the end (10 increments)",
         "direct, 1.5x finer mesh in 40 increments",
         "mesh_scale",
         {"direct", "direct:selective", "mixed", "mixed:selective", "feti-dirichlet", "feti-dirichlet:selective"},
         [](int s) { return plastic_project(s); },
         [](int) { return reaction_on(1, "end", 1, std::nan("")); }},
        // the reference at 1.5 × the sample's mesh: at 2 × it an element under the cylinder's edge inverts
        // (docs/VALIDATION.md)
        {{1, 2}, 3, {1e-8}}, out);
  return out;
}

}  // namespace rollsim::bench
