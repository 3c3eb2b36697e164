// results.pvd of a run that remeshed (analysis/Remeshing): each increment's VTU is written on the model it was computed
// on — the run's own, or a later segment's (IncrementResults::model) with its nodes elsewhere.
#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <memory>

#include "PvdWriter.h"
#include "analysis/LinearStatic.h"
#include "mesh/StructuredBlock.h"
#include "solve/SolverStrategy.h"

namespace test_pvd_writer {

using namespace rollsim;

TEST(PvdWriter, EachIncrementOnTheModelItWasComputedOn) {
  Model m;
  BlockSpec s;
  s.n = {2, 2, 1};
  m.bodies.push_back({"block", make_block(s), {1000.0, 0.3}, "m", Formulation::Full});
  m.displacements = {{0, "xmin", m.bodies[0].mesh.node_sets.at("xmin"), {0.0, 0.0, std::nullopt}},
                     {0, "xmax", m.bodies[0].mesh.node_sets.at("xmax"), {0.01, std::nullopt, std::nullopt}}};
  auto solver = make_solver("direct", {});
  Results r = run_linear_static(m, *solver, nullptr, 2);
  ASSERT_EQ(r.increments.size(), 2u);
  auto moved = std::make_shared<Model>(m);  // a later segment's model: its nodes 5 to the right
  for (auto& p : moved->bodies[0].mesh.nodes) p[0] += 5.0;
  r.increments[1].model = moved;
  const auto dir = std::filesystem::temp_directory_path() / "rollsim_test_pvd";
  std::filesystem::create_directories(dir);
  const auto files = write_increment_collection(dir / "results.pvd", m, r);
  ASSERT_EQ(files.size(), 2u);
  double first[3], second[3];
  for (size_t i = 0; i < 2; ++i) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(files[i].string().c_str());
    reader->Update();
    reader->GetOutput()->GetPoint(0, i == 0 ? first : second);
  }
  EXPECT_DOUBLE_EQ(first[0], m.bodies[0].mesh.nodes[0][0]);
  EXPECT_DOUBLE_EQ(second[0], m.bodies[0].mesh.nodes[0][0] + 5.0);
  std::filesystem::remove_all(dir);
}

}  // namespace test_pvd_writer
