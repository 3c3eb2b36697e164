#pragma once
// The one adapter between core results and VTK: writes a model and its results as a VTK XML
// unstructured grid (.vtu) that ParaView opens. No VTK header appears here.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "analysis/Results.h"
#include "model/Model.h"

namespace rollsim {

/// How a VTU file is encoded: its arrays appended as raw binary, compressed by `compression` (output.compression:
/// lz4, zlib or none), and the state's values (load factor, a process's clock) as field data.
struct VtuEncoding {
  std::string compression = "lz4";
  std::vector<std::pair<std::string, double>> values;  // name, value: one-tuple field-data arrays
};

/// Point data: displacement, stress (nodal average), von_mises, body_id;
/// cell data: stress (element mean), von_mises, body_id, subdomain_id — of the output fields, those `selected` names
/// (output.fields; empty: every one). Written atomically.
void write_vtu(const std::filesystem::path& file, const Model& model, const Results& results,
               const std::vector<std::string>& selected = {}, const VtuEncoding& encoding = {});

/// The same arrays for one state's fields, e.g. a load increment's (Results::increments[i].bodies).
void write_vtu(const std::filesystem::path& file, const Model& model, const std::vector<BodyResults>& fields,
               const std::vector<std::string>& selected = {}, const VtuEncoding& encoding = {});

/// Mesh only (no results): body_id and subdomain_id per cell.
void write_mesh_vtu(const std::filesystem::path& file, const Model& model);

}  // namespace rollsim
