#include "solve/PetscBordered.h"

#include <petscksp.h>

#include <cmath>

#include "base/Stopwatch.h"
#include "solve/BorderedMatrix.h"
#include "solve/ConstraintBasis.h"
#include "solve/PetscDistribution.h"
#include "solve/PetscSupport.h"
#include "solve/SparseCompare.h"

namespace rollsim {

namespace {

class PetscBordered final : public SolverStrategy {
 public:
  explicit PetscBordered(SolverOptions options) : options_(std::move(options)), spread_(mpi_group_distribution()) {}
  ~PetscBordered() override { release(); }
  PetscBordered(const PetscBordered&) = delete;
  PetscBordered& operator=(const PetscBordered&) = delete;

  BlockSolution solve(const BlockSystem& sys, AnalysisObserver* observer) override;
  const SolveStats& stats() const override { return stats_; }
  bool uses_subdomains() const override { return true; }  // a partition spreads the assembly over more ranks
  const SolverOptions& options() const override { return options_; }
  std::vector<size_t> local_groups(std::vector<size_t> groups) const override {
    std::vector<size_t> mine;  // as the mixed method spreads them: group g on rank g mod P
    for (size_t g : groups)
      if (spread_->holds(g)) mine.push_back(g);
    return mine;
  }
  bool solves_unsymmetric() const override { return true; }  // LU
  bool assembles_globally() const override { return true; }

 private:
  /// A_ from this rank's entries (its groups' K; rank 0 the border), a new matrix and KSP when any rank's positions
  /// changed (an active-set change), else the values only: MUMPS then refactors on the analysis it has.
  void assemble(const BlockSystem& sys);
  void factorize(const BlockSystem& sys, AnalysisObserver* observer);
  std::vector<size_t> my_groups(const BlockSystem& sys) const;
  /// b from every rank's own groups' f (a linear analysis assembles no other) and rank 0's d.
  void set_right_hand_side(const BlockSystem& sys, Vec b) const;
  Eigen::VectorXd solve_bordered(const BlockSystem& sys);
  void release();

  SolverOptions options_;
  std::shared_ptr<const GroupDistribution> spread_;
  SolveStats stats_;
  ConstraintBasis basis_;
  Mat A_ = nullptr;
  KSP ksp_ = nullptr;
  std::vector<PetscInt> rows_, cols_;  // this rank's entries' positions in A_
  BorderedFactorKey key_;  // what the factor was made from: the same on every rank (each runs the driver alike)
  petsc::PassedOptions passed_{options_.petsc_options, "mumps"};
};

void PetscBordered::release() {
  if (ksp_) KSPDestroy(&ksp_);
  if (A_) MatDestroy(&A_);
  key_.clear();
}

void PetscBordered::assemble(const BlockSystem& sys) {
  std::vector<char> mine(sys.groups.size(), 0);
  for (size_t g : my_groups(sys)) mine[g] = 1;
  const Triplets t = bordered_entries(sys, basis_.kept, mine, petsc::rank() == 0);
  std::vector<PetscInt> rows, cols;
  std::vector<PetscScalar> values;
  for (const auto& e : t) {
    rows.push_back(e.row());
    cols.push_back(e.col());
    values.push_back(e.value());
  }
  if (!petsc::on_all_ranks(A_ && rows == rows_ && cols == cols_)) {
    release();
    const PetscInt N = static_cast<PetscInt>(sys.num_dofs() + static_cast<long>(basis_.kept.size()));
    ROLLSIM_PETSC(MatCreate(PETSC_COMM_WORLD, &A_));
    ROLLSIM_PETSC(MatSetSizes(A_, PETSC_DECIDE, PETSC_DECIDE, N, N));
    ROLLSIM_PETSC(MatSetType(A_, MATAIJ));
    rows_ = rows;
    cols_ = cols;
    ROLLSIM_PETSC(MatSetPreallocationCOO(A_, static_cast<PetscCount>(rows.size()), rows.data(), cols.data()));
    ROLLSIM_PETSC(KSPCreate(PETSC_COMM_WORLD, &ksp_));
    ROLLSIM_PETSC(KSPSetType(ksp_, KSPPREONLY));
    PC pc = nullptr;
    ROLLSIM_PETSC(KSPGetPC(ksp_, &pc));
    ROLLSIM_PETSC(PCSetType(pc, PCLU));
    ROLLSIM_PETSC(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    ROLLSIM_PETSC(KSPSetOperators(ksp_, A_, A_));
    ROLLSIM_PETSC(KSPSetFromOptions(ksp_));
  }
  ROLLSIM_PETSC(MatSetValuesCOO(A_, values.data(), INSERT_VALUES));
}

void PetscBordered::factorize(const BlockSystem& sys, AnalysisObserver* observer) {
  basis_ = independent_rows(stacked_constraints(sys));  // every rank finds the same rows
  Stopwatch t;
  assemble(sys);
  ROLLSIM_PETSC(KSPSetUp(ksp_));
  PC pc = nullptr;
  ROLLSIM_PETSC(KSPGetPC(ksp_, &pc));
  PCFailedReason failed = PC_NOERROR;
  ROLLSIM_PETSC(PCGetFailedReason(pc, &failed));
  if (!petsc::on_all_ranks(failed == PC_NOERROR))
    throw SingularMatrix("petsc (mumps): the LU factorization of the bordered matrix failed (" +
                             std::string(failed == PC_NOERROR ? "on another rank" : PCFailedReasons[failed]) +
                             "): the matrix is singular",
                         -1);
  Mat F = nullptr;
  ROLLSIM_PETSC(PCFactorGetMatrix(pc, &F));
  PetscReal flops = 0;
  ROLLSIM_PETSC(MatMumpsGetRinfog(F, 3, &flops));  // RINFOG(3): the elimination's flops, all ranks together
  stats_.factor_flops_total += flops;
  stats_.factorize_s += t.seconds();
  key_.record(sys);
  for (const Group& g : sys.groups) {
    ++stats_.factorizations[g.name];
    if (observer) observer->on_factorization(g.name);
  }
}

/// Each group's first row in A_ (groups one after the other by their C's columns), and the end.
std::vector<long> group_offsets(const BlockSystem& sys) {
  std::vector<long> offset(sys.groups.size() + 1, 0);
  for (size_t g = 0; g < sys.groups.size(); ++g) offset[g + 1] = offset[g] + sys.groups[g].C.cols();
  return offset;
}

std::vector<size_t> PetscBordered::my_groups(const BlockSystem& sys) const {
  std::vector<size_t> all(sys.groups.size());
  for (size_t g = 0; g < all.size(); ++g) all[g] = g;
  return local_groups(all);
}

void PetscBordered::set_right_hand_side(const BlockSystem& sys, Vec b) const {
  const std::vector<long> offset = group_offsets(sys);
  std::vector<PetscInt> rows;
  std::vector<PetscScalar> values;
  for (size_t g : my_groups(sys))
    for (long i = 0; i < sys.groups[g].f.size(); ++i) {
      rows.push_back(static_cast<PetscInt>(offset[g] + i));
      values.push_back(sys.groups[g].f[i]);
    }
  if (petsc::rank() == 0)
    for (size_t i = 0; i < basis_.kept.size(); ++i) {
      rows.push_back(static_cast<PetscInt>(offset.back() + static_cast<long>(i)));
      values.push_back(sys.d[basis_.kept[i]]);
    }
  ROLLSIM_PETSC(VecSetValues(b, static_cast<PetscInt>(rows.size()), rows.data(), values.data(), ADD_VALUES));
  ROLLSIM_PETSC(VecAssemblyBegin(b));
  ROLLSIM_PETSC(VecAssemblyEnd(b));
}

/// The solve and its solution on every rank, refused when its backward error is above round-off.
Eigen::VectorXd PetscBordered::solve_bordered(const BlockSystem& sys) {
  Vec x = nullptr, b = nullptr, r = nullptr;
  ROLLSIM_PETSC(MatCreateVecs(A_, &x, &b));
  set_right_hand_side(sys, b);
  ROLLSIM_PETSC(KSPSolve(ksp_, b, x));
  // the normwise backward error, as `direct` checks it: MUMPS stops only at an exactly zero pivot
  ROLLSIM_PETSC(VecDuplicate(b, &r));
  ROLLSIM_PETSC(MatMult(A_, x, r));
  ROLLSIM_PETSC(VecAYPX(r, -1.0, b));
  PetscReal norm_r = 0, norm_A = 0, norm_x = 0, norm_b = 0;
  ROLLSIM_PETSC(VecNorm(r, NORM_INFINITY, &norm_r));
  ROLLSIM_PETSC(MatNorm(A_, NORM_INFINITY, &norm_A));
  ROLLSIM_PETSC(VecNorm(x, NORM_INFINITY, &norm_x));
  ROLLSIM_PETSC(VecNorm(b, NORM_INFINITY, &norm_b));
  Eigen::VectorXd out = petsc::on_every_rank(x);
  for (Vec* v : {&x, &b, &r}) VecDestroy(v);
  if (const double scale = norm_A * norm_x + norm_b; std::isfinite(scale))
    check_backward_error(norm_r / std::max(scale, 1e-300));  // the same on every rank: the norms are collective
  return out;
}

BlockSolution PetscBordered::solve(const BlockSystem& sys, AnalysisObserver* observer) {
  petsc::start();
  passed_.insert();
  if (!ksp_ || !key_.matches(sys)) factorize(sys, observer);
  Stopwatch t;
  const Eigen::VectorXd x = solve_bordered(sys);
  if (const std::string refusal = passed_.unused(); !refusal.empty()) petsc::refuse_together(refusal);
  BlockSolution out;
  long offset = 0;
  for (const Group& g : sys.groups) {
    out.u.push_back(x.segment(offset, g.C.cols()));
    offset += g.C.cols();
  }
  const long k = static_cast<long>(basis_.kept.size());
  out.lambda = basis_.every_row(x.tail(k), sys.num_multipliers());
  if (!basis_.full_rank()) check_dependent_rows(sys, basis_, out.u);
  stats_.solve_s += t.seconds();
  const int solve = ++stats_.solves;
  if (observer) observer->on_solve_end(solve, 0);
  return out;
}

}  // namespace

std::unique_ptr<SolverStrategy> make_petsc_bordered(const SolverOptions& options) {
  return std::make_unique<PetscBordered>(options);
}

}  // namespace rollsim
