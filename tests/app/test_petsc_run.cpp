// Solver `petsc` through the real binary: under `mpirun -n 4` (one subdomain per rank) PCBDDC and KSPFETIDP give
// the displacements of `direct` on a 2D and a 3D cantilever; bad input — an option PETSc does not use, a rank
// count that is not the partition's, no mpirun, contact, a Newton project, an unknown method — exits 2 on every rank
// with a message. Without PETSc in the build, `--solver petsc` exits 2 saying how to build it.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "RunBinary.h"

using json = nlohmann::json;

namespace {

/// A sample with its block mesh made smaller (the test's time), written into `dir`.
std::string small_sample(const std::string& dir, const std::string& sample, const std::vector<int>& n) {
  json j = json::parse(read_text(ROLLSIM_SOURCE_DIR "/samples/" + sample));
  const char* keys[] = {"nx", "ny", "nz"};
  for (size_t i = 0; i < n.size(); ++i) j["bodies"][0]["mesh"][keys[i]] = n[i];
  j.erase("probes");  // probe points of the full-size mesh may fall between the nodes of the small one
  const std::string file = dir + "/" + sample;
  write_text(file, j.dump(2));
  return file;
}

[[maybe_unused]] std::vector<double> displacements(const std::string& vtu) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(vtu.c_str());
  reader->Update();
  vtkDataArray* u = reader->GetOutput()->GetPointData()->GetArray("displacement");
  std::vector<double> values;
  if (!u) return values;
  for (vtkIdType i = 0; i < u->GetNumberOfTuples(); ++i)
    for (int c = 0; c < u->GetNumberOfComponents(); ++c) values.push_back(u->GetComponent(i, c));
  return values;
}

#ifdef ROLLSIM_HAVE_PETSC
/// `mpirun -n ranks --oversubscribe rollsim args…` (as root too: CI runs as root).
RunResult mpirun(int ranks, const std::vector<std::string>& args, int timeout_s = 120) {
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 1);
  std::vector<std::string> all{"-n", std::to_string(ranks), "--oversubscribe", ROLLSIM_BINARY};
  all.insert(all.end(), args.begin(), args.end());
  return run_program(ROLLSIM_MPIEXEC, all, timeout_s);
}

/// max |u_petsc − u_direct| / max |u_direct| over every node's displacement.
double relative_difference(const std::string& file, const std::string& dir, const std::string& partition,
                           const std::string& method) {
  const auto direct = run_rollsim({"run", file, "--solver", "direct", "--out", dir + "/direct", "--quiet"});
  EXPECT_EQ(direct.exit_code, 0) << direct.err;
  const auto petsc = mpirun(4, {"run", file, "--solver", "petsc", "--petsc-method", method, "--partition", partition,
                                "--cg-tolerance", "1e-10", "--out", dir + "/" + method, "--quiet"});
  EXPECT_EQ(petsc.exit_code, 0) << petsc.err << petsc.out;
  const std::vector<double> a = displacements(dir + "/direct/result.vtu"),
                            b = displacements(dir + "/" + method + "/result.vtu");
  if (a.empty() || a.size() != b.size()) return 1.0;
  double diff = 0, scale = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(a[i]));
  }
  return diff / scale;
}

TEST(PetscRun, Bddc2DCantileverAgreesWithDirect) {
  const std::string dir = make_temp_dir("petsc2d");
  const std::string file = small_sample(dir, "cantilever-2d-120x120.json", {24, 24});
  EXPECT_LT(relative_difference(file, dir, "2x2", "bddc"), 1e-7);
}

TEST(PetscRun, FetiDp2DCantileverAgreesWithDirect) {
  const std::string dir = make_temp_dir("petsc2d-fetidp");
  const std::string file = small_sample(dir, "cantilever-2d-120x120.json", {24, 24});
  EXPECT_LT(relative_difference(file, dir, "2x2", "fetidp"), 1e-7);
}

TEST(PetscRun, Bddc3DCantileverAgreesWithDirect) {
  const std::string dir = make_temp_dir("petsc3d");
  const std::string file = small_sample(dir, "cantilever-3d-16x16x16.json", {6, 6, 6});
  EXPECT_LT(relative_difference(file, dir, "2x2x1", "bddc"), 1e-7);
}

TEST(PetscRun, FetiDp3DCantileverAgreesWithDirect) {
  const std::string dir = make_temp_dir("petsc3d-fetidp");
  const std::string file = small_sample(dir, "cantilever-3d-16x16x16.json", {6, 6, 6});
  EXPECT_LT(relative_difference(file, dir, "2x2x1", "fetidp"), 1e-7);
}

/// `mpirun -n ranks rollsim run` (a small 2D cantilever in 2×2) with `extra` arguments exits 2 on every rank (no
/// rank left hanging) with `message`.
void expect_refused_by_every_rank(int ranks, const std::vector<std::string>& extra, const std::string& message) {
  const std::string dir = make_temp_dir("petsc-refused");
  std::vector<std::string> args{"run",         small_sample(dir, "cantilever-2d-120x120.json", {8, 8}),
                                "--solver",    "petsc",
                                "--partition", "2x2",
                                "--out",       dir + "/out"};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = mpirun(ranks, args);
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
}

TEST(PetscRun, RefusesAnOptionPetscDoesNotUseOnEveryRank) {
  expect_refused_by_every_rank(4, {"--petsc-options", "-no_such_option 3"}, "no_such_option");
}

TEST(PetscRun, RefusesARankCountThatIsNotThePartitions) {
  expect_refused_by_every_rank(2, {}, "one MPI rank per subdomain");
}

TEST(PetscRun, WithoutMpirunAPartitionOfFourIsRefused) {
  const std::string dir = make_temp_dir("petsc-nompirun");
  const std::string file = small_sample(dir, "cantilever-2d-120x120.json", {8, 8});
  const auto r = run_rollsim({"run", file, "--solver", "petsc", "--partition", "2x2", "--out", dir + "/out"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("mpirun -n 4"), std::string::npos) << r.err;
}

TEST(PetscRun, ContactAndNewtonAreNotYetSupported) {
  const std::string dir = make_temp_dir("petsc-unsupported");
  for (const std::string sample : {"block-indent-2d-50x30.json", "rolling-2d-36x6.json"}) {  // tied contact; Newton
    const auto r = run_rollsim({"run", ROLLSIM_SOURCE_DIR "/samples/" + sample, "--solver", "petsc", "--out", dir});
    EXPECT_EQ(r.exit_code, 2) << sample << "\n" << r.err;
    EXPECT_NE(r.err.find("not yet support"), std::string::npos) << sample << "\n" << r.err;
  }
}

TEST(PetscRun, RefusesAnUnknownMethod) {
  const auto r = run_rollsim(
      {"run", ROLLSIM_SOURCE_DIR "/samples/plate-hole-2d.json", "--solver", "petsc", "--petsc-method", "gamg"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("bddc or fetidp"), std::string::npos) << r.err;
}
#else
TEST(PetscRun, ABuildWithoutPetscRefusesTheStrategy) {
  const std::string dir = make_temp_dir("petsc-none");
  const std::string file = small_sample(dir, "cantilever-2d-120x120.json", {8, 8});
  const auto r = run_rollsim({"run", file, "--solver", "petsc", "--out", dir + "/out"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("ROLLSIM_WITH_PETSC"), std::string::npos) << r.err;
}
#endif

}  // namespace
