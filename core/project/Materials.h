#pragma once
// A project's materials: read into MaterialData, checked beyond their schema (a plastic material's hardening and
// flow stress law, the law's coefficients and the time a rate-dependent law needs), and what a run is warned of (a
// body's temperature outside the range its law was fitted over).
#include <string>
#include <vector>

#include "base/Schema.h"
#include "model/MaterialData.h"

namespace rollsim {

/// Whether a materials[] entry gives `property` (conductivity, heat_capacity): as a constant or in its thermal_table.
bool gives(const json& material, const std::string& property);
/// The MaterialData of one validated materials[] entry (a property its thermal_table gives: its constant is the
/// table's value at the material's temperature).
MaterialData material_data(const json& material);
/// Problems of the materials of a validated, process-expanded project (paths materials[i]…).
void check_materials(const json& expanded_project, std::vector<Issue>& issues);
/// Warnings for the run: materials whose temperature lies outside their flow stress law's range. The first
/// `own` materials are the project's (named by their path); the rest a process made (named by the process and
/// the material's name: their paths are not in the user's file).
std::vector<std::string> material_warnings(const json& expanded_project, size_t own);

}  // namespace rollsim
