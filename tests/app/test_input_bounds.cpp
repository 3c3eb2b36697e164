// Sizes are bounded before anything is allocated, with one message per class of problem: partitions asking for more
// subdomains than elements (where 400x400 printed 158,501 lines, 40000x40000 ran out of memory and 65536x65536
// overflowed to 0 subdomains), explicit maps with huge ids, meshes beyond 32-bit sparse indices or this machine's
// memory; and two conditions prescribing one dof differently are refused with both JSON paths.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "RunBinary.h"

namespace test_input_bounds {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const std::string kIndent = ROLLSIM_SOURCE_DIR "/samples/block-indent-2d-50x30.json";  // base: 50 x 30 elements

json sample(const std::string& file) { return json::parse(read_text(file)); }

double machine_memory_gb() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  in >> key >> kb;  // MemTotal: <kB>
  return kb / 1e6;
}

int lines(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// `rollsim run` of `project` with `extra` arguments: the result, after checking the refusal's common shape.
RunResult expect_refused(const json& project, const std::vector<std::string>& extra, const std::string& what) {
  const std::string dir = make_temp_dir("bounds"), file = dir + "/p.json", out = dir + "/out";
  write_text(file, project.dump(1));
  std::vector<std::string> args{"run", file, "--out", out, "--quiet"};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = run_rollsim(args, 30);
  EXPECT_FALSE(r.timed_out) << what;
  EXPECT_EQ(r.exit_code, 2) << what << "\n" << r.err.substr(0, 2000);
  EXPECT_EQ(r.err.rfind("rollsim: error: ", 0), 0u) << what;
  EXPECT_FALSE(fs::exists(out)) << what << ": nothing written for invalid input";
  fs::remove_all(dir);
  return r;
}

}  // namespace

TEST(InputBounds, PartitionsAskingForMoreSubdomainsThanElementsAreOneLine) {
  for (const std::string spec : {"400x400", "40000x40000", "65536x65536", "metis:5000"}) {
    const RunResult r = expect_refused(sample(kIndent), {"--solver", "feti", "--partition", "base=" + spec}, spec);
    EXPECT_EQ(lines(r.err), 2) << r.err.substr(0, 2000);
    EXPECT_TRUE(contains(r.err, "bodies[0].partition: '" + spec + "' asks for ")) << r.err;
    EXPECT_TRUE(contains(r.err, "only 1500 elements")) << r.err;
  }
  EXPECT_TRUE(contains(expect_refused(sample(kIndent), {"--partition", "base=65536x65536"}, "int").err,
                       "asks for 4294967296 subdomains"))
      << "counted in 64 bits, not wrapped to 0";
}

TEST(InputBounds, PartitionMapWithAHugeIdIsOneLine) {
  json j = sample(kIndent);
  std::vector<int> map(1500, 0);
  map[17] = 1000000;
  j["bodies"][0]["partition_map"] = map;
  const RunResult r = expect_refused(j, {"--solver", "feti"}, "map id 1e6");
  EXPECT_EQ(lines(r.err), 2) << r.err.substr(0, 2000);
  EXPECT_TRUE(contains(r.err, "bodies[0].partition_map: element 17 has subdomain id 1000000")) << r.err;
}

TEST(InputBounds, MeshesBeyondIndexWidthOrMemoryAreRefusedWithTheEstimate) {
  json j = sample(ROLLSIM_SOURCE_DIR "/samples/cantilever-3d-16x16x16.json");
  j["bodies"][0]["mesh"]["nx"] = 300, j["bodies"][0]["mesh"]["ny"] = 200, j["bodies"][0]["mesh"]["nz"] = 150;
  const RunResult wide = expect_refused(j, {}, "9e6 hexahedra");
  EXPECT_TRUE(contains(wide.err, "beyond the 32-bit sparse index limit")) << wide.err;
  EXPECT_TRUE(contains(wide.err, "at most about 8.84e+06 elements in 3D")) << wide.err;
  j["bodies"][0]["mesh"]["nx"] = 200, j["bodies"][0]["mesh"]["ny"] = 200, j["bodies"][0]["mesh"]["nz"] = 200;
  if (machine_memory_gb() > 58) GTEST_SKIP() << "this machine can assemble 8e6 hexahedra: no memory refusal to see";
  const RunResult big = expect_refused(j, {}, "8e6 hexahedra");
  EXPECT_TRUE(contains(big.err, "8e+06 elements need about 58.2 GB")) << big.err;
  EXPECT_TRUE(contains(big.err, "and this machine has")) << big.err;
}

TEST(InputBounds, ConflictingPrescribedValuesNameBothConditions) {
  json j = sample(ROLLSIM_SOURCE_DIR "/samples/cantilever-2d-240x60.json");
  j["boundary_conditions"].push_back({{"type", "symmetry"}, {"body", "beam"}, {"set", "xmin"}, {"normal", "x"}});
  const std::string dir = make_temp_dir("agree");
  write_text(dir + "/p.json", j.dump(1));
  EXPECT_EQ(run_rollsim({"check", dir + "/p.json"}).exit_code, 0) << "ux = 0 twice agrees";
  fs::remove_all(dir);
  j["boundary_conditions"].push_back({{"type", "displacement"}, {"body", "beam"}, {"set", "xmin"}, {"uy", 0.5}});
  const RunResult r = expect_refused(j, {}, "uy = 0 and uy = 0.5 on xmin");
  EXPECT_TRUE(contains(r.err, "boundary_conditions[3]: prescribes uy = 0.5 at node 0 ")) << r.err;
  EXPECT_TRUE(contains(r.err, "which boundary_conditions[0] prescribes as 0")) << r.err;
  EXPECT_EQ(lines(r.err), 2) << "one message for the pair, not one per node";
}

TEST(InputBounds, EmptySubdomainsAreOneMessage) {
  json j = sample(kIndent);
  std::vector<int> map(1500, 0);
  for (size_t e = 750; e < map.size(); ++e) map[e] = 5;  // ids 1 … 4 unused
  j["bodies"][0]["partition_map"] = map;
  const RunResult r = expect_refused(j, {"--solver", "feti"}, "four empty subdomains");
  EXPECT_EQ(lines(r.err), 2) << r.err;
  EXPECT_TRUE(contains(r.err,
                       "bodies[0].partition_map.subdomains[1]: subdomain 1 has no elements (so do subdomains "
                       "2, 3, 4: 4 in all)"))
      << r.err;
}

// The reported case: a 120³ block passed `check` (the estimate covered assembly only) — its Cholesky factor alone
// needs about 120 GB; a 30³ block's (0.6 GB) fits.
TEST(InputBounds, ABodyWhoseFactorCannotFitIsRefusedByCheck) {
  if (machine_memory_gb() > 150) GTEST_SKIP() << "this machine could factor a 120³ block";
  json j = sample(ROLLSIM_SOURCE_DIR "/samples/cantilever-3d-16x16x16.json");
  j["bodies"][0]["mesh"]["nx"] = 120, j["bodies"][0]["mesh"]["ny"] = 120, j["bodies"][0]["mesh"]["nz"] = 120;
  const RunResult big = expect_refused(j, {}, "120³ hexahedra, direct");
  EXPECT_TRUE(contains(big.err, "to assemble and factor the stiffness")) << big.err;
  EXPECT_TRUE(contains(big.err, "`feti` with subdomains")) << big.err;
  const std::string dir = make_temp_dir("factor-fits"), file = dir + "/p.json";
  json feti = j;
  feti["solver"]["mode"] = "feti", feti["bodies"][0]["partition"] = "4x4x4";
  write_text(file, feti.dump());
  const RunResult split = run_rollsim({"check", file});
  EXPECT_EQ(split.exit_code, 0) << "feti factors subdomains, never the whole body: " << split.err;
  j["bodies"][0]["mesh"]["nx"] = 30, j["bodies"][0]["mesh"]["ny"] = 30, j["bodies"][0]["mesh"]["nz"] = 30;
  write_text(file, j.dump());
  const RunResult small = run_rollsim({"check", file});
  EXPECT_EQ(small.exit_code, 0) << small.err;
  fs::remove_all(dir);
}

// The reported case: under an address-space limit a 30³ block with `direct` ended "internal error: CHOLMOD
// factorization failed" (exit 1). CHOLMOD's symbolic analysis gives the factor's size before it is allocated.
TEST(InputBounds, AFactorBeyondTheAddressSpaceLimitIsOutOfMemoryWithItsSize) {
  json j = sample(ROLLSIM_SOURCE_DIR "/samples/cantilever-3d-16x16x16.json");
  j["bodies"][0]["mesh"]["nx"] = 30, j["bodies"][0]["mesh"]["ny"] = 30, j["bodies"][0]["mesh"]["nz"] = 30;
  j["probes"] = json::array();
  const std::string dir = make_temp_dir("oom"), file = dir + "/p.json", out = dir + "/out";
  write_text(file, j.dump());
  const RunResult r = run_program("/bin/sh",
                                  {"-c", "ulimit -v 1000000; exec '" ROLLSIM_BINARY "' run '" + file + "' --out '" +
                                             out + "' --solver direct --quiet"},
                                  120);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  const std::string text = read_text(out + "/summary.json");
  ASSERT_FALSE(text.empty()) << r.err;
  const json s = json::parse(text);
  EXPECT_EQ(s.value("status", ""), "error");
  const std::string m = s.value("message", "");
  EXPECT_TRUE(contains(m, "out of memory: the Cholesky factor")) << m;
  EXPECT_TRUE(contains(m, "needs at least 0.")) << m;  // 0.6–0.7 GB
  EXPECT_TRUE(contains(m, "the address-space limit (ulimit -v)")) << m;
  fs::remove_all(dir);
}

}  // namespace test_input_bounds
