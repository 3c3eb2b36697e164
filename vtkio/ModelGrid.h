#pragma once
// Model (+ results) -> vtkUnstructuredGrid: the one conversion shared by the VTU writer and the window's view.
// Only VTK-aware code (vtkio/, ui/) includes this header; VtuWriter.h stays free of VTK.
#include <vtkSmartPointer.h>

#include "analysis/Results.h"
#include "model/Model.h"

class vtkUnstructuredGrid;

namespace rollsim {

/// Cells of every body stacked in body order (Q4 -> VTK_QUAD, H8 -> VTK_HEXAHEDRON), nodes offset per body.
/// Cell data always: body_id, subdomain_id (the body's partition, 0 when undivided).
/// With results: one array per field of the output registry (io/OutputFields: displacement — the active vectors —,
/// nodal stress, von_mises, contact_pressure with contact pairs; element stress and von_mises) that `selected` names
/// (output.fields; empty: every one), point body_id, and subdomain_id from the results.
vtkSmartPointer<vtkUnstructuredGrid> make_model_grid(const Model& model, const Results* results = nullptr,
                                                     const std::vector<std::string>& selected = {});

/// The same grid with the fields of one state, e.g. a load increment's (Results::increments[i].bodies), one entry per
/// body (none: the mesh alone).
vtkSmartPointer<vtkUnstructuredGrid> make_model_grid(const Model& model, const std::vector<BodyResults>& fields,
                                                     const std::vector<std::string>& selected = {});

}  // namespace rollsim
