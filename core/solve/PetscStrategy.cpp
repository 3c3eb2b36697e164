// Strategy "petsc" with PETSc (built with ROLLSIM_WITH_PETSC): one subdomain group per MPI rank, handed over as an
// unassembled MATIS matrix and solved by PCBDDC in CG or by KSPFETIDP (Dohrmann's BDDC; FETI-DP, Farhat et al.).
//
// The hand-over keeps our eliminated numbering: the groups' free dofs (prescribed dofs are not unknowns), so there
// are no Dirichlet rows to zero and PCBDDCSetDirichletBoundaries has nothing to mark. The global numbering comes
// from the glue rows B_i themselves: the copies of a dof that the rows join are one global dof, numbered in the
// lowest group that has it — which is the rank that owns it, so each rank's owned dofs are one contiguous range.
//
// This file is the module rollsim_petsc.so, not part of rollsim_core: the only code that links PETSc and MPI. Its one
// exported symbol, rollsim_petsc_module(), hands PetscLoader.cpp the table of PetscModule.h.
#include <petscksp.h>

#include <Eigen/IterativeLinearSolvers>
#include <numeric>
#include <stdexcept>

#include "base/Stopwatch.h"
#include "solve/PetscBordered.h"
#include "solve/PetscDistribution.h"
#include "solve/PetscModule.h"
#include "solve/PetscSupport.h"

namespace rollsim {

namespace {

using petsc::on_all_ranks;
using petsc::refuse_together;

/// The global dof numbers of every group's free dofs (see the file comment) and this rank's owned range.
struct Numbering {
  std::vector<std::vector<PetscInt>> global;  // per group, per free dof
  std::vector<PetscInt> begin;                // group g owns [begin[g], begin[g + 1])
  int block = 1;                              // dim when every node has all or none of its components free
};

long find_root(std::vector<long>& parent, long i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

Numbering number_dofs(const BlockSystem& sys, int dim) {
  const size_t G = sys.groups.size();
  std::vector<long> offset(G + 1, 0);
  for (size_t g = 0; g < G; ++g) offset[g + 1] = offset[g] + sys.groups[g].C.cols();
  std::vector<long> parent(static_cast<size_t>(offset[G]));
  std::iota(parent.begin(), parent.end(), 0L);
  std::vector<long> first(static_cast<size_t>(sys.num_multipliers()), -1);  // per glue row: one copy it joins
  for (size_t g = 0; g < G; ++g) {
    const SparseMatrix& C = sys.groups[g].C;
    for (int j = 0; j < C.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(C, j); it; ++it) {
        const long id = offset[g] + j;
        long& f = first[static_cast<size_t>(it.row())];
        if (f < 0)
          f = id;
        else
          parent[static_cast<size_t>(find_root(parent, id))] = find_root(parent, f);
      }
  }
  Numbering num;
  std::vector<PetscInt> number(parent.size(), -1);
  PetscInt next = 0;
  for (size_t g = 0; g < G; ++g) {
    num.begin.push_back(next);
    std::vector<PetscInt>& global = num.global.emplace_back(static_cast<size_t>(offset[g + 1] - offset[g]));
    for (size_t l = 0; l < global.size(); ++l) {
      PetscInt& n = number[static_cast<size_t>(find_root(parent, offset[g] + static_cast<long>(l)))];
      if (n < 0) n = next++;
      global[l] = n;
    }
  }
  num.begin.push_back(next);
  bool blocked = true;  // node blocks (x, y[, z]) numbered consecutively and aligned
  for (size_t g = 0; g < G && blocked; ++g) {
    const DofGeometry& geo = sys.groups[g].geometry;
    const std::vector<PetscInt>& global = num.global[g];
    blocked = global.size() % static_cast<size_t>(dim) == 0 && geo.component.size() == static_cast<long>(global.size());
    for (size_t b = 0; blocked && b < global.size(); b += static_cast<size_t>(dim))
      for (int c = 0; c < dim && blocked; ++c)
        blocked = global[b] % dim == 0 && global[b + static_cast<size_t>(c)] == global[b] + c &&
                  geo.component[static_cast<long>(b) + c] == c;
  }
  num.block = blocked ? dim : 1;
  return num;
}

/// An orthonormal near-null space from the columns of `modes` (rows: the Vec's local entries).
MatNullSpace null_space(MPI_Comm comm, const Eigen::MatrixXd& modes, PetscInt global_size) {
  std::vector<Vec> v(static_cast<size_t>(modes.cols()));
  for (size_t k = 0; k < v.size(); ++k) {
    if (comm == PETSC_COMM_SELF)
      ROLLSIM_PETSC(VecCreateSeq(comm, static_cast<PetscInt>(modes.rows()), &v[k]));
    else
      ROLLSIM_PETSC(VecCreateMPI(comm, static_cast<PetscInt>(modes.rows()), global_size, &v[k]));
    PetscScalar* a = nullptr;
    ROLLSIM_PETSC(VecGetArray(v[k], &a));
    for (long i = 0; i < modes.rows(); ++i) a[i] = modes(i, static_cast<long>(k));
    ROLLSIM_PETSC(VecRestoreArray(v[k], &a));
    for (size_t j = 0; j < k; ++j) {  // modified Gram-Schmidt
      PetscScalar dot = 0;
      ROLLSIM_PETSC(VecDot(v[k], v[j], &dot));
      ROLLSIM_PETSC(VecAXPY(v[k], -dot, v[j]));
    }
    ROLLSIM_PETSC(VecNormalize(v[k], nullptr));
  }
  MatNullSpace nsp = nullptr;
  ROLLSIM_PETSC(MatNullSpaceCreate(comm, PETSC_FALSE, static_cast<PetscInt>(v.size()), v.data(), &nsp));
  for (Vec& x : v) ROLLSIM_PETSC(VecDestroy(&x));
  return nsp;
}

/// K_g as a sequential AIJ matrix (both triangles, as stored).
Mat local_matrix(const SparseMatrix& K, int block) {
  Mat A = nullptr;
  const PetscInt n = static_cast<PetscInt>(K.rows());
  ROLLSIM_PETSC(MatCreate(PETSC_COMM_SELF, &A));
  ROLLSIM_PETSC(MatSetSizes(A, n, n, n, n));
  ROLLSIM_PETSC(MatSetType(A, MATSEQAIJ));
  ROLLSIM_PETSC(MatSetBlockSize(A, block));
  std::vector<PetscInt> nnz(static_cast<size_t>(n));
  for (PetscInt j = 0; j < n; ++j) nnz[j] = K.outerIndexPtr()[j + 1] - K.outerIndexPtr()[j];
  ROLLSIM_PETSC(MatSeqAIJSetPreallocation(A, 0, nnz.data()));
  std::vector<PetscInt> rows;
  for (PetscInt j = 0; j < n; ++j) {  // column j of the symmetric K is row j
    const int start = K.outerIndexPtr()[j];
    rows.assign(K.innerIndexPtr() + start, K.innerIndexPtr() + start + nnz[j]);
    ROLLSIM_PETSC(MatSetValues(A, 1, &j, nnz[j], rows.data(), K.valuePtr() + start, INSERT_VALUES));
  }
  ROLLSIM_PETSC(MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY));
  ROLLSIM_PETSC(MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY));
  ROLLSIM_PETSC(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
  return A;
}

/// Every group's vector on every rank, from each rank's own group's `mine` (an MPI_Allgatherv; group g on rank g).
std::vector<Eigen::VectorXd> gather_groups(const BlockSystem& sys, const Eigen::VectorXd& mine) {
  std::vector<int> counts, displs;
  int total = 0;
  for (const Group& g : sys.groups) {
    displs.push_back(total);
    counts.push_back(static_cast<int>(g.C.cols()));
    total += counts.back();
  }
  std::vector<double> all(static_cast<size_t>(total));
  MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, PETSC_COMM_WORLD);
  std::vector<Eigen::VectorXd> out;
  for (size_t g = 0; g < counts.size(); ++g)
    out.push_back(Eigen::Map<const Eigen::VectorXd>(all.data() + displs[g], counts[g]));
  return out;
}

/// The glue forces λ that balance the subdomains' interface forces, C_gᵀλ = s_g = f_g − K_g u_g for every g (paper
/// eq. (1)'s first row), in the least-squares sense: C Cᵀ λ = Σ_g C_g s_g by CG — C Cᵀ is well conditioned for the
/// Boolean glue, and for redundant glue (singular) CG from zero gives the minimum-norm λ. The Newton driver needs
/// them: its residual of a group is f_g − C_gᵀλ, whose interface part only λ cancels.
Eigen::VectorXd glue_forces(const BlockSystem& sys, const std::vector<Eigen::VectorXd>& s) {
  const long m = sys.num_multipliers();
  if (m == 0) return Eigen::VectorXd(0);
  SparseMatrix CCt(static_cast<int>(m), static_cast<int>(m));
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
  for (size_t g = 0; g < sys.groups.size(); ++g) {
    const SparseMatrix& C = sys.groups[g].C;
    CCt += SparseMatrix(C * SparseMatrix(C.transpose()));
    rhs += C * s[g];
  }
  Eigen::ConjugateGradient<SparseMatrix, Eigen::Lower | Eigen::Upper> cg;
  cg.setTolerance(1e-14);
  cg.compute(CCt);
  return cg.solve(rhs);
}

class PetscStrategy final : public SolverStrategy {
 public:
  explicit PetscStrategy(SolverOptions options) : options_(std::move(options)) {}  // the loader checked the method
  ~PetscStrategy() override { release(); }
  PetscStrategy(const PetscStrategy&) = delete;
  PetscStrategy& operator=(const PetscStrategy&) = delete;

  BlockSolution solve(const BlockSystem& sys, AnalysisObserver* observer) override;
  const SolveStats& stats() const override { return stats_; }
  bool uses_subdomains() const override { return true; }
  double multiplier_tolerance() const override { return rtol_; }
  const SolverOptions& options() const override { return options_; }
  std::vector<size_t> local_groups(std::vector<size_t> groups) const override {
    petsc::start();
    std::vector<size_t> mine;
    for (size_t g : groups)
      if (g == static_cast<size_t>(petsc::rank())) mine.push_back(g);
    return mine;
  }
  std::string contact_refusal() const override {
    return "solver 'petsc' with --petsc-method " + word(options_.petsc_method) +
           " solves contact-free projects only: --petsc-method mumps solves contact pairs (tied, frictionless or "
           "frictional) — or use feti, mixed or direct";
  }

 private:
  std::string check_system(const BlockSystem& sys) const;
  void set_up(const BlockSystem& sys);
  void release();

  SolverOptions options_;
  /// The Krylov solves' relative tolerance: the system's interface tolerance where it sets one (an inexact Newton
  /// iteration's forcing term), else solver.cg_tolerance; both KSPs get it (KSPFETIDP's inner CG on the multipliers).
  void set_tolerance(const BlockSystem& sys);
  SolveStats stats_;
  double rtol_ = options_.cg_tolerance;
  Numbering num_;
  Mat A_ = nullptr;
  KSP ksp_ = nullptr, inner_ = nullptr;  // inner_: FETI-DP's CG on the multipliers (bddc: ksp_ itself)
  std::vector<long> versions_;           // every group's K version at the last set-up: the same on every rank
  petsc::PassedOptions passed_{options_.petsc_options, word(options_.petsc_method)};
};

void PetscStrategy::release() {
  if (ksp_) KSPDestroy(&ksp_);
  if (A_) MatDestroy(&A_);
  inner_ = nullptr;
  versions_.clear();
}

std::vector<long> versions(const BlockSystem& sys) {
  std::vector<long> v;
  for (const Group& g : sys.groups) v.push_back(g.version);
  return v;
}

std::string PetscStrategy::check_system(const BlockSystem& sys) const {
  const ConstraintBlock* glue = sys.glue();
  const long glue_rows = glue ? glue->size() : 0;
  if (sys.num_multipliers() != glue_rows)
    return "petsc: contact constraints are not yet supported by --solver petsc (" +
           std::to_string(sys.num_multipliers() - glue_rows) +
           " contact rows): --petsc-method mumps solves them (or use feti, mixed or direct)";
  const int ranks = petsc::ranks();
  const size_t G = sys.groups.size();
  if (G != static_cast<size_t>(ranks))
    return "petsc: one MPI rank per subdomain: the problem has " + std::to_string(G) + " subdomain" +
           (G == 1 ? "" : "s") + " (bodies' partitions), but " + std::to_string(ranks) + " rank" +
           (ranks == 1 ? " runs" : "s run") + " — start it as `mpirun -n " + std::to_string(G) +
           " rollsim run … --solver petsc` or give a --partition of " + std::to_string(ranks) + " subdomain" +
           (ranks == 1 ? "" : "s");
  for (const Group& g : sys.groups)
    if (g.geometry.x.rows() != g.C.cols() || g.geometry.modes.rows() != g.C.cols())
      return "petsc: group '" + g.name + "' has no dof geometry (coordinates, rigid modes) to hand to PETSc";
  const Group& own = sys.groups[static_cast<size_t>(petsc::rank())];
  if (own.K.rows() != own.C.cols()) return "petsc: the stiffness of group '" + own.name + "' was not assembled";
  return "";
}

void PetscStrategy::set_up(const BlockSystem& sys) {
  release();
  const MPI_Comm comm = PETSC_COMM_WORLD;
  const size_t rank = static_cast<size_t>(petsc::rank());
  const Group& own = sys.groups[rank];
  const int dim = static_cast<int>(own.geometry.x.cols());
  num_ = number_dofs(sys, dim);
  const int bs = num_.block;
  const std::vector<PetscInt>& global = num_.global[rank];
  const PetscInt n = static_cast<PetscInt>(global.size()), M = num_.begin.back();
  const PetscInt m = num_.begin[rank + 1] - num_.begin[rank];

  // MATIS: the local-to-global map (block size dim when the nodes are whole) and K_g as the local matrix
  std::vector<PetscInt> blocks(static_cast<size_t>(n / bs));
  for (size_t b = 0; b < blocks.size(); ++b) blocks[b] = global[b * static_cast<size_t>(bs)] / bs;
  ISLocalToGlobalMapping l2g = nullptr;
  ROLLSIM_PETSC(ISLocalToGlobalMappingCreate(comm, bs, static_cast<PetscInt>(blocks.size()), blocks.data(),
                                             PETSC_COPY_VALUES, &l2g));
  ROLLSIM_PETSC(MatCreateIS(comm, bs, m, m, M, M, l2g, l2g, &A_));
  ROLLSIM_PETSC(ISLocalToGlobalMappingDestroy(&l2g));
  Mat local = local_matrix(own.K, bs);
  MatNullSpace local_nsp = null_space(PETSC_COMM_SELF, own.geometry.modes, n);
  ROLLSIM_PETSC(MatSetNearNullSpace(local, local_nsp));
  ROLLSIM_PETSC(MatNullSpaceDestroy(&local_nsp));
  ROLLSIM_PETSC(MatISSetLocalMat(A_, local));
  ROLLSIM_PETSC(MatDestroy(&local));
  ROLLSIM_PETSC(MatAssemblyBegin(A_, MAT_FINAL_ASSEMBLY));
  ROLLSIM_PETSC(MatAssemblyEnd(A_, MAT_FINAL_ASSEMBLY));
  ROLLSIM_PETSC(MatSetOption(A_, MAT_SPD, PETSC_TRUE));

  // the owned dofs' geometry: near-null space of the global matrix (the rows of the body's rigid modes, the same in
  // every subdomain holding the dof), coordinates for BDDC's corner selection
  Eigen::MatrixXd owned_x(m, dim), owned_modes(m, own.geometry.modes.cols());
  for (size_t l = 0; l < global.size(); ++l)
    if (const PetscInt i = global[l] - num_.begin[rank]; i >= 0 && i < m) {
      owned_x.row(i) = own.geometry.x.row(static_cast<long>(l));
      owned_modes.row(i) = own.geometry.modes.row(static_cast<long>(l));
    }
  MatNullSpace nsp = null_space(comm, owned_modes, M);
  ROLLSIM_PETSC(MatSetNearNullSpace(A_, nsp));
  ROLLSIM_PETSC(MatNullSpaceDestroy(&nsp));
  std::vector<PetscReal> coords(static_cast<size_t>(m) * static_cast<size_t>(dim));
  for (PetscInt i = 0; i < m; ++i)
    for (int c = 0; c < dim; ++c) coords[static_cast<size_t>(i * dim + c)] = owned_x(i, c);

  ROLLSIM_PETSC(KSPCreate(comm, &ksp_));
  PC bddc = nullptr;
  if (options_.petsc_method == PetscMethod::Bddc) {
    ROLLSIM_PETSC(KSPSetType(ksp_, KSPCG));
    ROLLSIM_PETSC(KSPGetPC(ksp_, &bddc));
    ROLLSIM_PETSC(PCSetType(bddc, PCBDDC));
    // BDDC's pre-solve starts CG from a nonzero guess (its interior solution); measured against ‖B b‖ the tolerance
    // then went wrong inside Newton — a second set-up stopped at iteration 0 with DIVERGED_DTOL, or with a tolerance
    // too small to reach. Relative to the initial residual (of that guess) every solve converges as in the first.
    ROLLSIM_PETSC(KSPConvergedDefaultSetUIRNorm(ksp_));
    inner_ = ksp_;
  } else {
    ROLLSIM_PETSC(KSPSetType(ksp_, KSPFETIDP));
    ROLLSIM_PETSC(KSPFETIDPGetInnerBDDC(ksp_, &bddc));
    ROLLSIM_PETSC(KSPFETIDPGetInnerKSP(ksp_, &inner_));
    ROLLSIM_PETSC(KSPSetType(inner_, KSPCG));  // the FETI-DP operator is symmetric positive definite (GMRES by default)
  }
  ROLLSIM_PETSC(KSPSetOperators(ksp_, A_, A_));
  ROLLSIM_PETSC(PCSetCoordinates(bddc, dim, m, coords.data()));
  // Two defaults of ours, as options (no API call in PETSc 3.18) unless --petsc-options sets them: corners from the
  // coordinates — a floating subdomain touching one cross point only (2D 2×2) needs more primal vertices than the
  // cross points, or its K_RR keeps the rotation about that point —, and face constraints in 3D (averages and the
  // near-null space's rotations on every face: 13 → 6 CG iterations on a 12³ cube in 2×2×2)
  const std::string prefix = inner_ == ksp_ ? "" : "fetidp_bddc_";  // KSPFETIDP names its BDDC's options so at set-up
  for (const char* option : {"pc_bddc_corner_selection", "pc_bddc_use_faces"}) {
    const std::string name = "-" + prefix + option;
    PetscBool given = PETSC_FALSE;
    ROLLSIM_PETSC(PetscOptionsHasName(nullptr, nullptr, name.c_str(), &given));
    if (!given) ROLLSIM_PETSC(PetscOptionsSetValue(nullptr, name.c_str(), "true"));
  }
  // the components as fields: primal vertices and edge / face averages per component, not of x and y mixed (what
  // a block size of dim would say, were every node whole)
  std::vector<IS> fields(static_cast<size_t>(dim));
  for (int c = 0; c < dim; ++c) {
    std::vector<PetscInt> dofs;
    for (long l = 0; l < own.geometry.component.size(); ++l)
      if (own.geometry.component[l] == c) dofs.push_back(static_cast<PetscInt>(l));
    ROLLSIM_PETSC(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(dofs.size()), dofs.data(), PETSC_COPY_VALUES,
                                  &fields[static_cast<size_t>(c)]));
  }
  ROLLSIM_PETSC(PCBDDCSetDofsSplittingLocal(bddc, dim, fields.data()));
  for (IS& f : fields) ROLLSIM_PETSC(ISDestroy(&f));
  // KSPFETIDP hands its own tolerances to the CG on the multipliers at set-up: both get them
  ROLLSIM_PETSC(KSPSetTolerances(ksp_, rtol_, 1e-300, PETSC_DEFAULT, 10000));
  ROLLSIM_PETSC(KSPSetTolerances(inner_, rtol_, 1e-300, PETSC_DEFAULT, 10000));
  ROLLSIM_PETSC(KSPSetFromOptions(ksp_));
  ROLLSIM_PETSC(KSPSetUp(ksp_));
  versions_ = versions(sys);
}

void PetscStrategy::set_tolerance(const BlockSystem& sys) {
  const double rtol = sys.interface_tolerance.relative > 0 ? sys.interface_tolerance.relative : options_.cg_tolerance;
  if (rtol == rtol_) return;
  rtol_ = rtol;
  if (!ksp_) return;  // set_up gives it
  ROLLSIM_PETSC(KSPSetTolerances(ksp_, rtol_, 1e-300, PETSC_DEFAULT, 10000));
  ROLLSIM_PETSC(KSPSetTolerances(inner_, rtol_, 1e-300, PETSC_DEFAULT, 10000));
}

BlockSolution PetscStrategy::solve(const BlockSystem& sys, AnalysisObserver* observer) {
  petsc::start();
  ++stats_.solves;
  refuse_together(check_system(sys));
  const size_t rank = static_cast<size_t>(petsc::rank());
  const Group& own = sys.groups[rank];
  passed_.insert();
  // set-up is collective: every rank sets up again when any group's K changed (a Newton iteration of the selective
  // update may re-assemble one subdomain only) — the driver runs on every rank alike, so the versions are the same
  set_tolerance(sys);
  if (versions_ != versions(sys) || !ksp_) {
    Stopwatch t;
    set_up(sys);
    stats_.factorize_s += t.seconds();
    stats_.factorizations[own.name] += 1;
    if (observer) observer->on_factorization(own.name);
  }
  Stopwatch t;
  Vec x = nullptr, b = nullptr;
  ROLLSIM_PETSC(MatCreateVecs(A_, &x, &b));
  const std::vector<PetscInt>& global = num_.global[rank];
  ROLLSIM_PETSC(VecSetValues(b, static_cast<PetscInt>(global.size()), global.data(), own.f.data(), ADD_VALUES));
  ROLLSIM_PETSC(VecAssemblyBegin(b));
  ROLLSIM_PETSC(VecAssemblyEnd(b));
  ROLLSIM_PETSC(KSPSolve(ksp_, b, x));
  KSPConvergedReason reason;
  PetscInt its = 0;
  ROLLSIM_PETSC(KSPGetConvergedReason(inner_, &reason));
  ROLLSIM_PETSC(KSPGetIterationNumber(inner_, &its));
  if (const std::string refusal = passed_.unused(); !refusal.empty()) {
    VecDestroy(&x);
    VecDestroy(&b);
    refuse_together(refusal);
  }
  // every rank gets the whole solution: the driver recovers every body from the groups' displacements
  const Eigen::VectorXd all = petsc::on_every_rank(x);
  BlockSolution sol;
  for (size_t g = 0; g < sys.groups.size(); ++g) {
    Eigen::VectorXd& u = sol.u.emplace_back(static_cast<long>(num_.global[g].size()));
    for (size_t l = 0; l < num_.global[g].size(); ++l) u[static_cast<long>(l)] = all[num_.global[g][l]];
  }
  VecDestroy(&x);
  VecDestroy(&b);
  sol.lambda = glue_forces(sys, gather_groups(sys, own.f - own.K * sol.u[rank]));
  stats_.cg_iterations += its;
  stats_.solve_s += t.seconds();
  if (observer) observer->on_solve_end(stats_.solves, static_cast<int>(its));
  if (reason < 0) {
    const bool indefinite = reason == KSP_DIVERGED_INDEFINITE_PC || reason == KSP_DIVERGED_INDEFINITE_MAT;
    sol.status = {Status::not_converged, reason == KSP_DIVERGED_ITS ? Reason::iteration_limit : Reason::breakdown,
                  "petsc (" + word(options_.petsc_method) + "): the Krylov solve stopped after " + std::to_string(its) +
                      " iterations: " + KSPConvergedReasons[reason] +
                      (indefinite ? " (CG needs a positive definite matrix: the stiffness or tangent is not — plastic "
                                    "flow without hardening, or a part that lost its stiffness)"
                                  : "")};
  }
  return sol;
}

std::unique_ptr<SolverStrategy> make(const SolverOptions& options) {
  if (options.petsc_method == PetscMethod::Mumps) return make_petsc_bordered(options);
  if (options.petsc_method == PetscMethod::Mixed)  // the core's MixedStrategy over distribution(): PetscLoader
    throw std::invalid_argument("petsc: the mixed method is made by the core, not by the module");
  return std::make_unique<PetscStrategy>(options);
}

}  // namespace

}  // namespace rollsim

extern "C" __attribute__((visibility("default"))) const rollsim::PetscModule* rollsim_petsc_module() {
  static const rollsim::PetscModule module{rollsim::kPetscModuleAbi, &rollsim::make,
                                           &rollsim::petsc::start,   &rollsim::petsc::rank,
                                           &rollsim::petsc::finish,  &rollsim::mpi_group_distribution};
  return &module;
}
