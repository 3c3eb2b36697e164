#include "bench/StabilitySuite.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "bench/ProjectBuilders.h"
#include "bench/Quantities.h"

namespace rollsim::bench {

namespace {

std::string fmt(const char* f, double v) {
  char s[64];
  std::snprintf(s, sizeof s, f, v);
  return s;
}

SuiteCase make(const std::string& family, const std::string& variant, const std::string& mode, double level, double tol,
               json project, MeasureFn measure, const std::string& quantity) {
  SuiteCase c;
  c.suite = "stability", c.family = family, c.variant = variant, c.mode = mode, c.level = level;
  c.cg_tolerance = is_iterative(mode) ? tol : 0;
  c.project = std::move(project);
  c.project["solver"] = solver_json(mode, tol);
  c.measure = std::move(measure), c.quantity = quantity;
  return c;
}

/// The direct solution of `project` as a reference case, and the cases of `modes` checked against it.
void against_direct(const std::string& family, const std::string& variant, double level, const json& project,
                    const MeasureFn& measure, const std::string& quantity, const std::vector<std::string>& modes,
                    double tol, double bound, std::vector<SuiteCase>& out) {
  // compared with direct only: a closed form of the quantity (Hertz's) would mix the discretisation error in
  MeasureFn without_exact = [measure](const Model& m, const Results& r) { return Measure{measure(m, r).value}; };
  SuiteCase ref = make(family, variant, "direct", level, 0, project, without_exact, quantity);
  ref.reference_kind = "itself (reference)", ref.reference_only = true;
  out.push_back(ref);
  for (const std::string& mode : modes) {
    SuiteCase c = make(family, variant, mode, level, tol, project, without_exact, quantity);
    c.reference_case = ref.name(), c.reference_kind = "direct, same mesh", c.bound = bound;
    c.compare_to_direct = true;
    out.push_back(c);
  }
}

const std::vector<std::string> kFeti = {"feti-none", "feti-lumped", "feti-dirichlet"};

void stiffness_ratios(SuiteSize size, std::vector<SuiteCase>& out) {
  const double h = size == SuiteSize::tiny ? 0.08 : 0.02;
  const std::vector<double> ratios =
      size == SuiteSize::tiny ? std::vector<double>{1, 1e8} : std::vector<double>{1, 1e2, 1e4, 1e6, 1e8};
  for (const double r : ratios)
    for (const std::string mode : {"direct", "mixed", "feti-dirichlet"}) {
      SuiteCase c = make("stiffness-ratio", fmt("E_cyl/E_block=%.0e", r), mode, r, 1e-8, hertz_project(h, 1000 * r),
                         hertz_peak_pressure(1, 1000, 0.3, 1000 * r, 0.3), "peak contact pressure p0");
      c.reference_kind = "closed form (Hertz)", c.bound = size == SuiteSize::tiny ? 0.3 : 0.05;
      c.if_wrong = "the contact zone is resolved by too few nodes for a stiff indenter (a shrinks as E* grows)";
      out.push_back(c);
    }
}

void poisson(SuiteSize size, std::vector<SuiteCase>& out) {
  const int nr = size == SuiteSize::tiny ? 4 : 16;
  const std::vector<double> nus =
      size == SuiteSize::tiny ? std::vector<double>{0.3, 0.4999} : std::vector<double>{0.3, 0.45, 0.49, 0.499, 0.4999};
  for (const double nu : nus)
    for (const std::string form : {"full", "bbar"})
      for (const std::string mode : {"direct", "feti-dirichlet"}) {
        SuiteCase c = make("poisson", fmt("nu=%g ", nu) + form, mode, nu, 1e-8, thick_cylinder_project(nu, form, nr),
                           lame_inner_displacement(1, 2, 1, 1000, nu), "inner radial displacement");
        c.reference_kind = "closed form (Lame)", c.bound = size == SuiteSize::tiny ? 0.1 : 0.01;
        c.if_wrong = form == "full" ? "volumetric locking of full integration (use formulation bbar)"
                                    : "near-incompressible conditioning";
        out.push_back(c);
      }
}

void aspect_ratios(SuiteSize size, std::vector<SuiteCase>& out) {
  const int n = size == SuiteSize::tiny ? 8 : size == SuiteSize::quick ? 60 : 100;
  const std::vector<std::pair<std::string, double>> parts =
      size == SuiteSize::tiny ? std::vector<std::pair<std::string, double>>{{"2x2", 1}, {"1x8", 8}}
      : size == SuiteSize::quick
          ? std::vector<std::pair<std::string, double>>{{"4x4", 1},
                                                        {"2x8", 4},
                                                        {"1x10", 10},
                                                        {"1x30", 30},
                                                        {"1x60", 60}}
          : std::vector<std::pair<std::string, double>>{{"4x4", 1},   {"2x8", 4},   {"1x10", 10},
                                                        {"1x25", 25}, {"1x50", 50}, {"1x100", 100}};
  for (const auto& [part, ar] : parts) {
    json p = project_skeleton(2, 1000, 0.3);
    p["bodies"].push_back(block_body("plate", n, n, 1, 1, {0, 0}, part));
    p["boundary_conditions"] = {
        {{"type", "displacement"}, {"body", "plate"}, {"set", "xmin"}, {"ux", 0.0}, {"uy", 0.0}},
        {{"type", "force"}, {"body", "plate"}, {"set", "xmax"}, {"fy", -1.0 / (n + 1)}}};
    against_direct("aspect-ratio", "partition " + part + fmt(" (AR %g)", ar), ar, p, displacement_at(0, {1, 0.5, 0}, 1),
                   "tip deflection", kFeti, 1e-8, 1e-5, out);
  }
}

void floating(SuiteSize size, std::vector<SuiteCase>& out) {
  const int n = size == SuiteSize::tiny ? 4 : size == SuiteSize::quick ? 16 : 32;
  const std::vector<std::string> parts = size == SuiteSize::tiny    ? std::vector<std::string>{"8x2"}
                                         : size == SuiteSize::quick ? std::vector<std::string>{"16x4", "32x8"}
                                                                    : std::vector<std::string>{"16x4", "32x8", "40x10"};
  for (const std::string& part : parts) {
    json p = project_skeleton(2, 1000, 0.3);
    p["bodies"].push_back(block_body("beam", 4 * n, n, 4, 1, {0, 0}, part));
    p["boundary_conditions"] = {{{"type", "displacement"}, {"body", "beam"}, {"set", "xmin"}, {"ux", 0.0}, {"uy", 0.0}},
                                {{"type", "force"}, {"body", "beam"}, {"set", "xmax"}, {"fy", -1.0 / (n + 1)}}};
    const int px = std::stoi(part.substr(0, part.find('x'))), py = std::stoi(part.substr(part.find('x') + 1));
    against_direct("floating", fmt("%g subdomains (", px * py) + part + ")", px * py, p,
                   displacement_at(0, {4, 0.5, 0}, 1), "tip deflection", kFeti, 1e-8, 1e-5, out);
  }
}

/// A subdomain that touches the supports at one node or along one edge only: partially floating.
void support_touch(SuiteSize size, std::vector<SuiteCase>& out) {
  const int n = size == SuiteSize::tiny ? 4 : 16;
  for (const auto& [what, top] :
       std::vector<std::pair<std::string, double>>{{"2D, one node", 0.5}, {"2D, one element edge", 0.5 + 1.0 / n}}) {
    json p = project_skeleton(2, 1000, 0.3);
    json body = block_body("plate", n, n, 1, 1, {0, 0}, "2x2");
    body["node_sets"] = {{{"name", "support"}, {"box_min", {0.0, 0.0}}, {"box_max", {0.0, top}}, {"tolerance", 1e-9}}};
    p["bodies"].push_back(body);
    p["boundary_conditions"] = {
        {{"type", "displacement"}, {"body", "plate"}, {"set", "support"}, {"ux", 0.0}, {"uy", 0.0}},
        {{"type", "force"}, {"body", "plate"}, {"set", "xmax"}, {"fy", -1.0 / (n + 1)}}};
    against_direct("support-touch", what, top, p, displacement_at(0, {1, 1, 0}, 1), "corner deflection", kFeti, 1e-10,
                   1e-6, out);
  }
  const int m = size == SuiteSize::tiny ? 2 : 8;
  json p = project_skeleton(3, 1000, 0.3);
  json body = block_body_3d("cube", {m, m, m}, {1, 1, 1}, "2x2x2");
  body["node_sets"] = {
      {{"name", "support"}, {"box_min", {0.0, 0.0, 0.0}}, {"box_max", {0.0, 0.5, 0.5}}, {"tolerance", 1e-9}}};
  p["bodies"].push_back(body);
  p["boundary_conditions"] = {
      {{"type", "displacement"}, {"body", "cube"}, {"set", "support"}, {"ux", 0.0}, {"uy", 0.0}, {"uz", 0.0}},
      {{"type", "force"}, {"body", "cube"}, {"set", "xmax"}, {"fz", -1.0 / ((m + 1) * (m + 1))}}};
  against_direct("support-touch", "3D, one node and one edge", 0.5, p, displacement_at(0, {1, 1, 1}, 2),
                 "corner deflection", kFeti, 1e-10, 1e-6, out);
}

void contact_geometry(SuiteSize size, std::vector<SuiteCase>& out) {
  const double h = size == SuiteSize::tiny ? 0.08 : 0.04;
  const std::vector<double> radii = size == SuiteSize::tiny ? std::vector<double>{10} : std::vector<double>{1, 10, 100};
  for (const double r : radii)
    against_direct("grazing", fmt("R=%g", r), r, hertz_project(h, 1000, r),
                   hertz_peak_pressure(r, 1000, 0.3, 1000, 0.3), "peak contact pressure p0",
                   {"mixed", "feti-dirichlet"}, 1e-10, 1e-4, out);
  const std::vector<double> gaps =
      size == SuiteSize::tiny ? std::vector<double>{1e-6} : std::vector<double>{1e-12, 1e-8, 1e-4, 1e-2, 0.05};
  for (const double g : gaps)
    for (const std::string mode : {"direct", "mixed", "feti-dirichlet"}) {
      SuiteCase c = make("gap", fmt("gap=%.0e", g), mode, g, 1e-8, hertz_project(h, 1000, 1, g),
                         hertz_peak_pressure(1, 1000, 0.3, 1000, 0.3), "peak contact pressure p0");
      c.reference_kind = "closed form (Hertz)", c.bound = size == SuiteSize::tiny ? 0.3 : 0.05;
      c.if_wrong = "the gap is not closed by the force-loaded (floating) cylinder";
      out.push_back(c);
    }
}

void distorted(SuiteSize size, std::vector<SuiteCase>& out) {
  const int n = size == SuiteSize::tiny ? 4 : 16;
  const std::vector<double> amounts =
      size == SuiteSize::tiny ? std::vector<double>{0.3} : std::vector<double>{0.0, 0.1, 0.2, 0.3, 0.4, 0.7};
  const double exact = 1000 / (1 - 0.3 * 0.3) * 0.01;  // the force holding x = 1 stretched: σ_xx · 1
  for (const double d : amounts)
    for (const std::string form : {"full", "bbar"})
      for (const std::string mode : {"direct", "feti-dirichlet"}) {
        SuiteCase c = make("distorted", fmt("moves %g h ", d) + form, mode, d, 1e-10, stretched_patch_project(n, form),
                           reaction_on(0, "xmax", 0, exact), "reaction on x = 1");
        c.distortion = d, c.reference_kind = "closed form (patch test)", c.bound = 1e-7;
        c.if_wrong = "the element does not pass the patch test on this distortion";
        out.push_back(c);
      }
}

void tight_tolerances(SuiteSize size, std::vector<SuiteCase>& out) {
  const int n = size == SuiteSize::tiny ? 2 : 16;
  const std::vector<double> tols =
      size == SuiteSize::tiny ? std::vector<double>{1e-12} : std::vector<double>{1e-6, 1e-8, 1e-10, 1e-12};
  for (const double tol : tols) {
    const std::string v = fmt("tol=%.0e", tol);
    against_direct("cg-tolerance", "cantilever " + v, tol, cantilever_project(n), displacement_at(0, {8, 0, 0}, 1),
                   "tip deflection", kFeti, tol, std::max(1e3 * tol, 1e-12), out);
    against_direct("cg-tolerance", "hertz " + v, tol, hertz_project(size == SuiteSize::tiny ? 0.08 : 0.04),
                   hertz_peak_pressure(1, 1000, 0.3, 1000, 0.3), "peak contact pressure p0",
                   {"mixed", "feti-dirichlet"}, tol, std::max(1e3 * tol, 1e-12), out);
  }
}

}  // namespace

std::vector<SuiteCase> stability_cases(SuiteSize size) {
  std::vector<SuiteCase> out;
  stiffness_ratios(size, out);
  poisson(size, out);
  aspect_ratios(size, out);
  floating(size, out);
  support_touch(size, out);
  contact_geometry(size, out);
  distorted(size, out);
  tight_tolerances(size, out);
  return out;
}

}  // namespace rollsim::bench
