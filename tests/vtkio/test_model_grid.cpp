// make_model_grid (the grid of result.vtu and of the window's view): with results of a model that has contact pairs,
// a point array contact_pressure holding every body's nodal pressure (0 off the slave surfaces); none without
// contact pairs or without results.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <filesystem>

#include "ModelGrid.h"
#include "analysis/LinearStatic.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

using namespace rollsim;

namespace {
Model sample(const std::string& name) {
  return build_model(load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / name));
}
}  // namespace

TEST(ModelGrid, ContactPressureIsAPointArrayOfEveryBody) {
  const Model model = sample("cylinder-indent-2d.json");
  auto solver = make_solver("direct", {});
  const Results res = run_linear_static(model, *solver);
  const auto grid = make_model_grid(model, &res);
  vtkDataArray* p = grid->GetPointData()->GetArray("contact_pressure");
  ASSERT_NE(p, nullptr);
  ASSERT_EQ(p->GetNumberOfTuples(), model.total_nodes());
  ASSERT_EQ(p->GetNumberOfComponents(), 1);
  vtkIdType offset = 0;
  double max = 0;
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const int n = model.bodies[b].mesh.num_nodes();
    for (int i = 0; i < n; ++i) EXPECT_EQ(p->GetTuple1(offset + i), res.bodies[b].contact_pressure[i]);
    offset += n;
  }
  for (vtkIdType i = 0; i < p->GetNumberOfTuples(); ++i) max = std::max(max, p->GetTuple1(i));
  EXPECT_DOUBLE_EQ(max, res.contacts.at(0).max_pressure);
  EXPECT_EQ(make_model_grid(model)->GetPointData()->GetArray("contact_pressure"), nullptr) << "mesh only";
}

TEST(ModelGrid, NoContactPressureWithoutContactPairs) {
  const Model model = sample("plate-hole-2d.json");
  auto solver = make_solver("direct", {});
  const Results res = run_linear_static(model, *solver);
  EXPECT_EQ(make_model_grid(model, &res)->GetPointData()->GetArray("contact_pressure"), nullptr);
}
