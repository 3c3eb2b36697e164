#include "bench/ProjectBuilders.h"

#include <cmath>

namespace rollsim::bench {

bool is_iterative(const std::string& mode) { return mode.rfind("mixed", 0) == 0 || mode.rfind("feti", 0) == 0; }

json solver_json(const std::string& mode, double tol) {
  const auto colon = mode.find(':');
  const std::string base = mode.substr(0, colon);
  json s = {{"threads", 1}};
  if (colon != std::string::npos) s["update"] = mode.substr(colon + 1);
  if (base.rfind("feti-", 0) == 0) {
    s["mode"] = "feti";
    s["preconditioner"] = base.substr(5);
  } else {
    s["mode"] = base;
  }
  if (is_iterative(base)) s["cg_tolerance"] = tol;
  return s;
}

json block_body(const std::string& name, int nx, int ny, double lx, double ly, std::vector<double> origin,
                const std::string& partition) {
  json b = {{"name", name},
            {"material", "m"},
            {"mesh", {{"type", "block"}, {"nx", nx}, {"ny", ny}, {"lx", lx}, {"ly", ly}, {"origin", origin}}}};
  if (!partition.empty()) b["partition"] = partition;
  return b;
}

json block_body_3d(const std::string& name, std::vector<int> n, std::vector<double> size,
                   const std::string& partition) {
  json b = {{"name", name},
            {"material", "m"},
            {"mesh",
             {{"type", "block"},
              {"nx", n[0]},
              {"ny", n[1]},
              {"nz", n[2]},
              {"lx", size[0]},
              {"ly", size[1]},
              {"lz", size[2]}}}};
  if (!partition.empty()) b["partition"] = partition;
  return b;
}

json project_skeleton(int dim, double e, double nu) {
  return {{"dimension", dim},
          {"materials", json::array({{{"name", "m"}, {"E", e}, {"nu", nu}}})},
          {"bodies", json::array()},
          {"boundary_conditions", json::array()},
          {"output", {{"vtu", false}}}};
}

json cantilever_project(int n, const std::string& partition) {
  json p = project_skeleton(2, 1000, 0.3);
  p["name"] = "cantilever";
  p["bodies"].push_back(block_body("beam", 4 * n, n, 8, 2, {0, -1}, partition));
  p["boundary_conditions"] = {{{"type", "displacement"}, {"body", "beam"}, {"set", "xmin"}, {"ux", 0.0}, {"uy", 0.0}},
                              {{"type", "force"}, {"body", "beam"}, {"set", "xmax"}, {"fy", -1.0 / (n + 1)}}};
  return p;
}

json plate_hole_project(int n_around) {
  json p = project_skeleton(2, 1000, 0.3);
  p["name"] = "plate-hole";
  const int n_radial = std::max(2, 3 * n_around / 4);
  const double grading = std::pow(1.06, 24.0 / n_radial);  // the sample's spread of radial sizes (32 × 24, 1.06)
  p["bodies"].push_back({{"name", "plate"},
                         {"material", "m"},
                         {"partition", "2x2"},
                         {"mesh",
                          {{"type", "plate_with_hole"},
                           {"width", 4.0},
                           {"height", 4.0},
                           {"radius", 1.0},
                           {"n_around", n_around},
                           {"n_radial", n_radial},
                           {"grading", grading}}}});
  p["boundary_conditions"] = {{{"type", "symmetry"}, {"body", "plate"}, {"set", "left"}, {"normal", "x"}},
                              {{"type", "symmetry"}, {"body", "plate"}, {"set", "bottom"}, {"normal", "y"}},
                              {{"type", "displacement"}, {"body", "plate"}, {"set", "top"}, {"uy", 0.01}}};
  return p;
}

json hertz_project(double h, double e_cylinder, double radius, double gap) {
  json p = project_skeleton(2, 1000, 0.3);
  p["name"] = "hertz";
  p["materials"].push_back({{"name", "cyl"}, {"E", e_cylinder}, {"nu", 0.3}});
  const int nb = static_cast<int>(std::lround(1.5 / h)), na = static_cast<int>(std::lround(1.5708 / h)),
            nr = static_cast<int>(std::lround(0.9 / h));
  p["bodies"].push_back(block_body("block", nb, nb, 1.5, 1.5, {0.0, -1.5}, "2x2"));
  p["bodies"].push_back({{"name", "cylinder"},
                         {"material", "cyl"},
                         {"mesh",
                          {{"type", "annulus"},
                           {"center", {0.0, radius + gap}},
                           {"inner_radius", radius - 0.9},
                           {"outer_radius", radius},
                           {"n_radial", nr},
                           {"n_around", na},
                           {"start_angle", 270.0},
                           {"end_angle", 270.0 + 90.0 / radius}}}});
  p["contacts"] = {{{"name", "cylinder-block"},
                    {"type", "frictionless"},
                    {"slave_body", "block"},
                    {"slave_surface", "ymax"},
                    {"master_body", "cylinder"},
                    {"master_surface", "outer"},
                    {"search_distance", 0.1}}};
  p["boundary_conditions"] = {{{"type", "displacement"}, {"body", "block"}, {"set", "ymin"}, {"ux", 0.0}, {"uy", 0.0}},
                              {{"type", "symmetry"}, {"body", "block"}, {"set", "xmin"}, {"normal", "x"}},
                              {{"type", "symmetry"}, {"body", "cylinder"}, {"set", "start"}, {"normal", "x"}},
                              {{"type", "force"}, {"body", "cylinder"}, {"set", "end"}, {"fy", -2.16 / (nr + 1)}}};
  return p;
}

json thick_cylinder_project(double nu, const std::string& formulation, int n_radial) {
  json p = project_skeleton(2, 1000, nu);
  p["name"] = "thick-cylinder";
  p["bodies"].push_back({{"name", "tube"},
                         {"material", "m"},
                         {"formulation", formulation},
                         {"partition", "2x2"},
                         {"mesh",
                          {{"type", "annulus"},
                           {"center", {0.0, 0.0}},
                           {"inner_radius", 1.0},
                           {"outer_radius", 2.0},
                           {"n_radial", n_radial},
                           {"n_around", 2 * n_radial},
                           {"start_angle", 0.0},
                           {"end_angle", 90.0}}}});
  p["boundary_conditions"] = {{{"type", "symmetry"}, {"body", "tube"}, {"set", "start"}, {"normal", "y"}},
                              {{"type", "symmetry"}, {"body", "tube"}, {"set", "end"}, {"normal", "x"}},
                              {{"type", "pressure"}, {"body", "tube"}, {"surface", "inner"}, {"value", 1.0}}};
  return p;
}

json stretched_patch_project(int n, const std::string& formulation) {
  json p = project_skeleton(2, 1000, 0.3);
  p["name"] = "patch";
  json body = block_body("patch", n, n, 1, 1, {0, 0}, "2x2");
  body["formulation"] = formulation;
  p["bodies"].push_back(body);
  p["boundary_conditions"] = {{{"type", "displacement"}, {"body", "patch"}, {"set", "xmin"}, {"ux", 0.0}},
                              {{"type", "displacement"}, {"body", "patch"}, {"set", "ymin"}, {"uy", 0.0}},
                              {{"type", "displacement"}, {"body", "patch"}, {"set", "xmax"}, {"ux", 0.01}}};
  return p;
}

}  // namespace rollsim::bench
