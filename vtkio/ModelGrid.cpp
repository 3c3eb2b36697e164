#include "ModelGrid.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include "io/OutputFields.h"

namespace rollsim {

namespace {

vtkNew<vtkDoubleArray> array(const char* name, int components, vtkIdType tuples) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

vtkNew<vtkIntArray> int_array(const char* name, vtkIdType tuples) {
  vtkNew<vtkIntArray> a;
  a->SetName(name);
  a->SetNumberOfTuples(tuples);
  return a;
}

/// One array per registered output field (io/OutputFields) that `selected` names, filled body by body; point data
/// also carries body_id.
void add_results(vtkUnstructuredGrid* grid, const Model& model, const std::vector<BodyResults>& fields,
                 const std::vector<std::string>& selected) {
  const vtkIdType np = model.total_nodes(), nc = model.total_elements();
  for (const OutputField& f : output_fields()) {
    if (!is_present(f, model) || !is_selected(f, selected)) continue;
    const bool at_nodes = f.location == FieldLocation::Node;
    auto a = array(f.name.c_str(), f.components, at_nodes ? np : nc);
    double v[6];
    vtkIdType i = 0;
    for (size_t b = 0; b < model.bodies.size(); ++b) {
      const Mesh& m = model.bodies[b].mesh;
      for (int k = 0; k < (at_nodes ? m.num_nodes() : m.num_elements()); ++k, ++i) {
        f.value(model, b, fields[b], k, v);
        a->SetTuple(i, v);
      }
    }
    vtkDataSetAttributes* where = at_nodes ? static_cast<vtkDataSetAttributes*>(grid->GetPointData())
                                           : static_cast<vtkDataSetAttributes*>(grid->GetCellData());
    where->AddArray(a);
    if (at_nodes && f.components == 3 && f.name == "displacement") grid->GetPointData()->SetVectors(a);
  }
  auto body_pt = int_array("body_id", np);
  vtkDataArray* sub = grid->GetCellData()->GetArray("subdomain_id");
  vtkIdType pn = 0, cn = 0;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    for (int n = 0; n < model.bodies[b].mesh.num_nodes(); ++n, ++pn) body_pt->SetValue(pn, static_cast<int>(b));
    for (int e = 0; e < model.bodies[b].mesh.num_elements(); ++e, ++cn)
      if (static_cast<size_t>(e) < fields[b].subdomain.size()) sub->SetTuple1(cn, fields[b].subdomain[e]);
  }
  grid->GetPointData()->AddArray(body_pt);
}

}  // namespace

vtkSmartPointer<vtkUnstructuredGrid> make_model_grid(const Model& model, const Results* results,
                                                     const std::vector<std::string>& selected) {
  static const std::vector<BodyResults> none;
  return make_model_grid(model, results ? results->bodies : none, selected);
}

vtkSmartPointer<vtkUnstructuredGrid> make_model_grid(const Model& model, const std::vector<BodyResults>& fields,
                                                     const std::vector<std::string>& selected) {
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(model.total_nodes());
  const vtkIdType nc = model.total_elements();
  auto body_id = int_array("body_id", nc), subdomain_id = int_array("subdomain_id", nc);
  grid->Allocate(nc);
  vtkIdType offset = 0, cell = 0;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Mesh& m = model.bodies[b].mesh;
    const std::vector<int>& part = model.bodies[b].partition.element_subdomain;
    for (int n = 0; n < m.num_nodes(); ++n) points->SetPoint(offset + n, m.nodes[n].data());
    const int type = m.type == ElementType::Quad4 ? VTK_QUAD : VTK_HEXAHEDRON;
    vtkIdType ids[8];
    for (int e = 0; e < m.num_elements(); ++e, ++cell) {
      for (int a = 0; a < m.nodes_per_elem(); ++a) ids[a] = offset + m.element(e)[a];
      grid->InsertNextCell(type, m.nodes_per_elem(), ids);
      body_id->SetValue(cell, static_cast<int>(b));
      subdomain_id->SetValue(cell, static_cast<size_t>(e) < part.size() ? part[e] : 0);
    }
    offset += m.num_nodes();
  }
  grid->SetPoints(points);
  grid->GetCellData()->AddArray(body_id);
  grid->GetCellData()->AddArray(subdomain_id);
  if (!fields.empty() && fields.size() == model.bodies.size()) add_results(grid, model, fields, selected);
  return grid;
}

}  // namespace rollsim
