#include "project/RollingProcess.h"

#include <cmath>

#include "project/MeshFactory.h"

namespace rollsim {

namespace {
Field number(std::string name, std::string unit, double def, double min, double max, std::string doc) {
  Field f;
  f.name = std::move(name);
  f.kind = Kind::Number;
  f.unit = std::move(unit);
  f.default_value = def;
  f.min = min, f.max = max;
  f.min_exclusive = true;
  f.doc = std::move(doc);
  return f;
}
Field count(std::string name, int def, std::string doc) {
  Field f;
  f.name = std::move(name);
  f.kind = Kind::Integer;
  f.default_value = def;
  f.min = 1, f.max = 1e5;
  f.doc = std::move(doc);
  return f;
}
}  // namespace

const ObjectSchema& rolling_process_schema() {
  static const ObjectSchema s{
      "rolling process",
      "A flat-rolling pass. Generates bodies `slab` and `roll`, materials `slab` and `roll`, the frictionless "
      "contact `roll-slab` (slave: the slab's top, master: the roll's surface) and the conditions: slab mid-plane "
      "symmetry (and width symmetry y = 0 in 3D), slab rear end held in x, roll hub fixed. The slab's front end "
      "touches the roll at the entry of the bite; the rolling analysis itself (plasticity, friction, roll rotation) "
      "comes later. Units: mm and MPa (N/mm²).",
      {[] {
         Field f;
         f.name = "type";
         f.kind = Kind::Choice;
         f.choices = {"rolling"};
         f.default_value = "rolling";
         f.doc = "process kind";
         return f;
       }(),
       number("slab_length", "length", 300, 0, 1e6, "slab length along x (rolling direction)"),
       number("slab_width", "length", 350, 0, 1e6, "slab width (3D: along y; half is modelled)"),
       number("slab_thickness", "length", 100, 0, 1e6, "entry thickness h0 (half is modelled)"),
       number("roll_radius", "length", 300, 0, 1e6, "roll radius R"),
       number("roll_hub_radius", "length", 150, 0, 1e6, "inner radius of the modelled roll ring (fixed hub)"),
       number("barrel_width", "length", 400, 0, 1e6, "roll barrel width (3D; half is modelled)"),
       number("reduction", "-", 0.132, 0, 0.9, "thickness reduction (h0 − h1) / h0"),
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
       count("slab_nw", 8, "slab elements across the half width (3D)"),
       count("roll_n_around", 120, "roll elements around the circumference"),
       count("roll_n_radial", 6, "roll elements across the ring"),
       count("roll_n_axial", 8, "roll elements along the half barrel (3D)"),
       number("slab_E", "stress", 1e5, 0, 1e12, "slab Young's modulus (hot steel)"),
       number("slab_nu", "-", 0.3, -1, 0.5, "slab Poisson's ratio"),
       number("roll_E", "stress", 2.1e5, 0, 1e12, "roll Young's modulus"),
       number("roll_nu", "-", 0.3, -1, 0.5, "roll Poisson's ratio"),
       [] {
         Field f;
         f.name = "slab_partition";
         f.kind = Kind::String;
         f.doc = "subdomains of the slab for `feti` (as bodies[].partition)";
         return f;
       }(),
       [] {
         Field f;
         f.name = "slab_partition_map";
         f.kind = Kind::Vector;
         f.vector_size = -1;
         f.doc = "explicit element → subdomain map of the slab (as bodies[].partition_map, e.g. painted in the window)";
         return f;
       }()},
      "",
      {}};
  return s;
}

void check_process(const json& project, std::vector<Issue>& issues) {
  if (!project.contains("process")) return;
  const json& p = project.at("process");
  if (auto why = grading_problem(p.at("grading").get<double>(), p.at("slab_nx").get<int>()); !why.empty())
    issues.push_back({"process.grading", why});
}

json expand_process(const json& project) {
  if (!project.contains("process")) return project;
  const json& p = project.at("process");
  const int dim = project.at("dimension").get<int>();
  const double L = p.at("slab_length"), W = p.at("slab_width"), h0 = p.at("slab_thickness");
  const double R = p.at("roll_radius"), r = p.at("reduction");
  const double h1 = h0 * (1 - r), dh = (h0 - h1) / 2;
  const double bite = std::sqrt(R * R - (R - dh) * (R - dh));  // x of the entry point, before the roll's axis
  const double axis = h1 / 2 + R;                              // roll axis height above the slab's mid-plane
  json out = project;
  // every field written out, defaults included: the generated entries skip schema validation
  out["materials"].push_back(
      {{"name", "slab"}, {"model", "linear_elastic"}, {"E", p.at("slab_E")}, {"nu", p.at("slab_nu")}});
  out["materials"].push_back(
      {{"name", "roll"}, {"model", "linear_elastic"}, {"E", p.at("roll_E")}, {"nu", p.at("roll_nu")}});
  json slab_mesh = {{"type", "block"}, {"nx", p.at("slab_nx")}, {"lx", L}, {"x_grading", p.at("grading")}};
  json roll_mesh = {{"inner_radius", p.at("roll_hub_radius")},
                    {"outer_radius", R},
                    {"n_radial", p.at("roll_n_radial")},
                    {"n_around", p.at("roll_n_around")}};
  if (dim == 2) {
    slab_mesh.update({{"ny", p.at("slab_nt")}, {"ly", h0 / 2}, {"origin", {-bite - L, 0.0}}});
    roll_mesh.update({{"type", "annulus"}, {"center", {0.0, axis}}});
  } else {
    slab_mesh.update({{"ny", p.at("slab_nw")},
                      {"ly", W / 2},
                      {"nz", p.at("slab_nt")},
                      {"lz", h0 / 2},
                      {"origin", {-bite - L, 0.0, 0.0}}});
    roll_mesh.update({{"type", "cylinder"},
                      {"center", {0.0, axis}},
                      {"y0", 0.0},
                      {"length", p.at("barrel_width").get<double>() / 2},
                      {"n_axial", p.at("roll_n_axial")}});
  }
  json slab = {{"name", "slab"},
               {"material", "slab"},
               {"formulation", "full"},
               {"mesh", slab_mesh},
               {"node_sets", json::array()}};
  if (p.contains("slab_partition")) slab["partition"] = p.at("slab_partition");
  if (p.contains("slab_partition_map")) slab["partition_map"] = p.at("slab_partition_map");
  out["bodies"].push_back(slab);
  roll_mesh.update({{"start_angle", 0.0}, {"end_angle", 360.0}});
  out["bodies"].push_back({{"name", "roll"},
                           {"material", "roll"},
                           {"formulation", "full"},
                           {"mesh", roll_mesh},
                           {"node_sets", json::array()}});
  const std::string top = dim == 2 ? "ymax" : "zmax", mid = dim == 2 ? "ymin" : "zmin";
  out["contacts"].push_back({{"name", "roll-slab"},
                             {"type", "frictionless"},
                             {"slave_body", "slab"},
                             {"slave_surface", top},
                             {"master_body", "roll"},
                             {"master_surface", "outer"},
                             {"search_distance", 4 * dh + 1e-3 * h0}});
  json& bcs = out["boundary_conditions"];
  bcs.push_back({{"type", "symmetry"}, {"body", "slab"}, {"set", mid}, {"normal", dim == 2 ? "y" : "z"}});
  bcs.push_back({{"type", "displacement"}, {"body", "slab"}, {"set", "xmin"}, {"ux", 0.0}});
  json hub = {{"type", "displacement"}, {"body", "roll"}, {"set", "inner"}, {"ux", 0.0}, {"uy", 0.0}};
  if (dim == 3) {
    hub["uz"] = 0.0;
    bcs.push_back({{"type", "symmetry"}, {"body", "slab"}, {"set", "ymin"}, {"normal", "y"}});
  }
  bcs.push_back(hub);
  return out;
}

}  // namespace rollsim
