#pragma once
// The flat-rolling process section of a project ("process": {"type": "rolling", …}): from the pass geometry
// (slab length × width × thickness, roll radius and barrel, reduction) and mesh densities it generates the
// slab and roll bodies, their materials, the slab–roll contact pair and the symmetry / support conditions, so
// that the rest of the engine sees an ordinary multi-body project. Symmetry: half thickness always (the slab's
// mid-plane), half width in 3D. Axes: x rolling direction, y thickness (2D) / width (3D), z thickness (3D).
#include <optional>

#include "base/Schema.h"
#include "model/Model.h"

namespace rollsim {

/// The schema of the section (fields, units, defaults: the paper's pass, slab 300 × 350 × 100 mm, roll radius
/// 300 mm, 13.2 % reduction).
const ObjectSchema& rolling_process_schema();

/// Checks of the section that need more than one field (the grading against slab_nx), as `process.<field>`.
void check_process(const json& project, std::vector<Issue>& issues);

/// `project` with the bodies, materials, contacts and conditions of its process appended (unchanged without a
/// process). The section must already be validated (defaults filled).
json expand_process(const json& project);

/// The pass as the model's rolling measures need it (bodies, the hub's rotation, nominal geometry), or nothing when
/// the project has no process. `model` is the one built from expand_process(project).
std::optional<RollingPass> rolling_pass(const json& project, const Model& model);

}  // namespace rollsim
