#include "material/ThermalTableSchema.h"

#include <sstream>

#include "base/SchemaFields.h"

namespace rollsim {

namespace {
using namespace schema;

/// An array of positive numbers, one per temperature of the table.
Field column(std::string name, std::string unit, std::string doc) {
  Field f = positive(std::move(name), std::move(unit), std::move(doc));
  f.kind = Kind::Vector;
  f.vector_size = -1;
  return f;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::vector<double> numbers(const json& table, const char* name) {
  return table.contains(name) ? table.at(name).get<std::vector<double>>() : std::vector<double>{};
}
}  // namespace

const ObjectSchema& thermal_table_schema() {
  static const ObjectSchema s{
      "thermal table",
      "A material's conductivity and heat capacity against temperature: linear between the table's temperatures, "
      "held at the first and the last value beyond them (a body that leaves the table's range is warned of in "
      "summary.json's `warnings`). Heat conduction reads them once per step, at the temperatures the step starts "
      "from: k at each element's mean nodal temperature, ρc at each node's. A property the table gives replaces the "
      "material's constant (give one or the other); one it leaves out keeps the constant.",
      {req(bounded(vec("temperature", "°C", "the table's temperatures, strictly increasing, at least 2", -1), -273.15,
                   5000)),
       column("conductivity", "W/(m·K)",
              "k at each temperature (= N/(s·K) with mm, N and s; carbon steel about 50 at 20 °C falling to 28 at "
              "1100 °C)"),
       column("heat_capacity", "stress/K",
              "ρc at each temperature (MPa/K; carbon steel about 3.6 at 20 °C, 4.9 hot; its peak near 750 °C is the "
              "ferrite-austenite change)")},
      "",
      {}};
  return s;
}

void check_thermal_table(const json& table, const std::string& path, std::vector<Issue>& issues) {
  const std::vector<double> T = numbers(table, "temperature");
  if (T.size() < 2)
    issues.push_back({path + ".temperature", "needs at least 2 temperatures, got " + std::to_string(T.size())});
  for (size_t i = 1; i < T.size(); ++i)
    if (!(T[i] > T[i - 1])) {
      issues.push_back({path + ".temperature", "must increase strictly: [" + std::to_string(i) + "] = " + number(T[i]) +
                                                   " after " + number(T[i - 1])});
      break;
    }
  if (!table.contains("conductivity") && !table.contains("heat_capacity"))
    issues.push_back({path, "gives neither conductivity nor heat_capacity: give one of them or both, or remove it"});
  for (const char* name : {"conductivity", "heat_capacity"})
    if (table.contains(name) && table.at(name).size() != T.size())
      issues.push_back({path + "." + name, "has " + std::to_string(table.at(name).size()) + " values for " +
                                               std::to_string(T.size()) + " temperatures: give one per temperature"});
}

ThermalTable thermal_table_data(const json& table) {
  ThermalTable t;
  t.temperature = numbers(table, "temperature");
  t.conductivity = numbers(table, "conductivity");
  t.heat_capacity = numbers(table, "heat_capacity");
  return t;
}

}  // namespace rollsim
