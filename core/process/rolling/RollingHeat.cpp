#include "process/rolling/RollingHeat.h"

#include "base/SchemaFields.h"
#include "material/ThermalTableSchema.h"

namespace rollsim {

namespace {
using namespace schema;

Field positive_default(std::string name, std::string unit, double d, std::string doc) {
  return def(positive(std::move(name), std::move(unit), std::move(doc)), d);
}
Field non_negative_default(std::string name, std::string unit, double d, std::string doc) {
  return def(non_negative(std::move(name), std::move(unit), std::move(doc)), d);
}
}  // namespace

const ObjectSchema& rolling_heat_schema() {
  static const ObjectSchema s{
      "rolling heat transfer",
      "Heat in the pass: the slab (at slab_temperature, with slab_heat_capacity) and the roll conduct; the arc of "
      "contact passes heat through contact_conductance; the slab's free surfaces (top past the arc, front, rear, "
      "sides) lose heat to the air by convection and radiation, the roll's surface to its cooling; plastic work "
      "(β = 0.9) and friction work heat them. The mid-plane (and the width symmetry plane) is adiabatic. The time "
      "is the roll's: process.roll_speed is needed. A layer of tens of µm to a few mm under the contact carries "
      "the chill: a coarse slab mesh spreads it over its top elements (docs/VALIDATION.md).",
      {positive_default(
           "slab_conductivity", "W/(m·K)", 28,
           "the slab's k (carbon steel at 1100 °C about 28); a slab_thermal_table.conductivity replaces it"),
       positive_default("roll_conductivity", "W/(m·K)", 40, "the roll's k (forged steel about 40)"),
       positive_default("roll_heat_capacity", "MPa/K", 3.6, "the roll's ρc (steel near room temperature about 3.6)"),
       def(bounded(num("roll_temperature", "°C", "the roll's initial temperature, uniform"), -273.15, 2000), 60.0),
       non_negative_default("contact_conductance", "kW/(m²·K)", 20,
                            "h_c across the arc of contact (hot rolling 10–50, rising with pressure and scale-free "
                            "surfaces; 0: none)"),
       non_negative_default("convection", "kW/(m²·K)", 0.015, "the air's h on the slab's free surfaces"),
       def(bounded(num("emissivity", "-", "the slab's ε (oxidised hot steel about 0.8)"), 0, 1), 0.8),
       non_negative_default("roll_cooling", "kW/(m²·K)", 0,
                            "h of the roll's surface outside the arc (water sprays 5–20 on part of the "
                            "circumference, here spread over all of it; 0: an insulated roll)"),
       def(bounded(num("ambient_temperature", "°C", "the air's (and the cooling's) temperature"), -273.15, 2000), 20.0),
       def(bounded(num("friction_heat_to_slab", "-", "the share of the friction work that heats the slab"), 0, 1), 0.5),
       [] {
         Field f = object("slab_thermal_table", thermal_table_schema(),
                          "the slab's k(T) and ρc(T) (its material's thermal_table): its conductivity replaces "
                          "slab_conductivity, its heat_capacity process.slab_heat_capacity (give one or the other)");
         f.default_value = json();
         return f;
       }()},
      "",
      {}};
  return s;
}

void check_rolling_heat(const json& p, std::vector<Issue>& issues) {
  if (!p.contains("heat_transfer")) return;
  if (!(p.value("roll_speed", 0.0) > 0))
    issues.push_back({"process.roll_speed",
                      "is needed with process.heat_transfer: heat flows over the pass's time, "
                      "which the roll's speed sets"});
  const json& h = p.at("heat_transfer");
  if (!h.contains("slab_thermal_table")) return;
  check_thermal_table(h.at("slab_thermal_table"), "process.heat_transfer.slab_thermal_table", issues);
  if (h.at("slab_thermal_table").contains("heat_capacity") && p.contains("slab_heat_capacity"))
    issues.push_back({"process.slab_heat_capacity",
                      "give either slab_heat_capacity or heat_transfer.slab_thermal_table.heat_capacity"});
}

void expand_rolling_heat(const json& p, int dim, json& out) {
  if (!p.contains("heat_transfer")) return;
  const json& h = p.at("heat_transfer");
  for (json& m : out["materials"]) {
    if (m.at("name") == "slab") {
      m["conductivity"] = h.at("slab_conductivity");
      m["heat_capacity"] = p.value("slab_heat_capacity", kHotSteelHeatCapacity);
      if (h.contains("slab_thermal_table")) {  // the properties it gives replace the constants
        m["thermal_table"] = h.at("slab_thermal_table");
        for (const char* name : {"conductivity", "heat_capacity"})
          if (m["thermal_table"].contains(name)) m.erase(name);
      }
    } else if (m.at("name") == "roll") {
      m["conductivity"] = h.at("roll_conductivity");
      m["heat_capacity"] = h.at("roll_heat_capacity");
      m["temperature"] = h.at("roll_temperature");
    }
  }
  for (json& c : out["contacts"])
    if (c.at("name") == "roll-slab") {
      c["conductance"] = h.at("contact_conductance");
      c["friction_heat_to_slave"] = h.at("friction_heat_to_slab");
    }
  json air = json::array();
  // the slab's free faces: its top (where it does not touch the roll), its ends, and in 3D its side(s)
  std::vector<std::string> faces{dim == 2 ? "ymax" : "zmax", "xmin", "xmax"};
  if (dim == 3) faces.push_back("ymax");
  if (dim == 3 && !p.value("width_symmetry", true)) faces.push_back("ymin");
  for (const std::string& f : faces)
    air.push_back(
        {{"body", "slab"}, {"surface", f}, {"convection", h.at("convection")}, {"emissivity", h.at("emissivity")}});
  if (h.at("roll_cooling").get<double>() > 0)
    air.push_back({{"body", "roll"}, {"surface", "outer"}, {"convection", h.at("roll_cooling")}, {"emissivity", 0.0}});
  out["heat"] = {{"ambient_temperature", h.at("ambient_temperature")}, {"air", air}};
}

}  // namespace rollsim
