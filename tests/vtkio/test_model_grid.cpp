// make_model_grid (the grid of result.vtu and of the window's view): with results of a model that has contact pairs,
// a point array contact_pressure holding every body's nodal pressure (0 off the slave surfaces); none without
// contact pairs or without results; with a selection (output.fields), exactly the selected arrays.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <filesystem>
#include <set>
#include <string>

#include "ModelGrid.h"
#include "analysis/LinearStatic.h"
#include "io/OutputFields.h"
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

// The grid's field arrays are the output registry's: one array per field the model's results carry, with its
// name, location and component count, holding what the registry's reader gives (so a field added to the registry
// reaches result.vtu, the PVD files and the window's colour-by list with no other change).
TEST(ModelGrid, OneArrayPerRegisteredOutputField) {
  Model model = sample("cylinder-indent-2d.json");
  model.bodies[0].material.yield_stress = 1e30;     // a plastic material (that stays elastic): every field is there,
  model.bodies[0].material.heat_capacity = 4.9;     // its temperature too, at elements and (a conducting body)
  model.bodies[0].material.conductivity = 30;       // at nodes
  model.bodies[0].kinematics = Kinematics::Finite;  // and a finite-strain body (its element quality); the linear
                                                    // analysis below solves it at small strain all the same
  auto solver = make_solver("direct", {});
  const Results res = run_linear_static(model, *solver);
  const auto grid = make_model_grid(model, &res);
  int checked = 0;
  for (const OutputField& f : output_fields()) {
    ASSERT_TRUE(is_present(f, model)) << f.name;  // contact pairs, a plastic material, finite strain: every field
    vtkDataSetAttributes* data = f.location == FieldLocation::Node
                                     ? static_cast<vtkDataSetAttributes*>(grid->GetPointData())
                                     : static_cast<vtkDataSetAttributes*>(grid->GetCellData());
    vtkDataArray* a = data->GetArray(f.name.c_str());
    ASSERT_NE(a, nullptr) << f.name;
    EXPECT_EQ(a->GetNumberOfComponents(), f.components) << f.name;
    const size_t last_body = model.bodies.size() - 1;
    const Mesh& m = model.bodies[last_body].mesh;
    const int index = f.location == FieldLocation::Node ? m.num_nodes() - 1 : m.num_elements() - 1;
    double expected[6];
    f.value(model, last_body, res.bodies[last_body], index, expected);
    const vtkIdType last = a->GetNumberOfTuples() - 1;  // the last body's last node / element
    for (int c = 0; c < f.components; ++c) EXPECT_EQ(a->GetComponent(last, c), expected[c]) << f.name;
    ++checked;
  }
  EXPECT_EQ(checked, 12);
}

/// The names of the arrays of `data`, sorted.
std::set<std::string> array_names(vtkDataSetAttributes* data) {
  std::set<std::string> names;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) names.insert(data->GetArrayName(i));
  return names;
}

// output.fields: a name selects its point and its cell array; body_id and subdomain_id are always there; `all` and
// no selection give every field.
TEST(ModelGrid, WritesExactlyTheSelectedFields) {
  const Model model = sample("cylinder-indent-2d.json");
  auto solver = make_solver("direct", {});
  const Results res = run_linear_static(model, *solver);
  using Names = std::set<std::string>;
  auto grid = make_model_grid(model, &res, {"von_mises", "contact_pressure"});
  EXPECT_EQ(array_names(grid->GetPointData()), (Names{"body_id", "contact_pressure", "von_mises"}));
  EXPECT_EQ(array_names(grid->GetCellData()), (Names{"body_id", "subdomain_id", "von_mises"}));
  grid = make_model_grid(model, &res, {"displacement"});
  EXPECT_EQ(array_names(grid->GetPointData()), (Names{"body_id", "displacement"}));
  EXPECT_EQ(array_names(grid->GetCellData()), (Names{"body_id", "subdomain_id"}));
  EXPECT_NE(grid->GetPointData()->GetVectors(), nullptr) << "displacement stays the active vectors";
  const auto all = make_model_grid(model, &res, {"all"}), none = make_model_grid(model, &res);
  EXPECT_EQ(array_names(all->GetPointData()), array_names(none->GetPointData()));
  EXPECT_EQ(array_names(all->GetCellData()), array_names(none->GetCellData()));
  EXPECT_EQ(array_names(none->GetPointData()).size(), 7u);  // 6 fields with contact pairs, and body_id
}
