#include "project/Materials.h"

#include "material/FlowStress.h"
#include "material/ThermalTableSchema.h"

namespace rollsim {

namespace {
std::string at(size_t i) { return "materials[" + std::to_string(i) + "]"; }

/// A material's own hardening fields: consistent with each other and with its model.
void check_hardening(const json& m, const std::string& path, std::vector<Issue>& issues) {
  const bool has_yield = m.contains("yield_stress"), has_law = m.contains("flow_stress");
  if (has_yield && has_law)
    issues.push_back({path + ".flow_stress", "give either yield_stress (and its hardening) or a flow_stress law"});
  if (m.value("model", "linear_elastic") == "j2_plasticity" && !has_yield && !has_law)
    issues.push_back({path + ".yield_stress", "j2_plasticity needs a yield stress or a flow_stress law"});
  if (m.value("model", "") == "linear_elastic" && (has_yield || has_law))
    issues.push_back({path + ".model", "linear_elastic has no yield stress: remove " +
                                           std::string(has_yield ? "yield_stress" : "flow_stress") +
                                           " or say j2_plasticity"});
  const bool plastic_fields = m.contains("saturation_stress") || m.value("hardening_modulus", 0.0) > 0 ||
                              m.value("saturation_exponent", 0.0) > 0;
  if (!has_yield && plastic_fields)
    issues.push_back({path + ".yield_stress", has_law ? "hardening fields are yield_stress's: the flow_stress law "
                                                        "gives the hardening (remove them)"
                                                      : "hardening is given but no yield stress: the material is "
                                                        "elastic"});
  if (gives(m, "heat_capacity") && !has_yield && !has_law && !gives(m, "conductivity"))
    issues.push_back({path + ".heat_capacity",
                      "has no effect on an elastic material that does not conduct (only plastic work would heat "
                      "it): give it a conductivity, a yield stress or a flow_stress law, or remove it"});
  if (has_yield && m.contains("saturation_stress") &&
      m["saturation_stress"].get<double>() < m["yield_stress"].get<double>())
    issues.push_back({path + ".saturation_stress",
                      "must be at least yield_stress (" + std::to_string(m["yield_stress"].get<double>()) +
                          "): a saturation below the initial yield stress would soften the material"});
}

/// A material's thermal_table: its own checks, a property given twice, and a table nothing would read.
void check_table_use(const json& m, const std::string& path, std::vector<Issue>& issues) {
  if (!m.contains("thermal_table")) return;
  const json& table = m.at("thermal_table");
  check_thermal_table(table, path + ".thermal_table", issues);
  for (const char* name : {"conductivity", "heat_capacity"})
    if (m.contains(name) && table.contains(name))
      issues.push_back({path + "." + name, std::string("give either ") + name + " or thermal_table." + name +
                                               " (the table's value at the material's temperature stands for it)"});
  if (!gives(m, "conductivity"))
    issues.push_back({path + ".thermal_table",
                      "is read by heat conduction only, and the material does not conduct: give it a conductivity "
                      "(or a thermal_table.conductivity), or remove the table"});
}
}  // namespace

bool gives(const json& material, const std::string& property) {
  return material.contains(property) ||
         (material.contains("thermal_table") && material.at("thermal_table").contains(property));
}

MaterialData material_data(const json& mat) {
  MaterialData m;
  m.E = mat.at("E").get<double>();
  m.nu = mat.at("nu").get<double>();
  m.yield_stress = mat.value("yield_stress", 0.0);
  m.hardening_modulus = mat.value("hardening_modulus", 0.0);
  m.saturation_stress = mat.value("saturation_stress", 0.0);
  m.saturation_exponent = mat.value("saturation_exponent", 0.0);
  m.temperature = mat.value("temperature", m.temperature);
  m.heat_capacity = mat.value("heat_capacity", 0.0);
  m.taylor_quinney = mat.value("taylor_quinney", m.taylor_quinney);
  m.conductivity = mat.value("conductivity", 0.0);
  if (mat.contains("flow_stress")) m.flow_stress = flow_stress_data(mat.at("flow_stress"));
  if (mat.contains("thermal_table")) {
    m.thermal_table = thermal_table_data(mat.at("thermal_table"));
    if (m.thermal_table.gives_conductivity()) m.conductivity = m.thermal_table.conductivity_at(m.temperature);
    if (m.thermal_table.gives_heat_capacity()) m.heat_capacity = m.thermal_table.heat_capacity_at(m.temperature);
  }
  return m;
}

void check_materials(const json& d, std::vector<Issue>& issues) {
  const json& materials = d.at("materials");
  const double duration = d.at("analysis").value("duration", 0.0);
  for (size_t i = 0; i < materials.size(); ++i) {
    std::vector<Issue> found;
    check_hardening(materials[i], at(i), found);
    check_table_use(materials[i], at(i), found);
    if (found.empty() && materials[i].contains("flow_stress"))
      for (const Issue& issue : check_flow_stress(material_data(materials[i]), duration))
        found.push_back({at(i) + "." + issue.path, issue.message});
    issues.insert(issues.end(), found.begin(), found.end());
  }
}

std::vector<std::string> material_warnings(const json& d, size_t own) {
  std::vector<std::string> warnings;
  const json& materials = d.at("materials");
  for (size_t i = 0; i < materials.size(); ++i)
    if (const std::string w = temperature_warning(material_data(materials[i])); !w.empty())
      warnings.push_back(
          (i < own ? at(i) + ".temperature" : "process (its material '" + materials[i].value("name", "") + "')") +
          ": " + w);
  return warnings;
}

}  // namespace rollsim
