#include "VtuWriter.h"

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <stdexcept>

#include "material/LinearElastic.h"

namespace rollsim {

namespace {

vtkNew<vtkUnstructuredGrid> make_grid(const Model& model) {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(model.total_nodes());
  vtkNew<vtkIntArray> body_id;
  body_id->SetName("body_id");
  grid->Allocate(model.total_elements());
  vtkIdType offset = 0;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Mesh& m = model.bodies[b].mesh;
    for (int n = 0; n < m.num_nodes(); ++n) points->SetPoint(offset + n, m.nodes[n].data());
    const int type = m.type == ElementType::Quad4 ? VTK_QUAD : VTK_HEXAHEDRON;
    vtkIdType ids[8];
    for (int e = 0; e < m.num_elements(); ++e) {
      for (int a = 0; a < m.nodes_per_elem(); ++a) ids[a] = offset + m.element(e)[a];
      grid->InsertNextCell(type, m.nodes_per_elem(), ids);
      body_id->InsertNextValue(static_cast<int>(b));
    }
    offset += m.num_nodes();
  }
  grid->SetPoints(points);
  grid->GetCellData()->AddArray(body_id);
  return grid;
}

vtkNew<vtkDoubleArray> array(const char* name, int components, vtkIdType tuples) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

void add_results(vtkUnstructuredGrid* grid, const Model& model, const Results& r) {
  const vtkIdType np = model.total_nodes(), nc = model.total_elements();
  auto u = array("displacement", 3, np), sp = array("stress", 6, np), vp = array("von_mises", 1, np);
  auto sc = array("stress", 6, nc), vc = array("von_mises", 1, nc);
  vtkNew<vtkIntArray> body_pt, sub;
  body_pt->SetName("body_id");
  sub->SetName("subdomain_id");
  vtkIdType pn = 0, cn = 0;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Mesh& m = model.bodies[b].mesh;
    const BodyResults& br = r.bodies[b];
    for (int n = 0; n < m.num_nodes(); ++n, ++pn) {
      double d[3] = {0, 0, 0};
      for (int c = 0; c < m.dim; ++c) d[c] = br.displacement[n * m.dim + c];
      u->SetTuple(pn, d);
      sp->SetTuple(pn, br.nodal_stress[n].data());
      vp->SetValue(pn, von_mises(br.nodal_stress[n].data()));
      body_pt->InsertNextValue(static_cast<int>(b));
    }
    for (int e = 0; e < m.num_elements(); ++e, ++cn) {
      sc->SetTuple(cn, br.element_stress[e].data());
      vc->SetValue(cn, von_mises(br.element_stress[e].data()));
      sub->InsertNextValue(br.subdomain[e]);
    }
  }
  grid->GetPointData()->AddArray(u);
  grid->GetPointData()->SetVectors(u);
  grid->GetPointData()->AddArray(sp);
  grid->GetPointData()->AddArray(vp);
  grid->GetPointData()->AddArray(body_pt);
  grid->GetCellData()->AddArray(sc);
  grid->GetCellData()->AddArray(vc);
  grid->GetCellData()->AddArray(sub);
}

void write(const std::filesystem::path& file, vtkUnstructuredGrid* grid) {
  const auto tmp = file.parent_path() / ("." + file.filename().string() + ".tmp");
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetFileName(tmp.string().c_str());
  w->SetInputData(grid);
  w->SetDataModeToAppended();
  w->SetCompressorTypeToNone();  // zlib cost 5x the write time for a 2x smaller file
  if (w->Write() != 1) throw std::runtime_error("cannot write " + file.string());
  std::filesystem::rename(tmp, file);
}

}  // namespace

void write_vtu(const std::filesystem::path& file, const Model& model, const Results& results) {
  auto grid = make_grid(model);
  add_results(grid, model, results);
  write(file, grid);
}

void write_mesh_vtu(const std::filesystem::path& file, const Model& model) {
  auto grid = make_grid(model);
  write(file, grid);
}

}  // namespace rollsim
