#pragma once
// The output registry: every field a run writes, with its name, unit, location and how to read it from the results.
// The VTU/PVD writers (vtkio/ModelGrid) make one array per entry and summary.json lists them (`fields`), so a new
// field — plastic strain, slip — is added here and in its computation, nowhere else.
#include <functional>
#include <string>
#include <vector>

#include "analysis/Results.h"
#include "model/Model.h"

namespace rollsim {

enum class FieldLocation { Node, Cell };

struct OutputField {
  std::string name;    // array name in result.vtu (and the window's key)
  std::string label;   // for people: the window's colour-by list, docs
  std::string legend;  // short title of a colour bar (its width fits about ten characters)
  std::string unit;    // in the project's consistent units: "length", "stress", "-"
  FieldLocation location = FieldLocation::Node;
  int components = 1;       // 1, 3 (a vector; 2D padded with 0) or 6 (xx, yy, zz, xy, yz, zx)
  bool colourable = false;  // offered for colouring the view (vectors by magnitude)
  /// False when this model's results do not carry it (contact pressure without contact pairs); empty: always there.
  std::function<bool(const Model&)> present;
  /// The `components` values of node or element `index` of body `body` into `out`.
  std::function<void(const Model&, size_t body, const BodyResults&, int index, double* out)> value;
};

/// Every output field, in the order written.
const std::vector<OutputField>& output_fields();

/// Whether the results of `model` carry `field`.
bool is_present(const OutputField& field, const Model& model);

/// The distinct names of output_fields(), in order (a name may be a point and a cell array: stress, von_mises).
std::vector<std::string> output_field_names();

/// In output.fields: every field (the default, and what an empty selection means).
inline constexpr const char* kAllFields = "all";

/// Whether output.fields' `names` select `field`: its name is among them (its point and its cell array alike), or
/// `all` is, or there are none.
bool is_selected(const OutputField& field, const std::vector<std::string>& names);

/// Bytes of one VTU of `model` holding the selected fields, unencoded (points, cells and the arrays, 8 bytes a value):
/// a lower bound of what the writer puts on disk, for checking free space before a run.
double vtu_bytes(const Model& model, const std::vector<std::string>& selected);

/// "node" or "cell".
const char* to_string(FieldLocation location);

}  // namespace rollsim
