// `rollsim run` with analysis.increments: besides result.vtu and summary.json, one VTU per increment and a ParaView
// collection results.pvd whose DataSets name them with timestep = load factor; each VTU opens with VTK's reader and
// carries that increment's displacement; summary.json lists the increments with growing contact force. Bad counts
// exit 2 naming analysis.increments and write nothing.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUtilities.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "RunBinary.h"

namespace test_increments {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

/// The Hertz sample, coarse (mesh size about 0.04 near the contact), with `increments`.
json hertz(const json& increments) {
  json j = json::parse(read_text(ROLLSIM_SOURCE_DIR "/samples/cylinder-indent-2d.json"));
  j["bodies"][0]["mesh"]["nx"] = 38;
  j["bodies"][0]["mesh"]["ny"] = 38;
  j["bodies"][1]["mesh"]["n_around"] = 39;
  j["bodies"][1]["mesh"]["n_radial"] = 22;
  j["boundary_conditions"][3]["fy"] = -2.16 / 23;
  j["analysis"] = {{"increments", increments}};
  return j;
}

double max_displacement(const std::string& vtu) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(vtu.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  EXPECT_GT(grid->GetNumberOfCells(), 0) << vtu;
  vtkDataArray* u = grid->GetPointData()->GetArray("displacement");
  if (!u) {
    ADD_FAILURE() << vtu << " has no displacement";
    return 0;
  }
  double range[2];
  u->GetRange(range, -1);
  return range[1];
}

}  // namespace

TEST(RunIncrements, WritesOneVtuPerIncrementAndAParaViewCollection) {
  const std::string dir = make_temp_dir("increments");
  write_text(dir + "/hertz.json", hertz(3).dump(2));
  const auto r = run_rollsim({"run", dir + "/hertz.json", "--out", dir + "/out", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string out = dir + "/out/";
  EXPECT_TRUE(fs::exists(out + "result.vtu"));
  vtkSmartPointer<vtkXMLDataElement> pvd;
  pvd.TakeReference(vtkXMLUtilities::ReadElementFromFile((out + "results.pvd").c_str()));
  ASSERT_TRUE(pvd) << "results.pvd is not XML";
  EXPECT_STREQ(pvd->GetName(), "VTKFile");
  EXPECT_STREQ(pvd->GetAttribute("type"), "Collection");
  vtkXMLDataElement* collection = pvd->FindNestedElementWithName("Collection");
  ASSERT_TRUE(collection);
  ASSERT_EQ(collection->GetNumberOfNestedElements(), 3);
  std::vector<double> umax;
  for (int i = 0; i < 3; ++i) {
    vtkXMLDataElement* set = collection->GetNestedElement(i);
    EXPECT_STREQ(set->GetName(), "DataSet");
    double t = 0;
    ASSERT_TRUE(set->GetScalarAttribute("timestep", t));
    EXPECT_NEAR(t, (i + 1) / 3.0, 1e-15);
    const std::string file = set->GetAttribute("file");
    ASSERT_TRUE(fs::exists(out + file)) << file;
    umax.push_back(max_displacement(out + file));
  }
  EXPECT_LT(umax[0], umax[1]);
  EXPECT_LT(umax[1], umax[2]);
  EXPECT_DOUBLE_EQ(umax[2], max_displacement(out + "result.vtu"));  // the last increment is the result
  for (const auto& name : list_dir(out)) EXPECT_NE(name.front(), '.') << "a temporary file was left: " << name;
  const json summary = json::parse(read_text(out + "summary.json"));
  EXPECT_EQ(summary["solver"]["increments"], 3);
  ASSERT_EQ(summary["increments"].size(), 3u);
  double previous = 0;
  for (const auto& inc : summary["increments"]) {
    const double f = inc["contact"]["cylinder-block"]["normal_force"];
    EXPECT_GT(f, previous);
    previous = f;
    EXPECT_GE(inc["active_set_iterations"].get<int>(), 1);
    EXPECT_GE(inc["cg_iterations"].get<int>(), 1);
  }
  EXPECT_EQ(summary["increments"][2]["load_factor"], 1.0);
}

TEST(RunIncrements, OneIncrementWritesNoCollection) {
  const std::string dir = make_temp_dir("increments-one");
  write_text(dir + "/hertz.json", hertz(1).dump(2));
  const auto r = run_rollsim({"run", dir + "/hertz.json", "--out", dir + "/out", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/out/result.vtu"));
  EXPECT_FALSE(fs::exists(dir + "/out/results.pvd"));
  EXPECT_EQ(json::parse(read_text(dir + "/out/summary.json"))["increments"].size(), 1u);
}

TEST(RunIncrements, OutputIncrementsLastWritesTheResultOnly) {
  const std::string dir = make_temp_dir("increments-last");
  json j = hertz(3);
  j["output"] = {{"increments", "last"}};
  write_text(dir + "/hertz.json", j.dump(2));
  const auto r = run_rollsim({"run", dir + "/hertz.json", "--out", dir + "/out", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> names = list_dir(dir + "/out");
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"result.vtu", "summary.json"}));
  EXPECT_EQ(json::parse(read_text(dir + "/out/summary.json"))["increments"].size(), 3u) << "the summary keeps them";
  j["output"] = {{"increments", "first"}};
  write_text(dir + "/bad.json", j.dump(2));
  const auto bad = run_rollsim({"run", dir + "/bad.json", "--out", dir + "/bad"});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("output.increments"), std::string::npos) << bad.err;
}

TEST(RunIncrements, BadCountsExitTwoNamingTheField) {
  for (const json& bad : {json(0), json(1.5), json("x"), json(1001), json(-2)}) {
    SCOPED_TRACE(bad.dump());
    const std::string dir = make_temp_dir("increments-bad");
    write_text(dir + "/bad.json", hertz(bad).dump(2));
    const auto r = run_rollsim({"run", dir + "/bad.json", "--out", dir + "/out"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("analysis.increments: must be"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/out/summary.json"));
  }
}

}  // namespace test_increments
