// The result files in a rolling engineer's terms: ParaView's time of a rolling pass is the roll travel [mm] (the
// load factor rides along as field data), summary.json's increments carry the travel too, and the VTU arrays are
// raw binary compressed by output.compression (LZ4 by default) — smaller than the base64 files they replace, read
// back by VTK's own reader to the same values.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "RunBinary.h"

namespace test_result_files {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {
bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct Pass {
  std::string dir, out;
  json summary;
};

/// The main job over 10 mm of travel, every increment written, with `compression`.
Pass run_pass(const std::string& compression) {
  Pass p;
  json j = json::parse(read_text(ROLLSIM_SOURCE_DIR "/samples/rolling-2d-36x6.json"));
  j["process"]["travel"] = 10;
  j["output"] = {{"increments", "all"}, {"compression", compression}};
  p.dir = make_temp_dir("result-files");
  p.out = p.dir + "/out";
  write_text(p.dir + "/p.json", j.dump());
  const RunResult r = run_rollsim({"run", p.dir + "/p.json", "--out", p.out, "--quiet"});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  p.summary = json::parse(read_text(p.out + "/summary.json"));
  return p;
}

vtkSmartPointer<vtkUnstructuredGrid> read_grid(const std::string& file) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  return reader->GetOutput();
}
}  // namespace

TEST(ResultFiles, ARollingPassIsTimedByTravelAndCarriesItsLoadFactor) {
  const Pass p = run_pass("lz4");
  const std::string pvd = read_text(p.out + "/results.pvd");
  EXPECT_TRUE(contains(pvd, "<!-- timestep: travel [length] -->")) << pvd;
  const json& incs = p.summary["increments"];
  ASSERT_GE(incs.size(), 5u);
  const std::string last = "file=\"results_" + std::string(4 - std::to_string(incs.size()).size(), '0') +
                           std::to_string(incs.size()) + ".vtu\"";
  EXPECT_TRUE(contains(pvd, "timestep=\"10\" group=\"\" part=\"0\" " + last)) << pvd;  // the whole travel
  for (const json& inc : incs)
    EXPECT_DOUBLE_EQ(inc.value("travel", -1.0), 10 * inc.value("load_factor", 0.0)) << inc.dump();
  const auto grid = read_grid(p.out + "/results_0004.vtu");
  ASSERT_TRUE(grid->GetFieldData()->GetArray("load_factor"));
  const double lf = incs[3].value("load_factor", 0.0);
  EXPECT_DOUBLE_EQ(grid->GetFieldData()->GetArray("load_factor")->GetTuple1(0), lf);
  EXPECT_DOUBLE_EQ(grid->GetFieldData()->GetArray("travel")->GetTuple1(0), 10 * lf);
  char step[40];
  std::snprintf(step, sizeof step, "timestep=\"%.17g\"", 10 * lf);
  EXPECT_TRUE(contains(pvd, std::string(step) + " group=\"\" part=\"0\" file=\"results_0004.vtu\"")) << pvd;
  ASSERT_TRUE(grid->GetCellData()->GetArray("jacobian_ratio")) << "the finite-strain pass writes element quality";
  double range[2];
  grid->GetCellData()->GetArray("jacobian_ratio")->GetRange(range);
  EXPECT_GT(range[0], 0.0) << "no element of a converged pass has folded";
  EXPECT_LT(range[0], 1.0) << "the slab in the roll gap is squeezed";
  fs::remove_all(p.dir);
}

TEST(ResultFiles, CompressedFilesAreSmallerAndReadBackTheSame) {
  const Pass lz4 = run_pass("lz4"), none = run_pass("none");
  const std::string head = read_text(lz4.out + "/result.vtu").substr(0, 400);
  EXPECT_TRUE(contains(head, "compressor=\"vtkLZ4DataCompressor\"")) << head;
  EXPECT_LT(fs::file_size(lz4.out + "/result.vtu"), fs::file_size(none.out + "/result.vtu"));
  const auto a = read_grid(lz4.out + "/result.vtu"), b = read_grid(none.out + "/result.vtu");
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  vtkDataArray* ua = a->GetPointData()->GetArray("displacement");
  vtkDataArray* ub = b->GetPointData()->GetArray("displacement");
  ASSERT_TRUE(ua && ub);
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i) EXPECT_EQ(ua->GetComponent(i, 1), ub->GetComponent(i, 1));
  fs::remove_all(lz4.dir);
  fs::remove_all(none.dir);
}

}  // namespace test_result_files
