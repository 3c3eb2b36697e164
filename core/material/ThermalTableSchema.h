#pragma once
// The project's thermal_table (materials[].thermal_table, process.heat_transfer.slab_thermal_table): its schema, the
// checks beyond the schema's ranges (increasing temperatures, one value per temperature) and its reading into a
// ThermalTable. Declared here, below process/ and project/, so both read one declaration.
#include <string>
#include <vector>

#include "base/Schema.h"
#include "model/ThermalTable.h"

namespace rollsim {

/// The schema of a thermal_table object: temperature, conductivity and heat_capacity arrays.
const ObjectSchema& thermal_table_schema();
/// Problems of a schema-validated thermal_table at `path` (e.g. "materials[0].thermal_table"): at least two strictly
/// increasing temperatures, at least one property, one value per temperature.
void check_thermal_table(const json& table, const std::string& path, std::vector<Issue>& issues);
/// The ThermalTable of a validated thermal_table object.
ThermalTable thermal_table_data(const json& table);

}  // namespace rollsim
