// `rollsim run` with output.fields: result.vtu and every increment's VTU hold exactly the selected arrays (read back
// with VTK's reader) besides body_id and subdomain_id, and summary.json's `fields` lists exactly those; a name that is
// no field, a name given twice or a list that is not one is refused — exit 2, the JSON path (and the valid names) — and
// nothing is written.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

#include "RunBinary.h"

namespace test_output_fields {

using json = nlohmann::json;
using Names = std::set<std::string>;

namespace {

/// The small J2-plastic cantilever (16 × 4 elements, 3 increments) with output.fields = `fields`, in `dir`.
std::string plastic_cantilever(const std::string& dir, const json& fields) {
  json j = json::parse(read_text(ROLLSIM_SOURCE_DIR "/samples/cantilever-plastic-2d.json"));
  j["bodies"][0]["mesh"]["nx"] = 16;
  j["bodies"][0]["mesh"]["ny"] = 4;
  j.erase("probes");
  j["analysis"]["increments"] = 3;
  j["output"]["fields"] = fields;
  const std::string file = dir + "/cantilever.json";
  write_text(file, j.dump(2));
  return file;
}

/// The point and the cell array names of a VTU file.
std::pair<Names, Names> arrays(const std::string& vtu) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(vtu.c_str());
  reader->Update();
  std::pair<Names, Names> names;
  vtkUnstructuredGrid* grid = reader->GetOutput();
  EXPECT_GT(grid->GetNumberOfCells(), 0) << vtu;
  for (int i = 0; i < grid->GetPointData()->GetNumberOfArrays(); ++i)
    names.first.insert(grid->GetPointData()->GetArrayName(i));
  for (int i = 0; i < grid->GetCellData()->GetNumberOfArrays(); ++i)
    names.second.insert(grid->GetCellData()->GetArrayName(i));
  return names;
}

}  // namespace

TEST(OutputFields, ASubsetWritesExactlyThoseArraysInEveryVtu) {
  const std::string dir = make_temp_dir("output-fields");
  const auto r = run_rollsim(
      {"run", plastic_cantilever(dir, {"displacement", "plastic_strain"}), "--out", dir + "/out", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string file : {"result.vtu", "results_0001.vtu", "results_0003.vtu"}) {
    const auto [points, cells] = arrays(dir + "/out/" + file);
    EXPECT_EQ(points, (Names{"body_id", "displacement"})) << file;
    EXPECT_EQ(cells, (Names{"body_id", "plastic_strain", "subdomain_id"})) << file;
  }
  const json s = json::parse(read_text(dir + "/out/summary.json"));
  Names listed;
  for (const auto& f : s["fields"])
    listed.insert(f["name"].get<std::string>() + "@" + f["location"].get<std::string>());
  EXPECT_EQ(listed, (Names{"displacement@node", "plastic_strain@cell"}));
}

TEST(OutputFields, ANameWritesItsPointAndCellArraysAndAllWritesEveryField) {
  const std::string dir = make_temp_dir("output-fields-stress");
  auto r = run_rollsim({"run", plastic_cantilever(dir, {"stress"}), "--out", dir + "/stress", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto [points, cells] = arrays(dir + "/stress/result.vtu");
  EXPECT_EQ(points, (Names{"body_id", "stress"}));
  EXPECT_EQ(cells, (Names{"body_id", "stress", "subdomain_id"}));
  r = run_rollsim({"run", plastic_cantilever(dir, {"all"}), "--out", dir + "/all", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::tie(points, cells) = arrays(dir + "/all/result.vtu");
  EXPECT_EQ(points, (Names{"body_id", "displacement", "stress", "von_mises"}));
  EXPECT_EQ(cells, (Names{"body_id", "plastic_strain", "stress", "subdomain_id", "von_mises"}));
}

TEST(OutputFields, BadSelectionsExitTwoListingTheValidNamesAndWriteNothing) {
  const std::string dir = make_temp_dir("output-fields-bad");
  struct Case {
    json fields;
    std::string message;
    bool lists_names;  // the message lists every valid name
  };
  const std::vector<Case> cases = {
      {json{"displacement", "strain"}, "output.fields[1]: must be one of all, displacement, stress, von_mises", true},
      {json{"displacement", "displacement"}, "output.fields[1]: names \"displacement\" a second time", false},
      {json("displacement"), "output.fields: must be an array of at least 1 of: all, displacement", true},
      {json::array(), "output.fields: must be an array of at least 1 of: all, displacement", true}};
  for (const auto& [fields, message, lists_names] : cases) {
    const auto r = run_rollsim({"run", plastic_cantilever(dir, fields), "--out", dir + "/out"});
    EXPECT_EQ(r.exit_code, 2) << fields.dump() << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
    if (lists_names) {
      EXPECT_NE(r.err.find("plastic_strain"), std::string::npos) << "every valid name\n" << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(dir + "/out/summary.json")) << fields.dump();
  }
}

}  // namespace test_output_fields
