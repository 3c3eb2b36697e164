#include "solve/MixedStrategy.h"

#include "solve/Stopwatch.h"

namespace rollsim {

MixedStrategy::MixedStrategy(SolverOptions options, std::string factorization)
    : options_(options), kind_(std::move(factorization)) {}

void MixedStrategy::factorize_changed(const BlockSystem& sys) {
  if (groups_.size() != sys.groups.size()) {
    groups_.clear();
    for (size_t g = 0; g < sys.groups.size(); ++g) groups_.emplace_back(kind_);
    factored_version_.assign(sys.groups.size(), -1);
  }
  stats_.analyze_s = stats_.factorize_s = 0;
  for (size_t g = 0; g < sys.groups.size(); ++g) {
    if (factored_version_[g] != sys.groups[g].version) {
      groups_[g].factorize(sys.groups[g]);
      factored_version_[g] = sys.groups[g].version;
      ++stats_.factorizations[sys.groups[g].name];
    }
    stats_.analyze_s += groups_[g].stats().analyze_s;
    stats_.factorize_s += groups_[g].stats().factorize_s;
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
    Eigen::VectorXd y = Eigen::VectorXd::Zero(lambda.size());
    for (size_t g = 0; g < sys.groups.size(); ++g) {
      const Group& grp = sys.groups[g];
      if (grp.C.nonZeros() == 0) continue;
      y += grp.C * groups_[g].apply(grp.C.transpose() * lambda);
    }
    return y;
  };
  return p;
}

BlockSolution MixedStrategy::solve(const BlockSystem& sys, AnalysisObserver* observer) {
  factorize_changed(sys);
  Stopwatch t;
  std::vector<Eigen::VectorXd> Kf;
  for (size_t g = 0; g < sys.groups.size(); ++g) Kf.push_back(groups_[g].apply(sys.groups[g].f));
  const InterfaceProblem problem = interface_problem(sys, Kf);
  last_ = projected_cg(problem, {options_.cg_tolerance, 10000, {}}, observer);
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
