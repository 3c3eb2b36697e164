#include "solve/MixedStrategy.h"

#include <algorithm>
#include <cstdio>

#include "base/Blas.h"
#include "base/Parallel.h"
#include "base/Stopwatch.h"
#include "solve/DenseInterfaceSolve.h"
#include "solve/ProjectedGMRES.h"
#include "solve/SparseCompare.h"

namespace rollsim {

MixedStrategy::MixedStrategy(SolverOptions options, bool subdomains, std::string factorization,
                             std::shared_ptr<const GroupDistribution> spread)
    : options_(std::move(options)),
      subdomains_(subdomains),
      spread_(std::move(spread)),
      preconditioner_(subdomains ? make_interface_preconditioner(options_.preconditioner, options_.threads, spread_)
                                 : nullptr),
      kind_(std::move(factorization)) {
  if (spread_ && (options_.interface_solver == InterfaceSolver::Dense ||
                  (preconditioner_ && options_.projector == ProjectorMetric::Preconditioner)))
    throw std::invalid_argument(
        "the mixed method over MPI (petsc_method: mixed) solves its interface by projected CG / GMRES with the "
        "identity projector: solver.interface_solver must be krylov and solver.projector identity (on the command "
        "line: --interface-solver krylov --projector identity)");
}

std::vector<size_t> MixedStrategy::local_groups(std::vector<size_t> groups) const {
  std::vector<size_t> mine;
  for (size_t g : groups)
    if (held(g)) mine.push_back(g);
  return mine;
}

Eigen::VectorXd MixedStrategy::sum_over_groups(const BlockSystem& sys,
                                               const std::function<Eigen::VectorXd(size_t)>& op) const {
  const size_t n = sys.groups.size();
  std::vector<Eigen::VectorXd> parts(n);
  for_each_group(n, options_.threads, [&](size_t g) {
    if (sys.groups[g].C.nonZeros() && held(g)) parts[g] = op(g);
  });
  Eigen::VectorXd y = Eigen::VectorXd::Zero(sys.num_multipliers());
  for (size_t g = 0; g < n; ++g)
    if (parts[g].size()) y += sys.groups[g].C * parts[g];
  sum(y);
  return y;
}

void MixedStrategy::factorize_changed(const BlockSystem& sys, AnalysisObserver* observer) {
  if (groups_.size() != sys.groups.size()) {
    if (spread_) refuse_idle_processes(*spread_, sys.groups.size());
    groups_.clear();
    for (size_t g = 0; g < sys.groups.size(); ++g) groups_.emplace_back(kind_);
    flexibility_.assign(sys.groups.size(), InterfaceFlexibility());
    factored_version_.assign(sys.groups.size(), -1);
  }
  std::vector<size_t> todo, changed;  // spread: every process counts every group's refactorization, does its own
  for (size_t g = 0; g < sys.groups.size(); ++g)
    if (factored_version_[g] != sys.groups[g].version) {
      changed.push_back(g);
      if (held(g)) todo.push_back(g);
    }
  // independent groups are factored concurrently (BLAS on one thread: see solve()); a failure (e.g. a subdomain
  // that is not positive definite) is rethrown here instead of terminating the process from a worker thread
  std::vector<SingularMatrix> failed(sys.groups.size(), SingularMatrix("", -1));
  for_each_group(todo.size(), options_.threads, [&](size_t i) {
    try {
      groups_[todo[i]].factorize(sys.groups[todo[i]]);
    } catch (const SingularMatrix& e) {  // the column in the groups' stacked numbering, as the global strategies
      long offset = 0;
      for (size_t g = 0; g < todo[i]; ++g) offset += sys.groups[g].C.cols();
      failed[todo[i]] = SingularMatrix(e.what(), e.column < 0 ? -1 : static_cast<int>(offset + e.column));
    }
  });
  throw_first_failure(spread_.get(), failed);
  for (size_t g : changed) {
    if (spread_) stats_.ranks[sys.groups[g].name] = spread_->holder(g);
    factored_version_[g] = sys.groups[g].version;
    ++stats_.factorizations[sys.groups[g].name];
    if (observer) observer->on_factorization(sys.groups[g].name);
  }
  stats_.analyze_s = stats_.factorize_s = stats_.factor_flops_total = 0;
  stats_.factor.flops = stats_.factor.nnz_factor = 0;  // one factorization of every group: what one global factor
  for (size_t g = 0; g < groups_.size(); ++g) {        // would report (spread: of this process's groups)
    if (!held(g)) continue;
    const GroupSolver& gs = groups_[g];
    stats_.analyze_s += gs.stats().analyze_s;
    stats_.factorize_s += gs.stats().factorize_s;
    stats_.factor_flops_total += gs.stats().flops_total();
    stats_.factor.flops += gs.stats().flops;
    stats_.factor.nnz_factor += gs.stats().nnz_factor;
  }
  if (spread_) {  // every rank's seconds, for the load balance of the selective update
    Eigen::VectorXd seconds = Eigen::VectorXd::Zero(spread_->processes());
    seconds[spread_->process()] = stats_.analyze_s + stats_.factorize_s;
    sum(seconds);
    stats_.rank_factorize_s.assign(seconds.data(), seconds.data() + seconds.size());
  }
}

InterfaceProblem MixedStrategy::interface_problem(const BlockSystem& sys, const std::vector<Eigen::VectorXd>& Kf) {
  InterfaceProblem p;
  const long m = sys.num_multipliers();
  p.b = spread_ ? Eigen::VectorXd(Eigen::VectorXd::Zero(m)) : Eigen::VectorXd(-sys.d);  // − d after the sum, spread
  long modes = 0;
  for (size_t g = 0; g < sys.groups.size(); ++g) modes += kernel(sys, g).cols();
  p.e = Eigen::VectorXd::Zero(modes);
  // G = [C_g R_g], sparse: group g's modes touch only its own constraint rows; G̃ = [C_eq,g R_g] when a group's
  // equations take C_eq (slipping Coulomb friction: an unsymmetric problem)
  std::vector<Eigen::Triplet<double, int>> t, tt;
  bool unsymmetric = false;
  int col = 0;
  for (size_t g = 0; g < sys.groups.size(); ++g) {
    const Group& grp = sys.groups[g];
    const Eigen::MatrixXd& R_g = kernel(sys, g);
    if (held(g)) p.b += grp.C * Kf[g];  // paper eq. (2)/(8): b = Σ C_g K_g⁺ f_g − d
    unsymmetric = unsymmetric || grp.C_eq.rows() > 0;
    if (R_g.cols() == 0) continue;
    const SparseMatrix R = R_g.sparseView();
    const SparseMatrix CR = grp.C * R, CeqR = grp.equation_C() * R;
    for (int j = 0; j < CR.outerSize(); ++j) {
      for (SparseMatrix::InnerIterator it(CR, j); it; ++it) t.emplace_back(it.row(), col + j, it.value());
      for (SparseMatrix::InnerIterator it(CeqR, j); it; ++it) tt.emplace_back(it.row(), col + j, it.value());
    }
    if (held(g)) p.e.segment(col, R_g.cols()) = R_g.transpose() * grp.f;  // e = [R_gᵀ f_g]
    col += static_cast<int>(R_g.cols());
  }
  if (spread_) {
    sum(p.b);
    sum(p.e);
    p.b -= sys.d;
  }
  p.Gs.resize(static_cast<int>(m), col);
  p.Gs.setFromTriplets(t.begin(), t.end());
  if (unsymmetric) {
    p.Gt.resize(static_cast<int>(m), col);
    p.Gt.setFromTriplets(tt.begin(), tt.end());
  }
  p.F = [this, &sys](const Eigen::VectorXd& lambda) {  // F λ = Σ C_g K_g⁺ C_eq,gᵀ λ (+ compliance λ)
    Eigen::VectorXd y = sum_over_groups(sys, [&](size_t g) -> Eigen::VectorXd {
      const Group& grp = sys.groups[g];
      return groups_[g].apply(grp.equation_C().transpose() * lambda);
    });
    if (sys.compliance.size() == y.size()) y += sys.compliance.cwiseProduct(lambda);
    return y;
  };
  p.unsymmetric = unsymmetric;
  return p;
}

const SparseMatrix& MixedStrategy::weighted_modes(const BlockSystem& sys, const SparseMatrix& G,
                                                  bool preconditioner_changed) {
  if (preconditioner_changed || !same_matrix(G, QG_of_)) {
    QG_ = preconditioner_->apply_columns(sys, G);
    QG_of_ = G;
  }
  return QG_;
}

bool MixedStrategy::any_indefinite() const {
  Eigen::VectorXd count = Eigen::VectorXd::Zero(1);
  for (size_t g = 0; g < groups_.size(); ++g)
    if (held(g) && groups_[g].indefinite()) count[0] += 1;
  sum(count);
  return count[0] > 0;
}

bool MixedStrategy::same_constraints(const BlockSystem& sys, const std::vector<SparseMatrix>& C) {
  if (C.size() != sys.groups.size()) return false;
  for (size_t g = 0; g < sys.groups.size(); ++g)
    if (!same_matrix(C[g], sys.groups[g].C)) return false;
  return true;
}

Eigen::MatrixXd MixedStrategy::formed_interface(const BlockSystem& sys) {
  const size_t n = sys.groups.size();
  std::vector<Eigen::MatrixXd> parts(n);
  for_each_group(n, options_.threads, [&](size_t g) {
    if (sys.groups[g].C.nonZeros()) parts[g] = flexibility_[g].interface_block(sys.groups[g], groups_[g]);
  });
  stats_.interface_columns = 0;
  for (const InterfaceFlexibility& f : flexibility_) stats_.interface_columns += f.columns_solved();
  const auto m = static_cast<Eigen::Index>(sys.num_multipliers());
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(m, m);
  for (const Eigen::MatrixXd& p : parts)  // in group order: the same sum for any thread count
    if (p.size()) F += p;
  if (sys.compliance.size() == m) F.diagonal() += sys.compliance;
  return F;
}

ProjectedCGOptions MixedStrategy::krylov_options(const BlockSystem& sys, int solve) {
  const InterfaceTolerance& t = sys.interface_tolerance;
  last_tolerance_ = t.relative > 0 ? t.relative : options_.cg_tolerance;
  return {last_tolerance_, options_.max_interface_iterations, {}, solve, t.absolute, t.from_last, t.at_most};
}

ProjectedCGResult MixedStrategy::solve_interface(const BlockSystem& sys, InterfaceProblem& problem,
                                                 bool new_preconditioner, int solve, AnalysisObserver* observer) {
  if (options_.interface_solver == InterfaceSolver::Dense) {
    if (!same_constraints(sys, basis_C_)) {  // the independent rows, found again when a constraint block changed
      basis_ = independent_rows(stacked_constraints(sys));
      basis_C_.clear();
      for (const Group& g : sys.groups) basis_C_.push_back(g.C);
    }
    ProjectedCGResult r = dense_interface_solve(formed_interface(sys), problem, basis_.kept);
    r.lambda = basis_.minimum_norm(r.lambda);  // a dependent row's share spread as the Krylov solvers spread it
    return r;
  }
  if (options_.interface_start == InterfaceStart::Previous || sys.interface_tolerance.from_last)
    problem.start = sys.lambda_start;
  // an indefinite group factor (CholeskyOrLU) makes F symmetric but possibly indefinite on ker Gᵀ, where CG may
  // break down: GMRES then, as for an unsymmetric F; positive definite groups keep CG
  const bool krylov_gmres = problem.unsymmetric || any_indefinite();
  if (preconditioner_ && options_.projector == ProjectorMetric::Preconditioner && problem.Gs.cols() && !krylov_gmres)
    problem.QG = &weighted_modes(sys, problem.Gs, new_preconditioner);
  ProjectedCGOptions cg = krylov_options(sys, solve);
  if (preconditioner_) cg.preconditioner = [&](const Eigen::VectorXd& w) { return preconditioner_->apply(sys, w); };
  gmres_solves_ += krylov_gmres;
  return krylov_gmres ? projected_gmres(problem, cg, observer) : projected_cg(problem, cg, observer);
}

namespace {
/// [top; bottom] for two blocks with the same columns.
SparseMatrix stack(const SparseMatrix& top, const SparseMatrix& bottom) {
  std::vector<Eigen::Triplet<double, int>> t;
  for (int j = 0; j < top.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(top, j); it; ++it) t.emplace_back(it.row(), j, it.value());
  for (int j = 0; j < bottom.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(bottom, j); it; ++it)
      t.emplace_back(static_cast<int>(top.rows() + it.row()), j, it.value());
  SparseMatrix S(static_cast<int>(top.rows() + bottom.rows()), top.cols());
  S.setFromTriplets(t.begin(), t.end());
  return S;
}
}  // namespace

BlockSolution MixedStrategy::solve(const BlockSystem& sys, AnalysisObserver* observer) {
  if (sys.compliance.size() == 0) return solve_plain(sys, observer);
  // compliant rows: rows of the interface after every other, their multipliers μ with F's diagonal + 1/k — then
  // dropped from the answer, since no caller knows them
  BlockSystem aug = sys;
  const long m = sys.num_multipliers(), mc = sys.compliance.size();
  for (Group& g : aug.groups) {
    g.C = stack(SparseMatrix(g.C), g.C_compliant);
    if (g.C_eq.rows() > 0) g.C_eq = stack(SparseMatrix(g.C_eq), g.C_compliant);
    g.C_compliant = SparseMatrix(0, g.C.cols());
  }
  aug.d = Eigen::VectorXd::Zero(m + mc);
  aug.d.head(m) = sys.d;
  aug.compliance = Eigen::VectorXd::Zero(m + mc);
  aug.compliance.tail(mc) = sys.compliance;
  if (sys.lambda_start.size() == m) {
    aug.lambda_start = Eigen::VectorXd::Zero(m + mc);
    aug.lambda_start.head(m) = sys.lambda_start;
  }
  BlockSolution out = solve_plain(aug, observer);
  out.lambda = Eigen::VectorXd(out.lambda.head(m));
  return out;
}

BlockSolution MixedStrategy::solve_plain(const BlockSystem& sys, AnalysisObserver* observer) {
  // Several groups: the threads go to the groups and BLAS / CHOLMOD's OpenMP stay on one, whatever --threads is,
  // so that results are bit-identical for any thread count and `--threads 1` uses one core. One group: the
  // libraries keep the threads.
  if (sys.groups.size() > 1) set_library_threads(1);
  const int solve = ++stats_.solves;
  const bool refactor = groups_.size() != sys.groups.size() || [&] {
    for (size_t g = 0; g < sys.groups.size(); ++g)
      if (factored_version_[g] != sys.groups[g].version) return true;
    return false;
  }();
  factorize_changed(sys, observer);
  Stopwatch t;
  const bool new_preconditioner = preconditioner_ && (refactor || !same_constraints(sys, preconditioned_C_));
  if (new_preconditioner) {
    preconditioner_->setup(sys);
    preconditioned_C_.clear();
    for (const Group& g : sys.groups) preconditioned_C_.push_back(g.C);
  }
  if (spread_) kernels_ = shared_kernels(*spread_, sys);
  std::vector<Eigen::VectorXd> Kf(sys.groups.size());
  for_each_group(sys.groups.size(), options_.threads, [&](size_t g) {
    if (held(g)) Kf[g] = groups_[g].apply(sys.groups[g].f);
  });
  InterfaceProblem problem = interface_problem(sys, Kf);
  last_ = solve_interface(sys, problem, new_preconditioner, solve, observer);
  stats_.cg_iterations += last_.iterations;
  stats_.extra_interface_iterations += last_.extra_iterations;
  stats_.cg_lambda_min = last_.lambda_min;
  stats_.cg_lambda_max = last_.lambda_max;
  BlockSolution out;
  out.lambda = last_.lambda;
  out.status = cg_status(last_, krylov_options(sys, solve));
  if (options_.interface_solver == InterfaceSolver::Dense && !last_.converged) {
    char what[300];
    std::snprintf(what, sizeof what,
                  "the dense interface solve left a relative residual of %.3g and a constraint error of %.3g (above "
                  "%.0e): constraints that contradict each other, or an interface singular on its free directions",
                  last_.residuals.back(), last_.max_constraint_error, kDenseInterfaceResidual);
    out.status = {Status::not_converged, Reason::breakdown, what};
  }
  std::vector<long> first_mode(sys.groups.size(), 0);  // column of group g's modes in α
  for (size_t g = 1; g < sys.groups.size(); ++g) first_mode[g] = first_mode[g - 1] + kernel(sys, g - 1).cols();
  out.u.resize(sys.groups.size());
  for_each_group(sys.groups.size(), options_.threads, [&](size_t g) {
    const Group& grp = sys.groups[g];
    if (!held(g)) {
      out.u[g] = Eigen::VectorXd::Zero(grp.C.cols());  // its holder's, from share_displacements
      return;
    }
    Eigen::VectorXd u = grp.C.nonZeros() ? groups_[g].apply(grp.f - grp.equation_C().transpose() * out.lambda) : Kf[g];
    const Eigen::MatrixXd& R = kernel(sys, g);
    if (R.cols()) u += R * last_.alpha.segment(first_mode[g], R.cols());  // paper eq. (5)
    out.u[g] = std::move(u);
  });
  if (spread_) share_vectors(*spread_, out.u);
  stats_.solve_s += t.seconds();
  if (observer) observer->on_solve_end(solve, last_.iterations);
  return out;
}

}  // namespace rollsim
