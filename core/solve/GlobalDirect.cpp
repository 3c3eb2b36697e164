#include "solve/GlobalDirect.h"

#include <vector>

namespace rollsim {

namespace {
SparseMatrix block_diagonal(const BlockSystem& sys) {
  const long n = sys.num_dofs();
  std::vector<Eigen::Triplet<double, int>> t;
  long offset = 0;
  for (const Group& g : sys.groups) {
    for (int j = 0; j < g.K.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(g.K, j); it; ++it)
        t.emplace_back(static_cast<int>(offset + it.row()), static_cast<int>(offset + j), it.value());
    offset += g.K.rows();
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}
}  // namespace

GlobalDirect::GlobalDirect(std::string kind) : kind_(std::move(kind)) {}

std::vector<Eigen::VectorXd> GlobalDirect::solve(const BlockSystem& sys) {
  const SparseMatrix& A = sys.groups.size() == 1 ? sys.groups[0].K : (global_ = block_diagonal(sys));
  Eigen::VectorXd f(A.rows());
  long offset = 0;
  for (const Group& g : sys.groups) {
    f.segment(offset, g.f.size()) = g.f;
    offset += g.f.size();
  }
  const bool new_pattern = !factor_ || factor_->stats().factorizations == 0;
  if (!factor_) factor_ = make_factorization(kind_);
  if (new_pattern) factor_->analyze(A);
  factor_->factorize(A);
  const Eigen::VectorXd u = factor_->solve(f);
  for (const Group& g : sys.groups) ++stats_.factorizations[g.name];
  stats_.factor = factor_->stats();
  stats_.analyze_s = stats_.factor.analyze_s;
  stats_.factorize_s = stats_.factor.factorize_s;
  stats_.solve_s = stats_.factor.solve_s;
  std::vector<Eigen::VectorXd> out;
  offset = 0;
  for (const Group& g : sys.groups) {
    out.push_back(u.segment(offset, g.f.size()));
    offset += g.f.size();
  }
  return out;
}

}  // namespace rollsim
