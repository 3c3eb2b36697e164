// Solver `petsc` through the real binary: under `mpirun -n 4` (one subdomain per rank) PCBDDC and KSPFETIDP give
// the displacements of `direct` on a 2D and a 3D cantilever; inside the Newton driver, a J2-plastic cantilever on 1,
// 2 and 4 ranks takes `direct`'s Newton iterations per increment (±1) to its displacements and reactions, and a load
// beyond the limit ends `diverged` on every rank; MUMPS on the whole bordered system rolls a sticking pass on 1, 2
// and 3 ranks and a Coulomb pass on a partitioned slab as `direct` does, and solves a tied pair; bad input — an
// option PETSc does not use, a rank count that is not the partition's, no mpirun (linear and Newton projects alike),
// contact under bddc / fetidp, an unknown method — exits 2 on every rank with a message. PETSc is a module the binary
// loads when `petsc` is chosen: other commands and modes never map it, and a module that cannot be loaded exits 2
// naming the file, on every rank. Without PETSc in the build, `--solver petsc` exits 2 saying how to build it.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <nlohmann/json.hpp>

#include "RunBinary.h"

namespace test_petsc_run {

using json = nlohmann::json;

namespace {

/// A sample with its block mesh made smaller (the test's time), written into `dir`; `edit` changes it further.
std::string small_sample(const std::string& dir, const std::string& sample, const std::vector<int>& n,
                         const std::function<void(json&)>& edit = {}) {
  json j = json::parse(read_text(ROLLSIM_SOURCE_DIR "/samples/" + sample));
  if (edit) edit(j);
  const char* keys[] = {"nx", "ny", "nz"};
  for (size_t i = 0; i < n.size(); ++i) j["bodies"][0]["mesh"][keys[i]] = n[i];
  j.erase("probes");  // probe points of the full-size mesh may fall between the nodes of the small one
  const std::string file = dir + "/" + sample;
  write_text(file, j.dump(2));
  return file;
}

[[maybe_unused]] json summary(const std::string& dir) {
  const std::string text = read_text(dir + "/summary.json");
  return text.empty() ? json() : json::parse(text);
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

/// max |a − b| / max |a| over every entry (1 when the sizes differ or a is empty).
double relative_difference(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.empty() || a.size() != b.size()) return 1.0;
  double diff = 0, scale = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    diff = std::max(diff, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(a[i]));
  }
  return diff / scale;
}

/// max |u_petsc − u_direct| / max |u_direct| over every node's displacement.
double relative_difference(const std::string& file, const std::string& dir, const std::string& partition,
                           const std::string& method) {
  const auto direct = run_rollsim({"run", file, "--solver", "direct", "--out", dir + "/direct", "--quiet"});
  EXPECT_EQ(direct.exit_code, 0) << direct.err;
  const auto petsc = mpirun(4, {"run", file, "--solver", "petsc", "--petsc-method", method, "--partition", partition,
                                "--cg-tolerance", "1e-10", "--out", dir + "/" + method, "--quiet"});
  EXPECT_EQ(petsc.exit_code, 0) << petsc.err << petsc.out;
  return relative_difference(displacements(dir + "/direct/result.vtu"),
                             displacements(dir + "/" + method + "/result.vtu"));
}

/// Every reaction component of a summary (results.reactions: body → set → vector), in order.
std::vector<double> reactions(const json& s) {
  std::vector<double> r;
  for (const auto& body : s["results"]["reactions"])
    for (const auto& set : body)
      for (const auto& v : set) r.push_back(v.get<double>());
  return r;
}

/// The small J2-plastic cantilever (16 × 4 elements, 5 increments of the tip's push) written into `dir`.
std::string plastic_cantilever(const std::string& dir, const std::function<void(json&)>& edit = {}) {
  return small_sample(dir, "cantilever-plastic-2d.json", {16, 4}, [&](json& j) {
    j["analysis"]["increments"] = 5;
    if (edit) edit(j);
  });
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

// Newton: every rank runs the driver, each assembles its own subdomain's tangent, PETSc solves. The iterations of
// every increment (±1) and the answers are direct's; the plastic strain shows the test is past the elastic range.
TEST(PetscRun, NewtonPlasticCantileverAgreesWithDirectOnOneTwoAndFourRanks) {
  const std::string dir = make_temp_dir("petsc-newton");
  const std::string file = plastic_cantilever(dir);
  const auto direct = run_rollsim({"run", file, "--solver", "direct", "--out", dir + "/direct", "--quiet"});
  ASSERT_EQ(direct.exit_code, 0) << direct.err;
  const json want = summary(dir + "/direct");
  ASSERT_EQ(want["increments"].size(), 5u);
  EXPECT_GT(want["results"]["max_plastic_strain"]["beam"].get<double>(), 1e-3);
  const std::vector<double> u = displacements(dir + "/direct/result.vtu");
  for (const auto& [ranks, partition] : std::vector<std::pair<int, std::string>>{{1, "1x1"}, {2, "2x1"}, {4, "2x2"}}) {
    const std::string out = dir + "/petsc" + std::to_string(ranks);
    const auto r = mpirun(ranks, {"run", file, "--solver", "petsc", "--partition", partition, "--cg-tolerance", "1e-10",
                                  "--out", out, "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << ranks << " ranks\n" << r.err << r.out;
    const json got = summary(out);
    EXPECT_EQ(got["solver"]["mode"], "petsc");
    ASSERT_EQ(got["increments"].size(), want["increments"].size()) << ranks << " ranks";
    for (size_t i = 0; i < want["increments"].size(); ++i)
      EXPECT_NEAR(got["increments"][i]["newton_iterations"].get<int>(),
                  want["increments"][i]["newton_iterations"].get<int>(), 1)
          << ranks << " ranks, increment " << i + 1;
    if (ranks > 1) {  // one subdomain: BDDC's exact interior solve answers before the first iteration
      EXPECT_GT(got["solver"]["cg_iterations_total"].get<long>(), 0) << ranks << " ranks";
    }
    EXPECT_LT(relative_difference(u, displacements(out + "/result.vtu")), 1e-7) << ranks << " ranks";
    EXPECT_LT(relative_difference(reactions(want), reactions(got)), 1e-6) << ranks << " ranks";
    EXPECT_NEAR(got["results"]["max_plastic_strain"]["beam"].get<double>(),
                want["results"]["max_plastic_strain"]["beam"].get<double>(),
                1e-6 * want["results"]["max_plastic_strain"]["beam"].get<double>())
        << ranks << " ranks";
  }
}

/// The small cantilever perfectly plastic (no hardening) under a pressure beyond its limit load, one cut-back allowed.
std::string beyond_the_limit(const std::string& dir) {
  return plastic_cantilever(dir, [](json& j) {
    j["materials"][0]["hardening_modulus"] = 0.0;
    j["boundary_conditions"][1] = {{"type", "pressure"}, {"body", "beam"}, {"surface", "xmax"}, {"value", 2000.0}};
    j["analysis"]["max_cutbacks"] = 1;
  });
}

// A load beyond the limit of a perfectly plastic body: the tangent loses its stiffness, PETSc's CG fails, the steps
// are cut back until none is left — `diverged` naming the increment, on every rank (none left hanging), exit 4.
TEST(PetscRun, NewtonBeyondTheLimitLoadEndsDivergedOnEveryRank) {
  const std::string dir = make_temp_dir("petsc-newton-diverged");
  const std::string file = beyond_the_limit(dir);
  const auto r = mpirun(4, {"run", file, "--solver", "petsc", "--partition", "2x2", "--out", dir + "/out"});
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 4) << r.err;
  const json s = summary(dir + "/out");
  EXPECT_EQ(s["status"], "diverged");
  const std::string message = s["message"].get<std::string>();
  EXPECT_NE(message.find("increment "), std::string::npos) << message;
  EXPECT_NE(message.find("1 cut-backs"), std::string::npos) << message;
  EXPECT_NE(message.find("positive definite"), std::string::npos) << message;
  EXPECT_EQ(message.find("nan"), std::string::npos) << message;
}

// The same load under mumps: LU with pivoting factors the lost tangent, Newton's residual grows, the steps are cut
// back until none is left — `diverged` naming the increment on every rank, no NaN, exit 4.
TEST(PetscRun, MumpsBeyondTheLimitLoadEndsDivergedOnEveryRank) {
  const std::string dir = make_temp_dir("petsc-mumps-diverged");
  const std::string file = beyond_the_limit(dir);
  const auto r = mpirun(3, {"run", file, "--solver", "petsc", "--petsc-method", "mumps", "--out", dir + "/out"});
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 4) << r.err;
  const json s = summary(dir + "/out");
  EXPECT_EQ(s["status"], "diverged");
  const std::string message = s["message"].get<std::string>();
  EXPECT_NE(message.find("increment 2"), std::string::npos) << message;
  EXPECT_NE(message.find("1 cut-backs"), std::string::npos) << message;
  EXPECT_EQ(message.find("nan"), std::string::npos) << message;
}

/// `mpirun -n ranks rollsim run` (a small 2D cantilever in 2×2; `newton`: the small plastic one) with `extra`
/// arguments exits 2 on every rank (no rank left hanging) with `message`.
void expect_refused_by_every_rank(int ranks, const std::vector<std::string>& extra, const std::string& message,
                                  bool newton = false) {
  const std::string dir = make_temp_dir("petsc-refused");
  std::vector<std::string> args{
      "run",         newton ? plastic_cantilever(dir) : small_sample(dir, "cantilever-2d-120x120.json", {8, 8}),
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
  expect_refused_by_every_rank(4, {"--petsc-options", "-no_such_option 3"}, "no_such_option", true);
  expect_refused_by_every_rank(2, {"--petsc-method", "mumps", "--petsc-options", "-no_such_option 3"},
                               "not an option of --petsc-method mumps", true);
}

TEST(PetscRun, RefusesARankCountThatIsNotThePartitions) {
  expect_refused_by_every_rank(2, {}, "one MPI rank per subdomain");
  expect_refused_by_every_rank(2, {}, "one MPI rank per subdomain", true);
}

TEST(PetscRun, WithoutMpirunAPartitionOfFourIsRefused) {
  const std::string dir = make_temp_dir("petsc-nompirun");
  for (const std::string& file : {small_sample(dir, "cantilever-2d-120x120.json", {8, 8}), plastic_cantilever(dir)}) {
    const auto r = run_rollsim({"run", file, "--solver", "petsc", "--partition", "2x2", "--out", dir + "/out"});
    EXPECT_EQ(r.exit_code, 2) << file << "\n" << r.err;
    EXPECT_NE(r.err.find("mpirun -n 4"), std::string::npos) << file << "\n" << r.err;
  }
}

// Under bddc and fetidp contact pairs of every kind are refused before anything is solved, in the linear and the
// Newton analysis alike, naming the pair, its kind and the method that solves them.
TEST(PetscRun, BddcAndFetiDpRefuseContactNamingMumps) {
  const std::string dir = make_temp_dir("petsc-unsupported");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"block-indent-2d-50x30.json", "is tied"},           // linear
      {"cylinder-plastic-2d.json", "is frictionless"},     // Newton
      {"rolling-2d-36x6.json", "contacts[0] 'roll-slab'"}  // Newton, a rolling pass
  };
  for (const auto& [sample, kind] : cases) {
    const auto r = run_rollsim({"run", ROLLSIM_SOURCE_DIR "/samples/" + sample, "--solver", "petsc", "--out", dir});
    EXPECT_EQ(r.exit_code, 2) << sample << "\n" << r.err;
    EXPECT_NE(r.err.find("solves contact-free projects only: --petsc-method mumps solves contact pairs"),
              std::string::npos)
        << sample << "\n"
        << r.err;
    EXPECT_NE(r.err.find(kind), std::string::npos) << sample << "\n" << r.err;
  }
}

/// Every number of a rolling.csv after its header (travel, force, torque, … of every increment), in order.
std::vector<double> rolling_csv(const std::string& dir) {
  std::vector<double> values;
  const std::string text = read_text(dir + "/rolling.csv");
  std::string cell;
  bool header = true;
  for (const char c : text + "\n") {
    if (c == ',' || c == '\n') {
      if (!header && !cell.empty()) values.push_back(std::stod(cell));
      if (c == '\n') header = false;
      cell.clear();
    } else {
      cell += c;
    }
  }
  return values;
}

/// A rolling pass in one process under `reference` and under `petsc` with `method` on each of `ranks`: every rank
/// count gives the reference's Newton iterations, status and rolling.csv (force, torque, contact length, … of every
/// increment) to `tolerance`; the mixed method also its factorizations of every group (the selective update's).
void expect_rolls_as(const std::string& dir, const std::string& project, const std::string& reference,
                     const std::string& method, const std::vector<int>& ranks, double tolerance) {
  const auto one = run_rollsim({"run", project, "--solver", reference, "--out", dir + "/" + reference, "--quiet"});
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const json d = summary(dir + "/" + reference);
  const std::vector<double> expected = rolling_csv(dir + "/" + reference);
  ASSERT_GT(expected.size(), 20u);
  for (int n : ranks) {
    const std::string out = dir + "/" + method + std::to_string(n);
    const auto r = mpirun(n, {"run", project, "--solver", "petsc", "--petsc-method", method, "--out", out, "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << n << " ranks\n" << r.err;
    const json s = summary(out);
    EXPECT_EQ(s["status"], d["status"]) << n;
    EXPECT_EQ(s["solver"]["newton_iterations"], d["solver"]["newton_iterations"]) << n;
    if (method == "mixed") {  // group by group, as the reference (mumps refactors its one matrix, torn or not)
      EXPECT_EQ(s["solver"]["factorizations"], d["solver"]["factorizations"]) << n;
      long total = 0, per_rank = 0;  // and per rank: every group on one rank, g mod n
      for (const auto& f : s["solver"]["factorizations"]) total += f.get<long>();
      for (const auto& rank : s["solver"]["ranks"]["per_rank"]) per_rank += rank["factorizations"].get<long>();
      EXPECT_EQ(per_rank, total) << n;
      EXPECT_EQ(s["solver"]["ranks"]["per_rank"].size(), static_cast<size_t>(n));
      for (const auto& rank : s["solver"]["ranks"]["per_rank"]) EXPECT_GT(rank["factorize_s"].get<double>(), 0.0) << n;
    }
    EXPECT_GT(s["results"]["rolling"]["roll_force"].get<double>(), 1000.0) << n;  // the slab is being rolled
    EXPECT_LT(relative_difference(expected, rolling_csv(out)), tolerance) << n << " ranks";
  }
}

/// The main job's pass, 6 mm of travel, its interface solved by CG (the mixed method over MPI has no dense interface),
/// written into `dir`.
std::string short_pass(const std::string& dir) {
  const std::string file = dir + "/pass.json";
  json j = json::parse(read_text(ROLLSIM_SOURCE_DIR "/samples/rolling-2d-36x6.json"));
  j["process"]["travel"] = 6;
  j["solver"]["interface_solver"] = "krylov";
  write_text(file, j.dump(2));
  return file;
}

/// The partitioned pass (slab in 4 subdomains) made small, Coulomb μ 0.35 in 0.5 mm steps, written into `dir`.
std::string coulomb_partitioned_pass(const std::string& dir) {
  const std::string file = dir + "/pass.json";
  json j = json::parse(read_text(ROLLSIM_SOURCE_DIR "/samples/rolling-2d-72x12-dd.json"));
  j["process"]["slab_nx"] = 36;
  j["process"]["slab_nt"] = 6;
  j["process"]["roll_n_around"] = 60;
  j["process"]["travel"] = 3;
  j["process"]["travel_increment"] = 0.5;
  j["process"]["friction"] = "coulomb";
  j["process"]["friction_coefficient"] = 0.35;
  write_text(file, j.dump(2));
  return file;
}

// MUMPS on the whole bordered system: a sticking rolling pass (two groups, slab and roll) on 1, 2 and 3 ranks — the
// third rank assembles no group, only factors — takes direct's iterations to direct's forces.
TEST(PetscRun, MumpsRollsASticking2DPassAsDirectOnOneTwoAndThreeRanks) {
  const std::string dir = make_temp_dir("petsc-mumps-rolling");
  expect_rolls_as(dir, short_pass(dir), "direct", "mumps", {1, 2, 3}, 1e-9);
}

// Coulomb friction (an unsymmetric bordered matrix where points slip) on a slab torn into four subdomains (glue rows
// beside the contact rows, five groups over three ranks).
TEST(PetscRun, MumpsRollsACoulombPassOnAPartitionedSlabAsDirect) {
  const std::string dir = make_temp_dir("petsc-mumps-coulomb");
  expect_rolls_as(dir, coulomb_partitioned_pass(dir), "direct", "mumps", {3}, 1e-8);
}

// The paper's mixed method over MPI: slab and roll on their own ranks (or both on one), each factoring its own group
// only when its tangent changed — `mixed`'s iterations and factorizations, its forces.
TEST(PetscRun, MixedMethodRollsASticking2DPassAsMixedOnOneAndTwoRanks) {
  const std::string dir = make_temp_dir("petsc-mixed-rolling");
  expect_rolls_as(dir, short_pass(dir), "mixed", "mixed", {1, 2}, 1e-9);
}

// A rank would hold no group: refused on every rank, naming both counts and the ways out.
TEST(PetscRun, MixedMethodRefusesMoreRanksThanGroupsOnEveryRank) {
  const std::string dir = make_temp_dir("petsc-mixed-ranks");
  const auto r =
      mpirun(3, {"run", short_pass(dir), "--solver", "petsc", "--petsc-method", "mixed", "--out", dir + "/o"});
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("3 MPI ranks for 2 groups (bodies and subdomains)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--petsc-method mumps, which takes any number of ranks"), std::string::npos) << r.err;
}

// Five groups (four slab subdomains and the roll) over three ranks, the interface unsymmetric where points slip
// (projected GMRES): `feti`'s iterations, factorizations and forces.
TEST(PetscRun, MixedMethodRollsACoulombPassOnAPartitionedSlabAsFeti) {
  const std::string dir = make_temp_dir("petsc-mixed-coulomb");
  expect_rolls_as(dir, coulomb_partitioned_pass(dir), "feti", "mixed", {3}, 1e-8);
}

// With FETI's Dirichlet preconditioner, applied by each rank to its own subdomains and summed: `feti`'s Newton
// iterations, factorizations and forces, and its interface iterations to round-off (±2 %).
TEST(PetscRun, MixedMethodWithTheDirichletPreconditionerRollsAsFeti) {
  const std::string dir = make_temp_dir("petsc-mixed-dirichlet");
  const std::string file = dir + "/pass.json";
  json j = json::parse(read_text(coulomb_partitioned_pass(dir)));
  j["solver"]["preconditioner"] = "dirichlet";
  write_text(file, j.dump(2));
  expect_rolls_as(dir, file, "feti", "mixed", {5}, 1e-8);
  const json plain = summary(dir + "/feti"), spread = summary(dir + "/mixed5");
  EXPECT_NEAR(
      spread["solver"]["cg_iterations_total"].get<double>() / plain["solver"]["cg_iterations_total"].get<double>(), 1.0,
      0.02);  // the same interface solves, to round-off in their sums
}

TEST(PetscRun, MixedMethodRefusesTheWeightedProjectorOnEveryRank) {
  const std::string dir = make_temp_dir("petsc-mixed-refused");
  const auto r = mpirun(2, {"run", short_pass(dir), "--solver", "petsc", "--petsc-method", "mixed",
                            "--interface-solver", "dense", "--out", dir + "/out"});
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("solver.interface_solver must be krylov and solver.projector identity (on the command line: "
                       "--interface-solver krylov --projector identity)"),
            std::string::npos)
      << r.err;
}

// A linear analysis with a tied pair: the displacements of direct.
TEST(PetscRun, MumpsSolvesALinearTiedContactAsDirect) {
  const std::string dir = make_temp_dir("petsc-mumps-tied");
  const std::string file = ROLLSIM_SOURCE_DIR "/samples/block-indent-2d-50x30.json";
  const auto direct = run_rollsim({"run", file, "--solver", "direct", "--out", dir + "/direct", "--quiet"});
  ASSERT_EQ(direct.exit_code, 0) << direct.err;
  const auto r =
      mpirun(2, {"run", file, "--solver", "petsc", "--petsc-method", "mumps", "--out", dir + "/mumps", "--quiet"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_LT(relative_difference(displacements(dir + "/direct/result.vtu"), displacements(dir + "/mumps/result.vtu")),
            1e-10);
}

/// Sets an environment variable for the processes spawned in its scope (unset again after).
struct ScopedEnv {
  ScopedEnv(const char* name, const std::string& value) : name_(name) { setenv(name, value.c_str(), 1); }
  ~ScopedEnv() { unsetenv(name_); }
  const char* name_;
};

// The dynamic loader's own account (LD_DEBUG=files lists every object it maps): neither `--version`, `check` nor a
// `direct` run maps PETSc; a `petsc` run maps the module and, through it, libpetsc.
TEST(PetscRun, TheModuleIsMappedOnlyWhenPetscIsChosen) {
  const std::string dir = make_temp_dir("petsc-lazy");
  const std::string file = small_sample(dir, "cantilever-2d-120x120.json", {8, 8});
  const ScopedEnv debug("LD_DEBUG", "files");
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"--version"}, {"check", file}, {"run", file, "--solver", "direct", "--out", dir + "/direct", "--quiet"}}) {
    const auto r = run_rollsim(args);
    EXPECT_EQ(r.exit_code, 0) << args[0] << "\n" << r.err;
    EXPECT_EQ(r.err.find("libpetsc"), std::string::npos) << args[0];
    EXPECT_EQ(r.err.find("rollsim_petsc.so"), std::string::npos) << args[0];
  }
  const auto r =
      run_rollsim({"run", file, "--solver", "petsc", "--partition", "1x1", "--out", dir + "/petsc", "--quiet"});
  EXPECT_EQ(r.exit_code, 0) << r.err.substr(r.err.size() > 4000 ? r.err.size() - 4000 : 0);
  EXPECT_NE(r.err.find("rollsim_petsc.so"), std::string::npos);
  EXPECT_NE(r.err.find("libpetsc"), std::string::npos);
}

// A module that is missing, is not a library, or lacks the entry point: exit 2 naming the file and dlerror()'s
// reason; under mpirun every rank refuses before MPI starts, none is left hanging.
TEST(PetscRun, AModuleThatCannotBeLoadedIsRefusedNamingTheFile) {
  const std::string dir = make_temp_dir("petsc-module");
  const std::string file = small_sample(dir, "cantilever-2d-120x120.json", {8, 8});
  const std::vector<std::pair<std::string, std::string>> cases = {
      {dir + "/missing/rollsim_petsc.so", "No such file"},
      {file, "cannot load its module " + file},  // a JSON file: not a shared object
      {"libm.so.6", "no entry point rollsim_petsc_module"}};
  for (const auto& [module, words] : cases) {
    const ScopedEnv env("ROLLSIM_PETSC_MODULE", module);
    const auto r = run_rollsim({"run", file, "--solver", "petsc", "--partition", "1x1", "--out", dir + "/out"});
    EXPECT_EQ(r.exit_code, 2) << module << "\n" << r.err;
    EXPECT_NE(r.err.find("cannot load its module " + module), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(words), std::string::npos) << r.err;
  }
  const ScopedEnv env("ROLLSIM_PETSC_MODULE", dir + "/missing/rollsim_petsc.so");
  const auto r = mpirun(2, {"run", file, "--solver", "petsc", "--partition", "2x1", "--out", dir + "/out"});
  EXPECT_FALSE(r.timed_out);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("cannot load its module"), std::string::npos) << r.err;
}

TEST(PetscRun, RefusesAnUnknownMethod) {
  const auto r = run_rollsim(
      {"run", ROLLSIM_SOURCE_DIR "/samples/plate-hole-2d.json", "--solver", "petsc", "--petsc-method", "gamg"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--petsc-method: must be one of bddc, fetidp, mumps, mixed, got \"gamg\""), std::string::npos)
      << r.err;
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

}  // namespace test_petsc_run
