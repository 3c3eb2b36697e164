#include "project/ModelBuilder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "model/Conditioning.h"
#include "model/RigidModes.h"
#include "partition/PartitionCheck.h"
#include "partition/PartitionSpec.h"
#include "process/ProcessRegistry.h"
#include "project/HeatProject.h"
#include "project/Materials.h"
#include "project/MeshFactory.h"
#include "project/ModelLimits.h"
#include "project/PrescribedConflicts.h"
#include "project/ProjectSchema.h"
#include "project/RemeshProject.h"

namespace rollsim {

namespace {

std::string at(const std::string& list, size_t i) { return list + "[" + std::to_string(i) + "]"; }

std::string join(const std::set<std::string>& s) {
  std::string r;
  for (const auto& x : s) r += (r.empty() ? "" : ", ") + x;
  return r;
}

int find_named(const json& list, const std::string& name) {
  for (size_t i = 0; i < list.size(); ++i)
    if (list[i].at("name").get<std::string>() == name) return static_cast<int>(i);
  return -1;
}

void check_unique(const json& list, const std::string& path, std::vector<Issue>& issues) {
  std::set<std::string> seen;
  for (size_t i = 0; i < list.size(); ++i) {
    const auto name = list[i].at("name").get<std::string>();
    if (!seen.insert(name).second) issues.push_back({at(path, i) + ".name", "duplicate name '" + name + "'"});
  }
}

/// `d` with every imported mesh's file resolved against the project file's folder: a relative path in a project is
/// relative to where the project is, not to where rollsim runs.
json with_mesh_files_resolved(json d, const std::string& source) {
  const std::filesystem::path base = std::filesystem::path(source).parent_path();
  for (json& body : d["bodies"])
    if (json& m = body["mesh"]; m.value("type", "") == "import")
      if (const std::filesystem::path f = m.at("file").get<std::string>(); f.is_relative())
        m["file"] = (base / f).string();
  return d;
}

std::set<std::string> node_set_names(const json& body, int dim) {
  std::set<std::string> names = generator_node_set_names(body.at("mesh"), dim);
  names.insert("all");
  for (const auto& s : body.at("node_sets")) names.insert(s.at("name").get<std::string>());
  return names;
}

void check_node_sets(const json& body, const std::string& path, int dim, std::vector<Issue>& issues) {
  check_unique(body.at("node_sets"), path + ".node_sets", issues);
  std::set<std::string> generated = generator_node_set_names(body.at("mesh"), dim);
  generated.insert("all");
  for (size_t i = 0; i < body.at("node_sets").size(); ++i) {
    const json& s = body["node_sets"][i];
    if (const auto name = s.at("name").get<std::string>(); generated.count(name))
      issues.push_back({at(path + ".node_sets", i) + ".name",
                        "duplicate name '" + name + "': the mesh generator already defines this set"});
    const bool nearest = s.contains("nearest"), box = s.contains("box_min") || s.contains("box_max");
    if (nearest == box || (box && !(s.contains("box_min") && s.contains("box_max"))))
      issues.push_back({at(path + ".node_sets", i), "give either `nearest` or both `box_min` and `box_max`"});
  }
}

/// The axis of a rotation: given in 3D (not zero), not given in 2D (z).
void check_rotation(const json& bc, const std::string& path, int dim, std::vector<Issue>& issues) {
  if (dim == 2) {
    if (bc.contains("axis")) issues.push_back({path + ".axis", "not allowed in a 2D model (the axis is z)"});
    if (bc.contains("uz")) issues.push_back({path + ".uz", "not allowed in a 2D model"});
    return;
  }
  if (!bc.contains("axis")) {
    issues.push_back({path + ".axis", "required in a 3D model: the direction of the rotation axis"});
    return;
  }
  double n2 = 0;
  for (const auto& a : bc.at("axis")) n2 += a.get<double>() * a.get<double>();
  if (!(n2 > 0)) issues.push_back({path + ".axis", "must not be the zero vector"});
}

/// The components <p>x, <p>y (, <p>z) of a condition: at least one, no z in 2D.
void check_components(const json& bc, const std::string& path, const std::string& p, int dim,
                      std::vector<Issue>& issues) {
  if (dim == 2 && bc.contains(p + "z")) issues.push_back({path + "." + p + "z", "not allowed in a 2D model"});
  if (!bc.contains(p + "x") && !bc.contains(p + "y") && !bc.contains(p + "z"))
    issues.push_back({path, "sets no component (give " + p + "x, " + p + "y" + (dim == 3 ? ", " + p + "z" : "") + ")"});
}

void check_condition(const json& bc, const std::string& path, const json& bodies, int dim, std::vector<Issue>& issues) {
  const auto body_name = bc.at("body").get<std::string>();
  const int b = find_named(bodies, body_name);
  if (b < 0) {
    issues.push_back({path + ".body", "no body named '" + body_name + "'"});
    return;
  }
  const json& body = bodies[static_cast<size_t>(b)];
  const auto type = bc.at("type").get<std::string>();
  if (type == "body_force") {
    check_components(bc, path, "b", dim, issues);
    return;
  }
  if (type == "traction") check_components(bc, path, "t", dim, issues);
  if (type == "pressure" && bc.value("follower", false) && body.value("kinematics", "small") != "finite")
    issues.push_back(
        {path + ".follower", "a pressure that follows the deformed surface needs finite kinematics: body '" +
                                 body_name + "' has small (set its `kinematics` to finite, or drop `follower`)"});
  if (type == "pressure" || type == "traction") {
    const auto names = generator_set_names(body.at("mesh"), dim);
    const auto s = bc.at("surface").get<std::string>();
    if (!names.count(s))
      issues.push_back(
          {path + ".surface", "no surface '" + s + "' in body '" + body_name + "' (available: " + join(names) + ")"});
    return;
  }
  const auto names = node_set_names(body, dim);
  const auto s = bc.at("set").get<std::string>();
  if (!names.count(s))
    issues.push_back(
        {path + ".set", "no node set '" + s + "' in body '" + body_name + "' (available: " + join(names) + ")"});
  if (type == "symmetry" && dim == 2 && bc.at("normal") == "z")
    issues.push_back({path + ".normal", "must be x or y in a 2D model"});
  if (type == "rotation") check_rotation(bc, path, dim, issues);
  if (type == "displacement" || type == "force") check_components(bc, path, type == "force" ? "f" : "u", dim, issues);
}

// The name is the default output directory results/<name>: it must stay one plain directory name.
void check_project_name(const json& project, std::vector<Issue>& issues) {
  const auto name = project.at("name").get<std::string>();
  const bool plain = name != "." && name != ".." && std::none_of(name.begin(), name.end(), [](char c) {
                       return c == '/' || c == '\\' || static_cast<unsigned char>(c) < 0x20;
                     });
  if (!plain)
    issues.push_back(
        {"name", "must be usable as a directory name (no '/', '\\', control characters, '.' or '..'), got " +
                     describe(project.at("name"))});
}

void check_partition_fields(const json& body, const std::string& path, std::vector<Issue>& issues) {
  if (body.contains("partition") && body.contains("partition_map"))
    issues.push_back({path + ".partition_map", "give either `partition` or `partition_map`, not both"});
  if (body.contains("partition")) {
    try {
      parse_partition_spec(body.at("partition").get<std::string>());
    } catch (const PartitionError& e) {
      for (const auto& p : e.problems()) issues.push_back({path + "." + p.path, p.message});
    }
  }
  if (!body.contains("partition_map")) return;
  const json& map = body.at("partition_map");
  for (size_t i = 0; i < map.size(); ++i) {
    const double v = map[i].get<double>();
    if (v != std::floor(v) || v < 0 || v > 1e6) {
      issues.push_back(
          {at(path + ".partition_map", i), "must be a subdomain id (an integer from 0), got " + describe(map[i])});
      return;
    }
  }
}

bool in_contact(const json& project, const json& name) {
  for (const auto& c : project.at("contacts"))
    if (c.at("slave_body") == name || c.at("master_body") == name) return true;
  return false;
}

void check_friction(const json& c, const std::string& path, std::vector<Issue>& issues) {
  const std::string type = c.at("type").get<std::string>();
  if (type == "coulomb" && !c.contains("friction"))
    issues.push_back({path + ".friction", "required for a coulomb pair: the friction coefficient μ"});
  if (type != "coulomb" && c.contains("friction"))
    issues.push_back(
        {path + ".friction", "only a coulomb pair has a friction coefficient (this pair is " + type + ")"});
  if (type != "coulomb" && type != "sticking" && c.contains("shear_limit"))
    issues.push_back({path + ".shear_limit",
                      "only sticking and coulomb pairs have a friction stress limit (this pair is " + type + ")"});
  if (c.contains("slip_tolerance") && type != "coulomb" && !(type == "sticking" && c.contains("shear_limit")))
    issues.push_back({path + ".slip_tolerance", "only a pair whose points slip has an elastic slip (this pair is " +
                                                    type + (type == "sticking" ? " without a shear_limit" : "") + ")"});
}

void check_contact(const json& c, const std::string& path, const json& bodies, int dim, std::vector<Issue>& issues) {
  check_friction(c, path, issues);
  std::string found[2];
  const char* roles[2] = {"slave", "master"};
  for (int r = 0; r < 2; ++r) {
    const std::string role = roles[r];
    const auto body_name = c.at(role + "_body").get<std::string>();
    const int b = find_named(bodies, body_name);
    if (b < 0) {
      issues.push_back({path + "." + role + "_body", "no body named '" + body_name + "'"});
      continue;
    }
    const auto names = generator_set_names(bodies[static_cast<size_t>(b)].at("mesh"), dim);
    const auto surface = c.at(role + "_surface").get<std::string>();
    if (!names.count(surface))
      issues.push_back({path + "." + role + "_surface",
                        "no surface '" + surface + "' in body '" + body_name + "' (available: " + join(names) + ")"});
    found[r] = body_name;
  }
  if (c.contains("master_turns")) {
    check_rotation(c.at("master_turns"), path + ".master_turns", dim, issues);
    if (c.value("sliding", "small") == "small")
      issues.push_back({path + ".sliding",
                        "a turning master surface (master_turns) needs large sliding: its "
                        "material moves along the surface"});
    if (c.value("conductance", 0.0) > 0)
      issues.push_back({path + ".master_turns",
                        "not with a conductance: the master's heat would stay where its "
                        "mesh is, not turn with its material"});
  }
  if (!found[0].empty() && found[0] == found[1])
    issues.push_back({path, "slave and master are the same body '" + found[0] +
                                "' (self-contact is not supported; name two different bodies)"});
}

void check_supports(const json& project, std::vector<Issue>& issues) {
  const json& bodies = project.at("bodies");
  for (size_t b = 0; b < bodies.size(); ++b) {
    bool held = in_contact(project, bodies[b].at("name"));
    for (const auto& bc : project.at("boundary_conditions"))
      held = held || ((bc.at("type") == "displacement" || bc.at("type") == "symmetry" || bc.at("type") == "rotation") &&
                      bc.at("body") == bodies[b].at("name"));
    if (!held)
      issues.push_back({at("bodies", b), "body '" + bodies[b].at("name").get<std::string>() +
                                             "' has no displacement or symmetry condition and no contact: it is free "
                                             "to move as a rigid body"});
  }
}

}  // namespace

std::string nonlinear_because(const json& d) {
  for (const json& m : d.at("materials"))
    if (m.contains("yield_stress") || m.contains("flow_stress"))
      return "material '" + m.value("name", "") + "' is plastic";
  for (const json& b : d.at("bodies"))
    if (b.value("kinematics", "small") == "finite") return "body '" + b.value("name", "") + "' has finite kinematics";
  for (const json& m : d.at("materials"))
    if (gives(m, "conductivity"))
      return "material '" + m.value("name", "") + "' conducts heat (a heat step follows each Newton step)";
  for (const json& c : d.value("contacts", json::array()))
    if (c.value("type", "") == "sticking" || c.value("type", "") == "coulomb")
      return "contact pair '" + c.value("name", "") + "' has friction";
  return "";
}

void check_analysis_type(const json& d, std::vector<Issue>& issues) {
  const auto a = d.find("analysis");
  if (const std::string why = nonlinear_because(d);
      !why.empty() && a != d.end() && a->value("type", "auto") == "linear")
    issues.push_back({"analysis.type", why + ": it needs the newton analysis"});
}

/// Whether the project's solver factors each body whole (every mode but `feti` and `petsc`, which factor
/// subdomains or hand them to PETSc).
bool factors_bodies_whole(const json& d) {
  const std::string mode = d.contains("solver") ? d["solver"].value("mode", "direct") : "direct";
  return mode != "feti" && mode != "petsc";
}

void check_references(const Project& project, std::vector<Issue>& issues) {
  if (const Process* process = process_of(project.data)) process->check(project.data, issues);
  if (!issues.empty()) return;  // the generated bodies would repeat the process's problem under their own paths
  const json d = with_mesh_files_resolved(expand_process(project.data), project.source);
  const int dim = project.dimension();
  if (d.at("bodies").empty()) issues.push_back({"bodies", "no body: give `bodies` or a `process`"});
  if (d.at("materials").empty()) issues.push_back({"materials", "no material: give `materials` or a `process`"});
  check_project_name(d, issues);
  check_unique(d.at("materials"), "materials", issues);
  check_materials(d, issues);
  check_heat(d, issues);
  check_remesh(d, dim, issues);
  check_analysis_type(d, issues);
  check_unique(d.at("bodies"), "bodies", issues);
  check_unique(d.at("probes"), "probes", issues);
  double elements = 0;
  for (size_t b = 0; b < d.at("bodies").size(); ++b) {
    const json& body = d["bodies"][b];
    const std::string path = at("bodies", b);
    const auto mat = body.at("material").get<std::string>();
    if (find_named(d.at("materials"), mat) < 0)
      issues.push_back({path + ".material", "no material named '" + mat + "'"});
    check_mesh_spec(body.at("mesh"), path + ".mesh", dim, issues);
    elements += estimated_elements(body.at("mesh"), dim);
    check_node_sets(body, path, dim, issues);
    check_partition_fields(body, path, issues);
  }
  if (elements > kMaxElements)
    issues.push_back({"bodies", "the meshes would have " + std::to_string(static_cast<long long>(elements)) +
                                    " elements, more than this build accepts (" +
                                    std::to_string(static_cast<long long>(kMaxElements)) + ")"});
  else
    check_model_limits(elements, dim, "bodies", issues, factors_bodies_whole(d));
  if (!issues.empty()) return;
  for (size_t i = 0; i < d.at("boundary_conditions").size(); ++i)
    check_condition(d["boundary_conditions"][i], at("boundary_conditions", i), d.at("bodies"), dim, issues);
  for (size_t i = 0; i < d.at("probes").size(); ++i) {
    const json& p = d["probes"][i];
    if (p.contains("body") && find_named(d.at("bodies"), p.at("body").get<std::string>()) < 0)
      issues.push_back({at("probes", i) + ".body", "no body named '" + p.at("body").get<std::string>() + "'"});
  }
  check_unique(d.at("contacts"), "contacts", issues);
  for (size_t i = 0; i < d.at("contacts").size(); ++i)
    check_contact(d["contacts"][i], at("contacts", i), d.at("bodies"), dim, issues);
  if (issues.empty()) check_supports(d, issues);
}

namespace {

std::array<double, 3> point(const json& v) {
  std::array<double, 3> p{0.0, 0.0, 0.0};
  for (size_t i = 0; i < v.size() && i < 3; ++i) p[i] = v[i].get<double>();
  return p;
}

int nearest_node(const Mesh& m, const std::array<double, 3>& x, double* distance = nullptr) {
  int best = 0;
  double bd = std::numeric_limits<double>::infinity();
  for (int n = 0; n < m.num_nodes(); ++n) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += (m.nodes[n][k] - x[k]) * (m.nodes[n][k] - x[k]);
    if (d2 < bd) bd = d2, best = n;
  }
  if (distance) *distance = std::sqrt(bd);
  return best;
}

double mesh_size(const Mesh& m) {
  double s = 0;
  for (int k = 0; k < m.dim; ++k) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& x : m.nodes) lo = std::min(lo, x[k]), hi = std::max(hi, x[k]);
    s = std::max(s, hi - lo);
  }
  return s;
}

void add_user_sets(Mesh& m, const json& sets, const std::string& path, std::vector<Issue>& issues) {
  for (size_t i = 0; i < sets.size(); ++i) {
    const json& s = sets[i];
    std::vector<int> nodes;
    if (s.contains("nearest")) {
      nodes.push_back(nearest_node(m, point(s["nearest"])));
    } else {
      const auto lo = point(s["box_min"]), hi = point(s["box_max"]);
      const double tol = s.contains("tolerance") ? s["tolerance"].get<double>() : 1e-6 * mesh_size(m);
      for (int n = 0; n < m.num_nodes(); ++n) {
        bool in = true;
        for (int k = 0; k < m.dim; ++k) in = in && m.nodes[n][k] >= lo[k] - tol && m.nodes[n][k] <= hi[k] + tol;
        if (in) nodes.push_back(n);
      }
      if (nodes.empty()) issues.push_back({at(path, i), "the box contains no node"});
    }
    m.node_sets[s.at("name").get<std::string>()] = std::move(nodes);
  }
}

RigidRotation rigid_rotation(const json& bc) {
  RigidRotation r;
  r.center = point(bc.at("center"));
  if (bc.contains("axis")) {
    r.axis = point(bc.at("axis"));
    const double n = std::sqrt(r.axis[0] * r.axis[0] + r.axis[1] * r.axis[1] + r.axis[2] * r.axis[2]);
    for (double& a : r.axis) a /= n;
  }
  r.angle = bc.at("angle").get<double>() * (M_PI / 180.0);
  return r;
}

void add_condition(Model& model, const json& bc, const json& bodies, int source) {
  const int b = find_named(bodies, bc.at("body").get<std::string>());
  const Mesh& m = model.bodies[static_cast<size_t>(b)].mesh;
  const auto type = bc.at("type").get<std::string>();
  const char* axes = "xyz";
  const auto components = [&](char p) {
    std::array<double, 3> v{0.0, 0.0, 0.0};
    for (int c = 0; c < 3; ++c) v[c] = bc.value(std::string(1, p) + axes[c], 0.0);
    return v;
  };
  if (type == "pressure") {
    model.pressures.push_back(
        {b, bc.at("surface").get<std::string>(), bc.at("value").get<double>(), bc.value("follower", false)});
    return;
  }
  if (type == "traction") {
    model.tractions.push_back({b, bc.at("surface").get<std::string>(), components('t')});
    return;
  }
  if (type == "body_force") {
    model.body_forces.push_back({b, components('b')});
    return;
  }
  const auto set = bc.at("set").get<std::string>();
  const std::vector<int>& nodes = m.node_sets.at(set);
  if (type == "force") {
    model.forces.push_back({b, set, nodes, components('f')});
    return;
  }
  DisplacementBC d{b, set, nodes, {}, source, std::nullopt};
  if (type == "symmetry") {
    d.value[bc.at("normal").get<std::string>()[0] - 'x'] = 0.0;
  } else {
    for (int c = 0; c < 3; ++c)
      if (bc.contains(std::string("u") + axes[c])) d.value[c] = bc[std::string("u") + axes[c]].get<double>();
  }
  if (type == "rotation") d.rotation = rigid_rotation(bc);
  model.displacements.push_back(std::move(d));
}

/// The partition of a body (one subdomain when none is asked for); its problems are reported with JSON paths.
Partition body_partition(const json& jb, const Mesh& mesh, const std::string& path, std::vector<Issue>& issues,
                         std::vector<std::string>& warnings) {
  PartitionSpec spec;
  std::string where = path + ".partition";
  if (jb.contains("partition")) {
    spec = parse_partition_spec(jb.at("partition").get<std::string>());
  } else if (jb.contains("partition_map")) {
    spec.kind = PartitionKind::Explicit;
    for (const auto& v : jb.at("partition_map")) {  // beyond int: out of range, said by oversized_partition
      const double id = v.get<double>();
      spec.map.push_back(id >= 0 && id < 2147483647.0 ? static_cast<int>(id) : std::numeric_limits<int>::max());
    }
    where = path + ".partition_map";
  } else {
    Partition whole;
    whole.element_subdomain.assign(static_cast<size_t>(mesh.num_elements()), 0);
    whole.description = "1";
    return whole;
  }
  if (const std::string too_many = oversized_partition(mesh, spec); !too_many.empty()) {
    issues.push_back({where, too_many});
    Partition whole;
    whole.element_subdomain.assign(static_cast<size_t>(mesh.num_elements()), 0);
    return whole;
  }
  Partition p = make_partition(mesh, spec);
  const auto report = [&](const std::vector<PartitionProblem>& problems) {
    for (const auto& problem : one_per_class(problems)) {
      std::string at_path = problem.path;  // "<where>.map[…]" of an explicit map is "<path>.partition_map[…]"
      if (at_path.rfind(where + ".map", 0) == 0) at_path = where + at_path.substr(where.size() + 4);
      issues.push_back({at_path, problem.message});
    }
  };
  bool ids_valid = static_cast<int>(p.element_subdomain.size()) == mesh.num_elements();
  for (const int id : p.element_subdomain) ids_valid = ids_valid && id >= 0 && id < p.num_subdomains;
  if (!ids_valid) {  // splitting needs a well-formed map: report its problems first
    report(check_partition(mesh, p, where));
    return p;
  }
  for (const auto& w : split_disconnected(mesh, p)) warnings.push_back(where + ": " + w);
  report(check_partition(mesh, p, where));
  return p;
}

double model_size(const Model& model) {
  double s = 0;
  for (const Body& b : model.bodies) s = std::max(s, mesh_size(b.mesh));
  return s;
}

void add_contacts(Model& model, const json& d) {
  const auto a = d.find("analysis");
  const bool boxes = a == d.end() || a->value("contact_search", std::string("boxes")) == "boxes";
  for (const auto& c : d.at("contacts")) {
    ContactPair p;
    p.box_search = boxes;
    p.name = c.at("name").get<std::string>();
    const std::string type = c.at("type").get<std::string>();
    p.kind = type == "tied"       ? ContactKind::Tied
             : type == "sticking" ? ContactKind::Sticking
             : type == "coulomb"  ? ContactKind::Coulomb
                                  : ContactKind::Frictionless;
    p.friction = c.value("friction", 0.0);
    p.shear_limit = c.value("shear_limit", 0.0);
    p.slip_tolerance = c.value("slip_tolerance", p.slip_tolerance);
    p.conductance = c.value("conductance", 0.0);
    p.friction_heat_to_slave = c.value("friction_heat_to_slave", p.friction_heat_to_slave);
    p.slave_body = find_named(d.at("bodies"), c.at("slave_body").get<std::string>());
    p.master_body = find_named(d.at("bodies"), c.at("master_body").get<std::string>());
    p.slave_surface = c.at("slave_surface").get<std::string>();
    p.master_surface = c.at("master_surface").get<std::string>();
    p.search_distance = c.contains("search_distance") ? c.at("search_distance").get<double>()
                                                      : (p.kind == ContactKind::Tied ? 1e-6 : 0.05) * model_size(model);
    const std::string sliding = c.value("sliding", "small");
    using S = ContactPair::Sliding;
    if (p.kind != ContactKind::Tied)
      p.sliding = sliding == "large_every_iteration" ? S::Iteration : sliding == "large" ? S::Step : S::Small;
    if (c.contains("master_turns")) p.master_turns = rigid_rotation(c.at("master_turns"));
    model.contacts.push_back(std::move(p));
  }
}

}  // namespace

Model build_model(const Project& project) {
  const json d = with_mesh_files_resolved(expand_process(project.data), project.source);
  Model model;
  model.dim = project.dimension();
  std::vector<Issue> issues;
  for (size_t b = 0; b < d.at("bodies").size(); ++b) {
    const json& jb = d["bodies"][b];
    Body body;
    body.name = jb.at("name").get<std::string>();
    body.material_name = jb.at("material").get<std::string>();
    const json& mat = d.at("materials")[static_cast<size_t>(find_named(d.at("materials"), body.material_name))];
    body.material = material_data(mat);
    body.formulation = jb.at("formulation") == "bbar" ? Formulation::BBar : Formulation::Full;
    body.kinematics = jb.value("kinematics", "small") == "finite" ? Kinematics::Finite : Kinematics::Small;
    try {
      body.mesh = make_mesh(jb.at("mesh"), model.dim);
      check_element_orientation(body.mesh);
    } catch (const std::exception& e) {
      issues.push_back({at("bodies", b) + ".mesh", e.what()});
      continue;
    }
    add_user_sets(body.mesh, jb.at("node_sets"), at("bodies", b) + ".node_sets", issues);
    try {
      body.partition = body_partition(jb, body.mesh, at("bodies", b), issues, model.warnings);
    } catch (const PartitionError& e) {
      for (const auto& p : e.problems()) issues.push_back({at("bodies", b) + "." + p.path, p.message});
    }
    model.bodies.push_back(std::move(body));
  }
  if (!issues.empty()) throw ProjectError(project.source, issues);
  const json& conditions = d.at("boundary_conditions");
  for (size_t i = 0; i < conditions.size(); ++i)
    add_condition(model, conditions[i], d.at("bodies"), static_cast<int>(i));
  for (Issue& conflict : prescribed_conflicts(model)) issues.push_back(std::move(conflict));
  add_contacts(model, d);
  add_heat(model, d);
  for (size_t i = 0; i < model.heat.air.size(); ++i)
    if (!model.bodies[static_cast<size_t>(model.heat.air[i].body)].mesh.surfaces.count(model.heat.air[i].surface))
      issues.push_back({"heat.air[" + std::to_string(i) + "].surface",
                        "no surface '" + model.heat.air[i].surface + "' in body '" +
                            model.bodies[static_cast<size_t>(model.heat.air[i].body)].name + "'"});
  for (ContactPair& p : model.contacts) p.holds_slave = !free_rigid_modes(model, p.slave_body).empty();
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    if (in_contact(d, model.bodies[b].name)) continue;  // a floating body: the contact must hold it
    const auto modes = free_rigid_modes(model, static_cast<int>(b));
    std::string list;
    for (const auto& m : modes) list += (list.empty() ? "" : ", ") + m;
    if (!modes.empty())
      issues.push_back({at("bodies", b), "body '" + model.bodies[b].name + "' is not held against " +
                                             std::to_string(modes.size()) + " rigid-body mode(s) (" + list +
                                             "): add displacement or symmetry conditions"});
  }
  if (!issues.empty()) throw ProjectError(project.source, issues);
  for (const auto& p : d.at("probes")) {
    Probe probe{p.at("name").get<std::string>(), point(p.at("at")), 0, 0};
    double best = std::numeric_limits<double>::infinity();
    for (size_t b = 0; b < model.bodies.size(); ++b) {
      if (p.contains("body") && p["body"] != model.bodies[b].name) continue;
      double dist = 0;
      const int n = nearest_node(model.bodies[b].mesh, probe.at, &dist);
      if (dist < best) best = dist, probe.body = static_cast<int>(b), probe.node = n;
    }
    model.probes.push_back(std::move(probe));
  }
  for (std::string& w : conditioning_warnings(model)) model.warnings.push_back(std::move(w));
  for (std::string& w : material_warnings(d, project.data.at("materials").size()))
    model.warnings.push_back(std::move(w));
  for (std::string& w : project.config().warnings) model.warnings.push_back(std::move(w));
  return model;
}

}  // namespace rollsim
