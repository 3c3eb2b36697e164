// A project's materials: a flow stress law is read with its coefficients and temperature; what cannot work is
// refused at the material's path (a rate-dependent law without analysis.duration, a law beside yield_stress,
// coefficients outside the law's range, a temperature where the law gives no flow stress); a temperature outside the
// range a law was fitted over is a warning of the model, never silent. A thermal_table is read into the material (a
// property it gives, at the material's temperature, is the constant) and refused at its path where it cannot work or
// would be ignored.
#include <gtest/gtest.h>

#include "project/Materials.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_materials {

using namespace rollsim;

namespace {
json block(json material, double duration = 0.1) {
  material["name"] = "hot";
  material["E"] = 1.2e5;
  material["nu"] = 0.3;
  return {{"dimension", 2},
          {"materials", {material}},
          {"bodies",
           {{{"name", "b"},
             {"material", "hot"},
             {"mesh", {{"type", "block"}, {"nx", 2}, {"ny", 2}, {"lx", 1.0}, {"ly", 1.0}}}}}},
          {"boundary_conditions",
           {{{"type", "displacement"}, {"body", "b"}, {"set", "ymin"}, {"ux", 0.0}, {"uy", 0.0}},
            {{"type", "displacement"}, {"body", "b"}, {"set", "ymax"}, {"uy", -0.1}}}},
          {"analysis", {{"duration", duration}}}};
}

std::string refusal(const json& j) {
  try {
    parse_project(j.dump(), "m.json");
  } catch (const ProjectError& e) {
    return e.what();
  }
  return "accepted";
}

const json kShida = {{"law", "shida"}, {"carbon", 0.2}};
}  // namespace

TEST(Materials, AFlowStressLawIsReadWithItsCoefficientsAndTemperature) {
  const MaterialData m = material_data({{"E", 1.2e5}, {"nu", 0.3}, {"flow_stress", kShida}, {"temperature", 950.0}});
  EXPECT_TRUE(m.plastic());
  EXPECT_EQ(m.flow_stress.law, "shida");
  EXPECT_EQ(m.flow_stress.coefficients.at("carbon"), 0.2);
  EXPECT_EQ(m.temperature, 950.0);
  const Project p = parse_project(block({{"flow_stress", kShida}, {"temperature", 1000.0}}).dump(), "m.json");
  EXPECT_TRUE(build_model(p).warnings.empty());
}

TEST(Materials, WhatCannotWorkIsRefusedAtTheMaterialsPath) {
  const std::string no_time = refusal(block({{"flow_stress", kShida}}, 0.0));
  EXPECT_NE(no_time.find("materials[0].flow_stress: the shida law depends on the strain rate, which needs time: give "
                         "analysis.duration"),
            std::string::npos)
      << no_time;
  const std::string both = refusal(block({{"flow_stress", kShida}, {"yield_stress", 100.0}}));
  EXPECT_NE(both.find("materials[0].flow_stress: give either yield_stress"), std::string::npos) << both;
  const std::string carbon = refusal(block({{"flow_stress", {{"law", "shida"}, {"carbon", 2.0}}}}));
  EXPECT_NE(carbon.find("materials[0].flow_stress.carbon"), std::string::npos) << carbon;
  const std::string molten = refusal(
      block({{"flow_stress", {{"law", "johnson_cook"}, {"A", 200.0}, {"m", 1.0}, {"melting_temperature", 1400.0}}},
             {"temperature", 1450.0}}));
  EXPECT_NE(molten.find("materials[0].temperature: the johnson_cook law gives no positive flow stress at 1450 °C"),
            std::string::npos)
      << molten;
  const std::string law = refusal(block({{"flow_stress", {{"law", "voce"}}}}));
  EXPECT_NE(law.find("materials[0].flow_stress.law"), std::string::npos) << law;
}

TEST(Materials, ATemperatureOutsideTheLawsRangeIsAWarning) {
  const Project p = parse_project(block({{"flow_stress", kShida}, {"temperature", 1250.0}}).dump(), "m.json");
  const Model model = build_model(p);
  ASSERT_EQ(model.warnings.size(), 1u);
  EXPECT_EQ(model.warnings[0],
            "materials[0].temperature: 1250 °C is outside the range the shida law holds over (700 °C to 1200 °C): "
            "its flow stress there is an extrapolation");
}

namespace {
/// The block's material conducting, with `table` as its thermal_table.
json conducting(json table, json extra = json::object()) {
  json m = {{"conductivity", 30.0}, {"heat_capacity", 4.5}, {"thermal_table", std::move(table)}};
  m.update(extra);
  for (auto it = m.begin(); it != m.end();) it = it.value().is_null() ? m.erase(it) : std::next(it);
  return block(m);
}
}  // namespace

TEST(Materials, AThermalTableIsReadAndItsPropertiesAtTheTemperatureAreTheConstants) {
  const json table = {{"temperature", {20.0, 1000.0}}, {"conductivity", {50.0, 25.0}}};
  const MaterialData m = material_data(
      {{"E", 2e5}, {"nu", 0.3}, {"heat_capacity", 4.5}, {"temperature", 600.0}, {"thermal_table", table}});
  EXPECT_EQ(m.thermal_table.temperature, (std::vector<double>{20, 1000}));
  EXPECT_TRUE(m.thermal_table.gives_conductivity());
  EXPECT_FALSE(m.thermal_table.gives_heat_capacity());
  EXPECT_DOUBLE_EQ(m.conductivity, 50 - 25 * 580.0 / 980) << "k at the material's temperature";
  EXPECT_EQ(m.heat_capacity, 4.5);
  EXPECT_TRUE(m.conducts());
  EXPECT_EQ(refusal(conducting(table, {{"conductivity", nullptr}})), "accepted");
}

TEST(Materials, AThermalTableIsRefusedAtItsPathWhereItCannotWork) {
  const auto refused = [](const json& j, const std::string& expected) {
    const std::string why = refusal(j);
    EXPECT_NE(why.find(expected), std::string::npos) << why;
  };
  const json k = {50.0, 25.0};
  refused(conducting({{"temperature", {1000.0, 20.0}}, {"conductivity", k}}, {{"conductivity", nullptr}}),
          "materials[0].thermal_table.temperature: must increase strictly: [1] = 20 after 1000");
  refused(conducting({{"temperature", {20.0}}, {"conductivity", {50.0}}}, {{"conductivity", nullptr}}),
          "materials[0].thermal_table.temperature: needs at least 2 temperatures, got 1");
  refused(conducting({{"temperature", {20.0, 500.0, 1000.0}}, {"conductivity", k}}, {{"conductivity", nullptr}}),
          "materials[0].thermal_table.conductivity: has 2 values for 3 temperatures");
  refused(conducting({{"temperature", {20.0, 1000.0}}}), "materials[0].thermal_table: gives neither conductivity");
  refused(conducting({{"temperature", {20.0, 1000.0}}, {"conductivity", {50.0, -1.0}}}, {{"conductivity", nullptr}}),
          "materials[0].thermal_table.conductivity: must be an array of finite numbers > 0");
  refused(conducting({{"temperature", {20.0, 1000.0}}, {"conductivity", k}}),
          "materials[0].conductivity: give either conductivity or thermal_table.conductivity");
  refused(conducting({{"temperature", {20.0, 1000.0}}, {"heat_capacity", {3.6, 5.4}}}),
          "materials[0].heat_capacity: give either heat_capacity or thermal_table.heat_capacity");
  // a table where nothing conducts would be ignored
  refused(conducting({{"temperature", {20.0, 1000.0}}, {"heat_capacity", {3.6, 5.4}}},
                     {{"conductivity", nullptr}, {"heat_capacity", nullptr}, {"yield_stress", 100.0}}),
          "materials[0].thermal_table: is read by heat conduction only");
  refused(conducting({{"temperature", {20.0, 1000.0}}, {"conductivity", k}},
                     {{"conductivity", nullptr}, {"heat_capacity", nullptr}}),
          "materials[0].heat_capacity: is needed with conductivity");
}

}  // namespace test_materials
