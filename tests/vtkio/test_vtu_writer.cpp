// result.vtu reads back with VTK's own XML reader: cells, points and every named array.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>

#include "VtuWriter.h"
#include "analysis/LinearStatic.h"
#include "mesh/StructuredBlock.h"
#include "solve/SolverStrategy.h"

using namespace rollsim;

TEST(VtuWriter, RoundTripThroughVtkReader) {
  Model m;
  m.dim = 3;
  BlockSpec s;
  s.dim = 3;
  s.n = {3, 2, 2};
  m.bodies.push_back({"block", make_block(s), {1000.0, 0.3}, "m", Formulation::Full});
  DisplacementBC clamp{0, "xmin", m.bodies[0].mesh.node_sets.at("xmin"), {0.0, 0.0, 0.0}};
  DisplacementBC pull{0, "xmax", m.bodies[0].mesh.node_sets.at("xmax"), {0.01, std::nullopt, std::nullopt}};
  m.displacements = {clamp, pull};
  auto solver = make_solver("direct", {});
  const Results r = run_linear_static(m, *solver);
  const auto file = std::filesystem::temp_directory_path() / "rollsim_test_result.vtu";
  write_vtu(file, m, r);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkUnstructuredGrid* g = reader->GetOutput();
  ASSERT_EQ(g->GetNumberOfPoints(), 4 * 3 * 3);
  ASSERT_EQ(g->GetNumberOfCells(), 12);
  for (const char* name : {"displacement", "stress", "von_mises", "body_id"})
    EXPECT_NE(g->GetPointData()->GetArray(name), nullptr) << name;
  for (const char* name : {"stress", "von_mises", "body_id", "subdomain_id"})
    EXPECT_NE(g->GetCellData()->GetArray(name), nullptr) << name;
  double ux[3];
  const int far = m.bodies[0].mesh.node_sets.at("xmax")[0];
  g->GetPointData()->GetArray("displacement")->GetTuple(far, ux);
  EXPECT_DOUBLE_EQ(ux[0], 0.01);
  EXPECT_FALSE(std::filesystem::exists(file.parent_path() / ("." + file.filename().string() + ".tmp")));
  std::filesystem::remove(file);
}
