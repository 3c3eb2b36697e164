#include "process/rolling/RollingSchedule.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "analysis/AnalysisError.h"
#include "analysis/HeatConduction.h"
#include "base/SchemaFields.h"
#include "process/rolling/RollingMeasures.h"
#include "process/rolling/RollingProcess.h"
#include "process/rolling/RollingTheory.h"

namespace rollsim {

namespace {
using namespace schema;

/// The keys a pass sets in place of the section's.
const std::vector<std::string>& pass_keys() {
  static const std::vector<std::string> keys{"reduction", "exit_thickness", "roll_radius", "roll_diameter",
                                             "roll_speed"};
  return keys;
}

Field open_number(std::string name, std::string unit, double hi, std::string doc) {
  Field f = bounded(num(std::move(name), std::move(unit), std::move(doc)), 0, hi);
  f.min_exclusive = true;
  return f;
}
}  // namespace

const ObjectSchema& pass_schema() {
  static const ObjectSchema s{
      "rolling pass of a schedule",
      "One pass of process.passes: its draft, and its roll where it differs from the section's. It receives the "
      "slab the pass before left (pass 1: the section's slab).",
      {open_number("reduction", "-", 0.9, "the pass's reduction of the thickness it receives (or exit_thickness)"),
       open_number("exit_thickness", "length", 1e6, "the pass's exit thickness (or reduction)"),
       open_number("roll_radius", "length", 1e6, "the pass's roll radius (default: the section's)"),
       open_number("roll_diameter", "length", 2e6, "the pass's roll diameter, instead of roll_radius"),
       open_number("roll_speed", "rpm", 1e4, "the pass's roll speed (default: the section's)"),
       def(non_negative("interpass_time", "s",
                        "time in air before the pass (pass 1: from the furnace's exit); the slab cools over it with "
                        "heat_transfer"),
           0.0)},
      "",
      {}};
  return s;
}

bool is_schedule(const json& project) {
  const auto p = project.find("process");
  return p != project.end() && p->is_object() && p->contains("passes");
}

json pass_section(const json& process, size_t k) {
  json s = process;
  s.erase("passes");
  const json& pass = process.at("passes").at(k);
  const auto either = [&](const char* a, const char* b) {
    if (pass.contains(a) || pass.contains(b)) s.erase(a), s.erase(b);
  };
  either("reduction", "exit_thickness");
  either("roll_radius", "roll_diameter");
  for (const std::string& key : pass_keys())
    if (pass.contains(key)) s[key] = pass.at(key);
  return s;
}

namespace {
/// The nominal thickness a section's pass leaves: exit_thickness, or its reduction of slab_thickness.
double nominal_exit(const json& section) {
  if (section.contains("exit_thickness")) return section.at("exit_thickness");
  return section.at("slab_thickness").get<double>() * (1 - section.value("reduction", 0.0));
}

/// Pass k's own checks: its draft against what it receives, then the pass's rolling checks, named in its entry.
void check_pass(const json& project, size_t k, double received, std::vector<Issue>& issues) {
  const std::string at = "process.passes[" + std::to_string(k) + "]";
  const json& pass = project.at("process").at("passes").at(k);
  if (pass.contains("reduction") == pass.contains("exit_thickness")) {
    issues.push_back({at, "give the pass either a reduction or an exit_thickness"});
    return;
  }
  if (pass.value("interpass_time", 0.0) > 0 && !project.at("process").contains("heat_transfer"))
    issues.push_back({at + ".interpass_time",
                      "has no effect without process.heat_transfer (the slab keeps its "
                      "temperature between passes): give heat_transfer, or remove it"});
  if (pass.contains("roll_radius") && pass.contains("roll_diameter"))
    issues.push_back({at + ".roll_diameter", "give either roll_radius or roll_diameter, not both"});
  if (pass.contains("exit_thickness") && !(pass.at("exit_thickness").get<double>() < received)) {
    char text[200];
    std::snprintf(text, sizeof text, "%g mm is not below the %g mm the pass receives (%s)",
                  pass.at("exit_thickness").get<double>(), received,
                  k == 0 ? "process.slab_thickness" : "the exit of the pass before");
    issues.push_back({at + ".exit_thickness", text});
    return;
  }
  json single = project;
  single["process"] = pass_section(project.at("process"), k);
  single["process"]["slab_thickness"] = received;
  std::vector<Issue> found;
  check_rolling(single, found);
  for (Issue& i : found) {
    const std::string path = i.path;
    for (const std::string& key : pass_keys())
      if (i.path == "process." + key && pass.contains(key)) i.path = at + "." + key;
    if (i.path == path) i.message = "in pass " + std::to_string(k + 1) + " (" + at + "): " + i.message;
    if (std::none_of(issues.begin(), issues.end(),
                     [&](const Issue& o) { return o.path == i.path && o.message == i.message; }))
      issues.push_back(i);
  }
}
}  // namespace

void check_schedule(const json& project, std::vector<Issue>& issues) {
  const json& p = project.at("process");
  if (project.at("dimension").get<int>() != 2) {
    issues.push_back({"process.passes", "a schedule runs in plane strain (dimension 2) for now"});
    return;
  }
  if (p.at("passes").empty()) issues.push_back({"process.passes", "give at least one pass"});
  for (const char* key : {"reduction", "exit_thickness"})
    if (p.contains(key))
      issues.push_back({std::string("process.") + key,
                        "each pass of process.passes gives its own draft: remove it here, or give it in the passes"});
  if (!issues.empty()) return;
  double received = p.at("slab_thickness");
  for (size_t k = 0; k < p.at("passes").size(); ++k) {
    const size_t before = issues.size();
    check_pass(project, k, received, issues);
    if (issues.size() > before) return;  // the next passes receive a thickness that is not known
    json section = pass_section(p, k);
    section["slab_thickness"] = received;
    received = nominal_exit(section);
  }
}

namespace {
/// Each node's layer from the mid-plane (0) to the top (nt): its rank by thickness coordinate among the nodes of its
/// column (the nodes of one reference x: the pre-bitten cut scales a column's heights, never reorders them).
std::vector<int> node_rows(const Mesh& mesh, int thickness_axis) {
  std::map<double, std::vector<int>> columns;
  for (int n = 0; n < mesh.num_nodes(); ++n) columns[mesh.nodes[static_cast<size_t>(n)][0]].push_back(n);
  std::vector<int> row(static_cast<size_t>(mesh.num_nodes()), 0);
  for (auto& [x, nodes] : columns) {
    std::sort(nodes.begin(), nodes.end(), [&](int a, int b) {
      return mesh.nodes[static_cast<size_t>(a)][static_cast<size_t>(thickness_axis)] <
             mesh.nodes[static_cast<size_t>(b)][static_cast<size_t>(thickness_axis)];
    });
    for (size_t i = 0; i < nodes.size(); ++i) row[static_cast<size_t>(nodes[i])] = static_cast<int>(i);
  }
  return row;
}

/// Each element's layer: the lower row of its nodes.
std::vector<int> element_rows(const Mesh& mesh, const std::vector<int>& rows) {
  std::vector<int> out(static_cast<size_t>(mesh.num_elements()));
  for (int e = 0; e < mesh.num_elements(); ++e) {
    int r = rows[static_cast<size_t>(mesh.element(e)[0])];
    for (int a = 1; a < mesh.nodes_per_elem(); ++a) r = std::min(r, rows[static_cast<size_t>(mesh.element(e)[a])]);
    out[static_cast<size_t>(e)] = r;
  }
  return out;
}

double current_x(const Mesh& mesh, const Eigen::VectorXd& u, int n) {
  return mesh.nodes[static_cast<size_t>(n)][0] + u[static_cast<Eigen::Index>(n) * mesh.dim];
}

/// Per row, the mean of `values` over the entries whose flag is set (rows without one: the mean of all).
std::vector<double> row_means(const std::vector<int>& row, const std::vector<char>& rolled, const auto& values) {
  const int rows = *std::max_element(row.begin(), row.end()) + 1;
  std::vector<double> sum(static_cast<size_t>(rows), 0.0), count(static_cast<size_t>(rows), 0.0);
  for (size_t i = 0; i < row.size(); ++i)
    if (rolled[i]) {
      sum[static_cast<size_t>(row[i])] += values[static_cast<Eigen::Index>(i)];
      count[static_cast<size_t>(row[i])] += 1;
    }
  for (size_t r = 0; r < sum.size(); ++r) sum[r] = count[r] > 0 ? sum[r] / count[r] : 0.0;
  return sum;
}

/// The model's slab alone, at the temperatures it brings, cooled by the air on the slab's surfaces of model.heat.
Eigen::VectorXd cooled_in_air(const Model& model, int slab, double time) {
  Model air;
  air.dim = model.dim;
  air.bodies.push_back(model.bodies[static_cast<size_t>(slab)]);
  air.heat.ambient = model.heat.ambient;
  for (AirCooling a : model.heat.air)
    if (a.body == slab) a.body = 0, air.heat.air.push_back(a);
  HeatConduction heat(air);
  const int steps = std::max(10, static_cast<int>(std::ceil(time / 0.25)));  // backward Euler, Δt ≤ 0.25 s
  const std::vector<Eigen::VectorXd> u{Eigen::VectorXd::Zero(air.bodies[0].mesh.num_nodes() * air.dim)};
  const std::vector<PairState> none;
  std::vector<std::vector<double>> states(1);
  for (int s = 0; s < steps; ++s) heat.step({time / steps, &u, &none, nullptr}, states);
  return heat.temperature(0);
}
}  // namespace

ScheduleRun::ScheduleRun(const json& project, const json& given) : project_(project), given_(given) {
  const json& p = project.at("process");
  count_ = p.at("passes").size();
  state_.thickness = p.at("slab_thickness");
  state_.length = p.at("slab_length");
}

json ScheduleRun::pass_project(size_t k) const {
  json out = given_;
  json& s = out["process"] = pass_section(given_.at("process"), k);
  if (k == 0) return out;
  s["slab_thickness"] = state_.thickness;
  s["slab_length"] = state_.length;
  if (!state_.row_temperature.empty()) s["slab_temperature"] = state_.mean_temperature;
  return out;
}

json ScheduleRun::section(size_t k) const {
  json s = pass_project(k).at("process");
  std::vector<Issue> issues;  // none: each pass's section was checked with the schedule
  validate_object(s, rolling_process_schema(), "process", project_.at("dimension").get<int>(), issues);
  return s;
}

bool ScheduleRun::cools(size_t k) const {
  const double time = project_.at("process").at("passes").at(k).value("interpass_time", 0.0);
  return k > 0 && time > 0 && project_.at("process").contains("heat_transfer") && state_.cooled.empty();
}

void ScheduleRun::apply(size_t k, Model& model) const {
  if (k == 0) return;
  const RollingPass pass = rolling_pass(section(k), model);
  Body& slab = model.bodies[static_cast<size_t>(pass.slab)];
  const std::vector<int> rows = node_rows(slab.mesh, pass.thickness_axis), layers = element_rows(slab.mesh, rows);
  if (static_cast<size_t>(*std::max_element(layers.begin(), layers.end()) + 1) != state_.layer_strain.size())
    throw AnalysisError("the schedule's passes must keep the slab's layers (process.slab_nt)");
  slab.initial_plastic_strain.clear();
  for (int layer : layers) slab.initial_plastic_strain.push_back(state_.layer_strain[static_cast<size_t>(layer)]);
  slab.initial_temperature.clear();
  if (!state_.cooled.empty())
    slab.initial_temperature = state_.cooled;
  else if (!state_.row_temperature.empty())
    for (int r : rows) slab.initial_temperature.push_back(state_.row_temperature[static_cast<size_t>(r)]);
}

void ScheduleRun::cool(size_t k, const Model& model) {
  Model brought = model;
  apply(k, brought);
  const double time = project_.at("process").at("passes").at(k).value("interpass_time", 0.0);
  const int slab = rolling_pass(section(k), model).slab;
  const Eigen::VectorXd T = cooled_in_air(brought, slab, time);
  state_.cooled.assign(T.data(), T.data() + T.size());
  const Eigen::VectorXd share = node_volumes(model.bodies[static_cast<size_t>(slab)].mesh);
  state_.mean_temperature = share.dot(T) / share.sum();
}

void ScheduleRun::finish(size_t k, const Model& model, const Results& results) {
  const json sec = section(k);
  const RollingPass pass = rolling_pass(sec, model);
  const RollingResults measured = measure_rolling(pass, model, results);
  const RollingTheory theory = rolling_theory(pass);
  PassRecord rec;
  rec.entry_thickness = pass.entry_thickness;
  rec.roll_radius = pass.radius, rec.roll_speed = pass.rpm;
  rec.interpass_time = project_.at("process").at("passes").at(k).value("interpass_time", 0.0);
  rec.entry_temperature = pass.temperature;
  rec.sims_force = theory.sims_force;
  RollingPass carried = pass;  // the same pass on a slab that is already strained
  carried.flow_stress = pass_flow_stress(sec, k > 0 ? state_.mean_strain : 0.0);
  rec.sims_force_carried = rolling_theory(carried).sims_force;
  const RollingIncrement& end = measured.increments.empty() ? RollingIncrement{} : measured.steady;
  rec.exit_thickness = end.exit_thickness > 0 ? end.exit_thickness : pass.exit_thickness;
  rec.roll_force = end.roll_force, rec.roll_torque = end.roll_torque, rec.roll_power = end.roll_power;
  rec.thermal = measured.thermal;
  if (!measured.increments.empty()) {
    rec.slab_temperature = measured.increments.back().slab_temperature;
    rec.surface_temperature = measured.increments.back().surface_temperature;
  }
  records_.push_back(rec);
  if (k + 1 == count_) return;
  // what the next pass receives: the rolled part — the slab that entered the arc from before it (reference x below
  // the arc's entry: the pre-bitten front was cut, never rolled) and has left it past the exit plane; a pass too
  // short for that: all that is past the exit plane
  const Mesh& mesh = model.bodies[static_cast<size_t>(pass.slab)].mesh;
  const BodyResults& slab = results.bodies[static_cast<size_t>(pass.slab)];
  const std::vector<int> rows = node_rows(mesh, pass.thickness_axis), layers = element_rows(mesh, rows);
  std::vector<char> node_in(static_cast<size_t>(mesh.num_nodes())), element_in(layers.size());
  for (const double entry : {-theory.contact_length, 1e300}) {
    std::fill(node_in.begin(), node_in.end(), 0);
    for (int e = 0; e < mesh.num_elements(); ++e) {
      double x = 0, X = 0;
      for (int a = 0; a < mesh.nodes_per_elem(); ++a) {
        x += current_x(mesh, slab.displacement, mesh.element(e)[a]) / mesh.nodes_per_elem();
        X += mesh.nodes[static_cast<size_t>(mesh.element(e)[a])][0] / mesh.nodes_per_elem();
      }
      element_in[static_cast<size_t>(e)] = X < entry && x > 0;
      for (int a = 0; a < mesh.nodes_per_elem(); ++a)
        node_in[static_cast<size_t>(mesh.element(e)[a])] |= element_in[static_cast<size_t>(e)];
    }
    if (std::count(element_in.begin(), element_in.end(), 1) > 0) break;
  }
  if (std::count(element_in.begin(), element_in.end(), 1) == 0)
    throw AnalysisError("pass " + std::to_string(k + 1) +
                        " left no rolled slab past the exit plane for the next pass: give process.travel more");
  const Eigen::Map<const Eigen::VectorXd> strain(slab.plastic_strain.data(),
                                                 static_cast<Eigen::Index>(slab.plastic_strain.size()));
  state_.layer_strain = row_means(layers, element_in, strain);
  {  // the rolled part's volume mean
    const Eigen::VectorXd share = node_volumes(mesh);
    double sum = 0, weight = 0;
    for (int e = 0; e < mesh.num_elements(); ++e) {
      if (!element_in[static_cast<size_t>(e)]) continue;
      double v = 0;
      for (int a = 0; a < mesh.nodes_per_elem(); ++a) v += share[mesh.element(e)[a]];
      sum += v * strain[e], weight += v;
    }
    state_.mean_strain = sum / weight;
  }
  const Eigen::VectorXd T = node_temperatures(mesh, slab);
  state_.row_temperature = T.size() > 0 ? row_means(rows, node_in, T) : std::vector<double>{};
  if (T.size() > 0) {  // the rolled part's volume mean
    const Eigen::VectorXd share = node_volumes(mesh);
    double sum = 0, weight = 0;
    for (int n = 0; n < mesh.num_nodes(); ++n)
      if (node_in[static_cast<size_t>(n)]) sum += share[n] * T[n], weight += share[n];
    state_.mean_temperature = sum / weight;
  }
  state_.cooled.clear();
  state_.length *= pass.entry_thickness / rec.exit_thickness;  // plane strain: the area kept
  state_.thickness = rec.exit_thickness;
}

MeasureTable ScheduleRun::table() const {
  MeasureTable t{
      "schedule",
      {{"pass", "pass", "-"},
       {"entry_thickness", "entry thickness", "mm"},
       {"exit_thickness", "exit thickness (measured)", "mm"},
       {"roll_radius", "roll radius", "mm"},
       {"roll_speed", "roll speed", "rpm"},
       {"interpass_time", "time in air before the pass", "s"},
       {"entry_temperature", "slab mean temperature entering", "°C"},
       {"roll_force", "roll force", "N/mm (per unit width)"},
       {"sims_roll_force", "Sims's roll force", "N/mm (per unit width)"},
       {"sims_roll_force_carried", "Sims's roll force from the strain the slab brings", "N/mm (per unit width)"},
       {"roll_torque", "torque per roll", "N·mm/mm (per unit width)"},
       {"roll_power", "roll power per roll", "kW/mm (per unit width)"},
       {"slab_temperature", "slab mean temperature leaving", "°C"},
       {"surface_temperature", "slab surface temperature past the exit", "°C"}},
      {}};
  for (size_t k = 0; k < records_.size(); ++k) {
    const PassRecord& r = records_[k];
    t.rows.push_back({static_cast<double>(k + 1), r.entry_thickness, r.exit_thickness, r.roll_radius, r.roll_speed,
                      r.interpass_time, r.entry_temperature, r.roll_force, r.sims_force, r.sims_force_carried,
                      r.roll_torque, r.roll_power, r.slab_temperature, r.surface_temperature});
  }
  return t;
}

ChartRequest ScheduleRun::chart() const {
  ChartRequest c;
  c.file = "schedule.png";
  c.title = "The schedule pass by pass: roll force beside Sims's, the slab's mean and surface temperatures";
  c.short_title = "roll force [MN/m], slab temperature [°C] per pass";
  c.table = "schedule";
  c.x = "pass";
  c.x_title = "pass";
  c.left_title = "roll force [MN/m]";
  c.right_title = "temperature [°C]";
  c.lines = {{"roll_force", "roll force", 1e-3, false, 0},
             {"sims_roll_force", "Sims's roll force", 1e-3, false, 2},
             {"sims_roll_force_carried", "Sims's from the strain brought", 1e-3, false, 4},
             {"slab_temperature", "slab mean temperature leaving", 1, true, 1},
             {"surface_temperature", "surface temperature past the exit", 1, true, 3}};
  return c;
}

nlohmann::json ScheduleRun::summary() const {
  nlohmann::json passes = nlohmann::json::array();
  const MeasureTable t = table();
  for (const MeasureRow& row : t.rows) {
    nlohmann::json p;
    for (size_t c = 0; c < t.columns.size(); ++c) p[t.columns[c].name] = row[c];
    p["folder"] = "pass-" + std::to_string(static_cast<int>(row[0]));
    passes.push_back(p);
  }
  nlohmann::json units;
  for (const Measure& m : t.columns) units[m.name] = m.unit;
  return {{"passes", passes}, {"units", units}};
}

}  // namespace rollsim
