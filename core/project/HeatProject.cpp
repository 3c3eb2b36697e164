#include "project/HeatProject.h"

#include "base/SchemaFields.h"
#include "project/Materials.h"
#include "project/MeshFactory.h"

namespace rollsim {

namespace {
using namespace schema;

const ObjectSchema& air_schema() {
  static const ObjectSchema s{
      "cooled surface",
      "A surface of a conducting body that gives heat to the air: convection h (T − T_air) and radiation ε σ (T⁴ − "
      "T_air⁴) per unit area. Where it touches another body through a contact pair with a conductance, it exchanges "
      "heat with that body instead.",
      {req(str("body", "body name (its material has a conductivity)")), req(str("surface", "surface of the body")),
       def(non_negative("convection", "kW/(m²·K)",
                        "heat transfer coefficient h (= N/(mm·s·K) with mm, N and s; still air about 0.01–0.03, "
                        "water sprays 1–20)"),
           0.0),
       def(bounded(num("emissivity", "-", "ε of the grey-body radiation (hot oxidised steel about 0.8; 0: none)"), 0,
                   1),
           0.0)},
      "",
      {}};
  return s;
}

int named(const json& list, const std::string& name) {
  for (size_t i = 0; i < list.size(); ++i)
    if (list[i].value("name", "") == name) return static_cast<int>(i);
  return -1;
}

/// The material of the body named `name` conducts heat (false for an unknown body).
bool body_conducts(const json& d, const std::string& name) {
  const int b = named(d.at("bodies"), name);
  if (b < 0) return false;
  const int m = named(d.at("materials"), d.at("bodies")[static_cast<size_t>(b)].value("material", ""));
  return m >= 0 && material_data(d.at("materials")[static_cast<size_t>(m)]).conducts();
}

std::string at(const char* list, size_t i) { return std::string(list) + "[" + std::to_string(i) + "]"; }

void check_materials_conduct(const json& d, std::vector<Issue>& issues) {
  const json& materials = d.at("materials");
  std::string conducting;
  for (size_t i = 0; i < materials.size(); ++i) {
    if (!gives(materials[i], "conductivity")) continue;
    if (!gives(materials[i], "heat_capacity"))
      issues.push_back({at("materials", i) + ".heat_capacity",
                        "is needed with conductivity: heat conducts into a volumetric heat capacity ρc (steel about "
                        "3.6 cold, 4.9 hot, MPa/K)"});
    else if (conducting.empty())
      conducting = materials[i].value("name", "");
  }
  if (!conducting.empty() && !(d.at("analysis").value("duration", 0.0) > 0))
    issues.push_back(
        {"analysis.duration", "is needed: material '" + conducting + "' conducts heat, over the analysis's time [s]"});
}
}  // namespace

const ObjectSchema& heat_schema() {
  static const ObjectSchema s{
      "heat",
      "Heat transfer between the bodies whose materials have a conductivity (and a heat capacity), staggered with "
      "the Newton analysis: after each converged step, one backward-Euler step of transient conduction over the "
      "step's time (analysis.duration shared by the steps), with plastic and friction work as heat, each contact "
      "pair's conductance between its bodies and the air on the cooled surfaces. Units with mm, N and s.",
      {def(bounded(num("ambient_temperature", "°C", "the air's temperature"), -273.15, 5000), 20.0),
       objects("air", air_schema(), "the surfaces the air cools")},
      "",
      {}};
  return s;
}

void check_heat(const json& d, std::vector<Issue>& issues) {
  check_materials_conduct(d, issues);
  const json& contacts = d.at("contacts");
  for (size_t i = 0; i < contacts.size(); ++i) {
    if (contacts[i].value("conductance", 0.0) <= 0) continue;
    for (const char* role : {"slave_body", "master_body"})
      if (!body_conducts(d, contacts[i].value(role, "")))
        issues.push_back({at("contacts", i) + ".conductance",
                          "body '" + contacts[i].value(role, "") +
                              "' does not conduct heat (its material has no conductivity and heat capacity)"});
  }
  if (!d.contains("heat")) return;
  const json& air = d.at("heat").value("air", json::array());
  for (size_t i = 0; i < air.size(); ++i) {
    const std::string path = "heat.air[" + std::to_string(i) + "]", name = air[i].at("body");
    const int b = named(d.at("bodies"), name);
    if (b < 0) {
      issues.push_back({path + ".body", "no body named '" + name + "'"});
      continue;
    }
    if (!body_conducts(d, name))
      issues.push_back({path + ".body", "'" + name +
                                            "' does not conduct heat: give its material a conductivity "
                                            "and a heat capacity"});
    const auto names = generator_set_names(d.at("bodies")[static_cast<size_t>(b)].at("mesh"), d.at("dimension"));
    if (!names.empty() && !names.count(air[i].at("surface").get<std::string>()))
      issues.push_back(
          {path + ".surface", "no surface '" + air[i].at("surface").get<std::string>() + "' in body '" + name + "'"});
  }
}

void add_heat(Model& model, const json& d) {
  if (!d.contains("heat")) return;
  const json& h = d.at("heat");
  model.heat.ambient = h.value("ambient_temperature", model.heat.ambient);
  for (const json& a : h.value("air", json::array())) {
    AirCooling c;
    for (size_t b = 0; b < model.bodies.size(); ++b)
      if (model.bodies[b].name == a.at("body")) c.body = static_cast<int>(b);
    c.surface = a.at("surface");
    c.convection = a.value("convection", 0.0);
    c.emissivity = a.value("emissivity", 0.0);
    model.heat.air.push_back(c);
  }
}

}  // namespace rollsim
