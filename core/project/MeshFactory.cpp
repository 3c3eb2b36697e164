#include "project/MeshFactory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mesh/Annulus.h"
#include "mesh/Cylinder.h"
#include "mesh/Disk.h"
#include "mesh/MeshImport.h"
#include "mesh/PlateWithHole.h"
#include "mesh/RollGap.h"
#include "mesh/RoundBar.h"
#include "mesh/StructuredBlock.h"

namespace rollsim {

namespace {
double num(const json& j, const char* k) { return j.at(k).get<double>(); }
bool full_ring(const json& m) { return std::fabs(num(m, "end_angle") - num(m, "start_angle") - 360.0) < 1e-9; }

/// The mesh of an `import` spec (its `file` already resolved against the project's folder: ModelBuilder).
std::shared_ptr<const Mesh> imported(const json& m, int dim) {
  return import_mesh(m.at("file").get<std::string>(), dim, m.value("element_set", std::string()));
}

/// The same, or null when the file cannot be used (check_mesh_spec says why).
std::shared_ptr<const Mesh> readable(const json& m, int dim) {
  try {
    return imported(m, dim);
  } catch (const MeshImportError&) {
    return nullptr;
  }
}

/// The names of a map's entries.
template <class Map>
std::set<std::string> names_of(const Map& map) {
  std::set<std::string> s;
  for (const auto& entry : map) s.insert(entry.first);
  return s;
}

RoundBarSpec round_bar_spec(const json& m) {
  RoundBarSpec s;
  s.radius = num(m, "radius");
  s.length = num(m, "length");
  s.n_core = m.at("n_core").get<int>();
  s.n_ring = m.at("n_ring").get<int>();
  s.n_axial = m.at("n_axial").get<int>();
  s.core_fraction = num(m, "core_fraction");
  s.neck_ratio = num(m, "neck_ratio");
  if (m.contains("taper_length")) s.taper_length = num(m, "taper_length");
  s.axial_grading = num(m, "axial_grading");
  return s;
}

/// A profile's points (objects with `y` and `radius_change`), in their order.
RadiusProfile radius_profile(const json& points) {
  RadiusProfile profile;
  for (const json& p : points) profile.points.emplace_back(num(p, "y"), num(p, "radius_change"));
  return profile;
}

DiskSpec disk_spec(const json& m, int dim) {
  DiskSpec s;
  s.dim = dim;
  s.c0 = m.at("center")[0].get<double>();
  s.c1 = m.at("center")[1].get<double>();
  s.radius = num(m, "radius");
  s.n_core = m.at("n_core").get<int>();
  s.n_ring = m.at("n_ring").get<int>();
  s.core_fraction = num(m, "core_fraction");
  s.theta0 = num(m, "start_angle");
  s.theta1 = num(m, "end_angle");
  if (dim == 3) {
    s.y0 = m.value("y0", 0.0);
    s.length = num(m, "length");
    s.n_axial = m.at("n_axial").get<int>();
  }
  return s;
}

void check_outer_profile(const json& m, const std::string& path, std::vector<Issue>& issues) {
  const json& points = m.value("outer_profile", json::array());
  for (size_t i = 1; i < points.size(); ++i)
    if (!(num(points[i], "y") > num(points[i - 1], "y")))
      issues.push_back(
          {path + ".outer_profile[" + std::to_string(i) + "].y", "must be greater than the point before's"});
  if (num(m, "outer_radius") + radius_profile(points).lowest() <= num(m, "inner_radius"))
    issues.push_back({path + ".outer_profile", "takes the outer radius down to inner_radius or below"});
}

void check_disk(const json& m, const std::string& path, int dim, std::vector<Issue>& issues) {
  for (const char* k : {"y0", "length", "n_axial"}) {
    if (dim == 2 && m.contains(k)) issues.push_back({path + "." + k, "not allowed in a 2D model"});
    if (dim == 3 && k != std::string("y0") && !m.contains(k))
      issues.push_back({path + "." + k, "is required in a 3D model"});
  }
  for (const char* k : {"start_angle", "end_angle"})
    if (const double a = num(m, k) / 90.0; std::fabs(a - std::round(a)) > 1e-12)
      issues.push_back({path + "." + k, "must be a multiple of 90 (the o-grid covers whole quarters)"});
  const double span = num(m, "end_angle") - num(m, "start_angle");
  if (!(span > 0.0 && span <= 360.0))
    issues.push_back({path + ".end_angle", "must be greater than start_angle by at most 360"});
}
}  // namespace

void check_mesh_spec(const json& m, const std::string& path, int dim, std::vector<Issue>& issues) {
  const auto type = m.at("type").get<std::string>();
  auto need_dim = [&](int d) {
    if (dim != d) issues.push_back({path + ".type", "'" + type + "' meshes are " + std::to_string(d) + "D only"});
  };
  if (type == "import") {
    try {
      imported(m, dim);
    } catch (const MeshImportError& e) {
      issues.push_back({path + "." + e.field(), e.what()});
    }
  } else if (type == "block") {
    for (const char* k : {"nz", "lz"}) {
      if (dim == 3 && !m.contains(k)) issues.push_back({path + "." + k, "is required in a 3D model"});
      if (dim == 2 && m.contains(k)) issues.push_back({path + "." + k, "not allowed in a 2D model"});
    }
    const std::pair<const char*, const char*> graded[] = {
        {"x_grading", "nx"}, {"y_grading", "ny"}, {"z_grading", "nz"}};
    for (const auto& [key, count] : graded)
      if (m.contains(key) && m.contains(count))
        if (auto why = grading_problem(num(m, key), m.at(count).get<int>()); !why.empty())
          issues.push_back({path + "." + key, why});
    if (dim == 2 && m.contains("z_grading")) issues.push_back({path + ".z_grading", "not allowed in a 2D model"});
  } else if (type == "round_bar") {
    need_dim(3);
    if (m.contains("taper_length") && num(m, "taper_length") > num(m, "length"))
      issues.push_back({path + ".taper_length", "must not exceed length (the taper ends inside the bar)"});
    if (auto why = grading_problem(num(m, "axial_grading"), m.at("n_axial").get<int>()); !why.empty())
      issues.push_back({path + ".axial_grading", why});
  } else if (type == "disk") {
    check_disk(m, path, dim, issues);
  } else if (type == "plate_with_hole") {
    need_dim(2);
    if (num(m, "radius") >= std::min(num(m, "width"), num(m, "height")))
      issues.push_back({path + ".radius", "must be smaller than width and height"});
    if (m.at("n_around").get<long long>() % 2) issues.push_back({path + ".n_around", "must be even"});
  } else {
    need_dim(type == "annulus" ? 2 : 3);
    if (num(m, "inner_radius") >= num(m, "outer_radius"))
      issues.push_back({path + ".inner_radius", "must be smaller than outer_radius"});
    if (type == "cylinder") check_outer_profile(m, path, issues);
    const double span = num(m, "end_angle") - num(m, "start_angle");
    if (!(span > 0.0 && span <= 360.0))
      issues.push_back({path + ".end_angle", "must be greater than start_angle by at most 360"});
    else if (span / m.at("n_around").get<double>() >= 180.0)
      issues.push_back({path + ".n_around", "too few elements: each must span less than 180 degrees"});
  }
}

double estimated_elements(const json& m, int dim) {
  const auto type = m.at("type").get<std::string>();
  auto n = [&](const char* k) { return m.contains(k) ? m.at(k).get<double>() : 1.0; };
  if (type == "import") {
    const auto mesh = readable(m, dim);
    return mesh ? mesh->num_elements() : 0;
  }
  if (type == "block") return n("nx") * n("ny") * (dim == 3 ? n("nz") : 1.0);
  if (type == "plate_with_hole" || type == "annulus") return n("n_around") * n("n_radial");
  if (type == "round_bar") return n("n_core") * (n("n_core") + 2.0 * n("n_ring")) * n("n_axial");
  if (type == "disk")
    return n("n_core") * (n("n_core") + 2.0 * n("n_ring")) *
           std::round((m.value("end_angle", 360.0) - m.value("start_angle", 0.0)) / 90.0) *
           (dim == 3 ? n("n_axial") : 1.0);
  return n("n_around") * n("n_radial") * n("n_axial");
}

std::set<std::string> generator_set_names(const json& m, int dim) {
  const auto type = m.at("type").get<std::string>();
  if (type == "import") {
    const auto mesh = readable(m, dim);
    return mesh ? names_of(mesh->surfaces) : std::set<std::string>{};
  }
  if (type == "block") {
    std::set<std::string> s{"xmin", "xmax", "ymin", "ymax"};
    if (dim == 3) s.insert({"zmin", "zmax"});
    return s;
  }
  if (type == "plate_with_hole") return {"left", "bottom", "right", "top", "hole"};
  if (type == "round_bar") return {"xmin", "ymin", "zmin", "zmax", "outer"};
  if (type == "disk") {
    std::set<std::string> s{"outer"};
    if (dim == 3) s.insert({"ymin", "ymax"});
    if (!full_ring(m)) s.insert({"start", "end"});
    return s;
  }
  std::set<std::string> s{"inner", "outer"};
  if (type == "cylinder") s.insert({"ymin", "ymax"});
  if (!full_ring(m)) s.insert({"start", "end"});
  return s;
}

std::set<std::string> generator_node_set_names(const json& m, int dim) {
  if (m.at("type") == "disk") {
    auto s = generator_set_names(m, dim);
    s.insert("center");
    return s;
  }
  if (m.at("type") != "import") return generator_set_names(m, dim);
  const auto mesh = readable(m, dim);
  return mesh ? names_of(mesh->node_sets) : std::set<std::string>{};
}

Mesh make_mesh(const json& m, int dim) {
  const auto type = m.at("type").get<std::string>();
  if (type == "import") return *imported(m, dim);
  if (type == "block") {
    BlockSpec s;
    s.dim = dim;
    s.n = {m.at("nx").get<int>(), m.at("ny").get<int>(), dim == 3 ? m.at("nz").get<int>() : 1};
    s.size = {num(m, "lx"), num(m, "ly"), dim == 3 ? num(m, "lz") : 1.0};
    if (m.contains("origin"))
      for (int k = 0; k < dim; ++k) s.origin[k] = m["origin"][static_cast<size_t>(k)].get<double>();
    const char* gradings[] = {"x_grading", "y_grading", "z_grading"};
    for (size_t a = 0; a < static_cast<size_t>(dim); ++a)
      if (m.contains(gradings[a])) s.grading[a] = num(m, gradings[a]);
    if (m.contains("x_planes"))  // written by the rolling process only: an ALE window's graded columns
      s.x_planes = m.at("x_planes").get<std::vector<double>>();
    Mesh mesh = make_block(s);
    if (m.contains("roll_cut")) {  // written by the rolling process only: the pre-bitten slab (mesh/RollGap.h)
      const json& c = m.at("roll_cut");
      const int t = dim - 1;
      cut_to_roll(mesh, t, s.origin[static_cast<size_t>(t)] + s.size[static_cast<size_t>(t)],
                  {c.at("center")[0].get<double>(), c.at("center")[1].get<double>(), num(c, "radius"),
                   c.at("n_around").get<int>()},
                  radius_profile(c.value("profile", json::array())), c.value("flat_exit", false));
    }
    return mesh;
  }
  auto count = [&](const char* k) { return m.at(k).get<int>(); };
  if (type == "round_bar") return make_round_bar(round_bar_spec(m));
  if (type == "disk") return make_disk(disk_spec(m, dim));
  if (type == "plate_with_hole")
    return make_plate_with_hole(
        {num(m, "width"), num(m, "height"), num(m, "radius"), count("n_around"), count("n_radial"), num(m, "grading")});
  const double c0 = m.at("center")[0].get<double>(), c1 = m.at("center")[1].get<double>();
  if (type == "annulus")
    return make_annulus({c0, c1, num(m, "inner_radius"), num(m, "outer_radius"), count("n_radial"), count("n_around"),
                         num(m, "start_angle"), num(m, "end_angle")});
  return make_cylinder({c0, c1, num(m, "y0"), num(m, "length"), num(m, "inner_radius"), num(m, "outer_radius"),
                        count("n_radial"), count("n_around"), count("n_axial"), num(m, "start_angle"),
                        num(m, "end_angle"), radius_profile(m.value("outer_profile", json::array()))});
}

}  // namespace rollsim
