#include "ModelGrid.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include "material/Material.h"

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

void add_results(vtkUnstructuredGrid* grid, const Model& model, const std::vector<BodyResults>& fields) {
  const vtkIdType np = model.total_nodes(), nc = model.total_elements();
  auto u = array("displacement", 3, np), sp = array("stress", 6, np), vp = array("von_mises", 1, np);
  auto sc = array("stress", 6, nc), vc = array("von_mises", 1, nc);
  auto body_pt = int_array("body_id", np);
  const bool contact = !model.contacts.empty();  // the array exists whenever the model has contact pairs
  auto cp = array("contact_pressure", 1, contact ? np : 0);
  vtkDataArray* sub = grid->GetCellData()->GetArray("subdomain_id");
  vtkIdType pn = 0, cn = 0;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Mesh& m = model.bodies[b].mesh;
    const BodyResults& br = fields[b];
    for (int n = 0; n < m.num_nodes(); ++n, ++pn) {
      double d[3] = {0, 0, 0};
      for (int c = 0; c < m.dim; ++c) d[c] = br.displacement[n * m.dim + c];
      u->SetTuple(pn, d);
      sp->SetTuple(pn, br.nodal_stress[n].data());
      vp->SetValue(pn, von_mises(br.nodal_stress[n].data()));
      body_pt->SetValue(pn, static_cast<int>(b));
      if (contact) cp->SetValue(pn, n < br.contact_pressure.size() ? br.contact_pressure[n] : 0.0);
    }
    for (int e = 0; e < m.num_elements(); ++e, ++cn) {
      sc->SetTuple(cn, br.element_stress[e].data());
      vc->SetValue(cn, von_mises(br.element_stress[e].data()));
      if (static_cast<size_t>(e) < br.subdomain.size()) sub->SetTuple1(cn, br.subdomain[e]);
    }
  }
  grid->GetPointData()->AddArray(u);
  grid->GetPointData()->SetVectors(u);
  grid->GetPointData()->AddArray(sp);
  grid->GetPointData()->AddArray(vp);
  grid->GetPointData()->AddArray(body_pt);
  if (contact) grid->GetPointData()->AddArray(cp);
  grid->GetCellData()->AddArray(sc);
  grid->GetCellData()->AddArray(vc);
}

}  // namespace

vtkSmartPointer<vtkUnstructuredGrid> make_model_grid(const Model& model, const Results* results) {
  static const std::vector<BodyResults> none;
  return make_model_grid(model, results ? results->bodies : none);
}

vtkSmartPointer<vtkUnstructuredGrid> make_model_grid(const Model& model, const std::vector<BodyResults>& fields) {
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
  if (!fields.empty() && fields.size() == model.bodies.size()) add_results(grid, model, fields);
  return grid;
}

}  // namespace rollsim
