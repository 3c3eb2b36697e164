#include "solve/MixedStrategy.h"

#include <thread>

#include "solve/Blas.h"
#include "solve/Stopwatch.h"

namespace rollsim {

MixedStrategy::MixedStrategy(SolverOptions options, bool subdomains, std::string factorization)
    : options_(std::move(options)),
      subdomains_(subdomains),
      preconditioner_(subdomains ? make_interface_preconditioner(options_.preconditioner) : nullptr),
      kind_(std::move(factorization)) {}

Eigen::VectorXd MixedStrategy::sum_over_groups(const BlockSystem& sys,
                                               const std::function<Eigen::VectorXd(size_t)>& op) const {
  const size_t n = sys.groups.size();
  std::vector<Eigen::VectorXd> parts(n);
  const size_t threads = std::min<size_t>(static_cast<size_t>(std::max(1, options_.threads)), n);
  if (threads <= 1) {
    for (size_t g = 0; g < n; ++g) parts[g] = op(g);
  } else {
    std::vector<std::thread> pool;
    for (size_t t = 0; t < threads; ++t)
      pool.emplace_back([&, t] {
        for (size_t g = t; g < n; g += threads) parts[g] = op(g);
      });
    for (auto& th : pool) th.join();
  }
  Eigen::VectorXd y = Eigen::VectorXd::Zero(sys.num_multipliers());
  for (const auto& p : parts)
    if (p.size()) y += p;
  return y;
}

void MixedStrategy::factorize_changed(const BlockSystem& sys) {
  if (groups_.size() != sys.groups.size()) {
    groups_.clear();
    for (size_t g = 0; g < sys.groups.size(); ++g) groups_.emplace_back(kind_);
    factored_version_.assign(sys.groups.size(), -1);
  }
  std::vector<size_t> todo;
  for (size_t g = 0; g < sys.groups.size(); ++g)
    if (factored_version_[g] != sys.groups[g].version) todo.push_back(g);
  // independent groups are factored concurrently (BLAS on one thread: see solve())
  const int threads = std::min<int>(std::max(1, options_.threads), static_cast<int>(todo.size()));
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(1, threads); ++t) {
    auto work = [&, t] {
      for (size_t i = static_cast<size_t>(t); i < todo.size(); i += static_cast<size_t>(std::max(1, threads)))
        groups_[todo[i]].factorize(sys.groups[todo[i]]);
    };
    if (threads > 1)
      pool.emplace_back(work);
    else
      work();
  }
  for (auto& th : pool) th.join();
  for (size_t g : todo) {
    factored_version_[g] = sys.groups[g].version;
    ++stats_.factorizations[sys.groups[g].name];
  }
  stats_.analyze_s = stats_.factorize_s = 0;
  for (const GroupSolver& gs : groups_) {
    stats_.analyze_s += gs.stats().analyze_s;
    stats_.factorize_s += gs.stats().factorize_s;
  }
}

InterfaceProblem MixedStrategy::interface_problem(const BlockSystem& sys, const std::vector<Eigen::VectorXd>& Kf) {
  InterfaceProblem p;
  const long m = sys.num_multipliers();
  p.b = -sys.d;
  p.G.resize(m, sys.num_rigid_modes());
  p.e.resize(sys.num_rigid_modes());
  long col = 0;
  for (size_t g = 0; g < sys.groups.size(); ++g) {
    const Group& grp = sys.groups[g];
    p.b += grp.C * Kf[g];  // paper eq. (2)/(8): b = Σ C_g K_g⁺ f_g − d
    if (grp.R.cols() == 0) continue;
    p.G.middleCols(col, grp.R.cols()) = grp.C * grp.R;           // G = [C_g R_g]
    p.e.segment(col, grp.R.cols()) = grp.R.transpose() * grp.f;  // e = [R_gᵀ f_g]
    col += grp.R.cols();
  }
  p.F = [this, &sys](const Eigen::VectorXd& lambda) {
    return sum_over_groups(sys, [&](size_t g) -> Eigen::VectorXd {
      const Group& grp = sys.groups[g];
      if (grp.C.nonZeros() == 0) return {};
      return grp.C * groups_[g].apply(grp.C.transpose() * lambda);
    });
  };
  return p;
}

BlockSolution MixedStrategy::solve(const BlockSystem& sys, AnalysisObserver* observer) {
  // Several groups: the threads go to the groups and BLAS stays on one, whatever --threads is, so that results
  // are bit-identical for any thread count. One group: BLAS keeps the threads.
  if (sys.groups.size() > 1) set_blas_threads(1);
  const bool refactor = groups_.size() != sys.groups.size() || [&] {
    for (size_t g = 0; g < sys.groups.size(); ++g)
      if (factored_version_[g] != sys.groups[g].version) return true;
    return false;
  }();
  factorize_changed(sys);
  Stopwatch t;
  if (preconditioner_ && (refactor || sys.num_multipliers() != preconditioned_rows_)) {
    preconditioner_->setup(sys);
    preconditioned_rows_ = sys.num_multipliers();
  }
  std::vector<Eigen::VectorXd> Kf(sys.groups.size());
  for (size_t g = 0; g < sys.groups.size(); ++g) Kf[g] = groups_[g].apply(sys.groups[g].f);
  const InterfaceProblem problem = interface_problem(sys, Kf);
  ProjectedCGOptions cg{options_.cg_tolerance, 10000, {}};
  if (preconditioner_) cg.preconditioner = [&](const Eigen::VectorXd& w) { return preconditioner_->apply(sys, w); };
  last_ = projected_cg(problem, cg, observer);
  stats_.cg_iterations += last_.iterations;
  BlockSolution out;
  out.lambda = last_.lambda;
  long col = 0;
  for (size_t g = 0; g < sys.groups.size(); ++g) {
    const Group& grp = sys.groups[g];
    Eigen::VectorXd u = grp.C.nonZeros() ? groups_[g].apply(grp.f - grp.C.transpose() * out.lambda) : Kf[g];
    if (grp.R.cols()) u += grp.R * last_.alpha.segment(col, grp.R.cols());  // paper eq. (5)
    col += grp.R.cols();
    out.u.push_back(std::move(u));
  }
  stats_.solve_s += t.seconds();
  return out;
}

}  // namespace rollsim
