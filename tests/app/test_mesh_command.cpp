// `rollsim mesh`: the model's meshes as mesh.vtu without solving — counts in the VTU header equal the model's,
// the body and subdomain arrays are there, partition.json holds the partition table, and bad input exits 2 writing
// nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>

#include "RunBinary.h"

namespace test_mesh_command {

namespace fs = std::filesystem;

namespace {

long header_count(const std::string& vtu, const std::string& attribute) {
  std::smatch m;
  const std::regex re(attribute + "=\"([0-9]+)\"");
  return std::regex_search(vtu, m, re) ? std::stol(m[1]) : -1;
}

}  // namespace

TEST(MeshCommand, WritesTheGeneratedRollingMeshesWithoutSolving) {
  const std::string dir = make_temp_dir("mesh");
  const auto r = run_rollsim(
      {"mesh", ROLLSIM_SOURCE_DIR "/samples/rolling-3d-16x8x4.json", "--out", dir, "--partition", "slab=4x2x1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, dir + "/mesh.vtu\n");
  const std::string vtu = read_text(dir + "/mesh.vtu");
  // the same counts as `rollsim check` reports for the project
  const auto check = run_rollsim({"check", ROLLSIM_SOURCE_DIR "/samples/rolling-3d-16x8x4.json"});
  std::smatch m;
  ASSERT_TRUE(std::regex_search(check.out, m, std::regex("([0-9]+) nodes, ([0-9]+) elements"))) << check.out;
  EXPECT_EQ(header_count(vtu, "NumberOfPoints"), std::stol(m[1]));
  EXPECT_EQ(header_count(vtu, "NumberOfCells"), std::stol(m[2]));
  EXPECT_NE(vtu.find("Name=\"body_id\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"subdomain_id\""), std::string::npos);
  EXPECT_EQ(vtu.find("Name=\"displacement\""), std::string::npos);  // nothing was solved
  EXPECT_FALSE(fs::exists(dir + "/summary.json"));
  // the window's partition table, for batch users: 8 subdomains of the slab and their predicted cost
  const std::string table = read_text(dir + "/partition.json");
  EXPECT_NE(table.find("\"body\": \"slab\""), std::string::npos) << table;
  EXPECT_NE(table.find("\"subdomain_count\": 8"), std::string::npos) << table;
  EXPECT_NE(table.find("\"predicted_ratio\""), std::string::npos) << table;
}

TEST(MeshCommand, NoPartitionTableWithoutAPartition) {
  const std::string dir = make_temp_dir("mesh-whole");
  const auto r = run_rollsim({"mesh", ROLLSIM_SOURCE_DIR "/samples/plate-hole-2d.json", "--out", dir});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir + "/mesh.vtu"));
  EXPECT_FALSE(fs::exists(dir + "/partition.json"));
}

TEST(MeshCommand, BadInputExitsTwoWritingNothing) {
  const std::string dir = make_temp_dir("mesh-bad");
  const auto r = run_rollsim(
      {"mesh", ROLLSIM_SOURCE_DIR "/samples/plate-hole-2d.json", "--out", dir + "/out", "--partition", "plate=0x2"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("rollsim: error:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/out/mesh.vtu"));
}

}  // namespace test_mesh_command
