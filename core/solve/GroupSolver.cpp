#include "solve/GroupSolver.h"

#include <algorithm>

#include "solve/CholeskyOrLU.h"

namespace rollsim {

namespace {
/// The r dofs where the kernel basis is best conditioned (pivots of a column-pivoted QR of Rᵀ).
std::vector<int> fixing_dofs(const Eigen::MatrixXd& R) {
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(R.transpose());
  std::vector<int> dofs;
  for (Eigen::Index k = 0; k < R.cols(); ++k) dofs.push_back(qr.colsPermutation().indices()[k]);
  std::sort(dofs.begin(), dofs.end());
  return dofs;
}

SparseMatrix remove_dofs(const SparseMatrix& K, const std::vector<int>& kept) {
  std::vector<int> position(static_cast<size_t>(K.rows()), -1);
  for (size_t i = 0; i < kept.size(); ++i) position[kept[i]] = static_cast<int>(i);
  std::vector<Eigen::Triplet<double, int>> t;
  t.reserve(static_cast<size_t>(K.nonZeros()));
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (position[it.row()] >= 0 && position[j] >= 0) t.emplace_back(position[it.row()], position[j], it.value());
  SparseMatrix Kpp(static_cast<int>(kept.size()), static_cast<int>(kept.size()));
  Kpp.setFromTriplets(t.begin(), t.end());
  return Kpp;
}
}  // namespace

void GroupSolver::factorize(const Group& g) {
  try {
    factorize_values(g);
  } catch (const SingularMatrix& e) {  // name the group; the column in its own numbering
    const int col = e.column >= 0 && !kept_.empty() ? kept_[static_cast<size_t>(e.column)] : e.column;
    throw SingularMatrix(std::string(e.what()) + " of group '" + g.name + "'", col);
  }
}

void GroupSolver::factorize_values(const Group& g) {
  if (g.K.rows() != size_) {
    size_ = g.K.rows();
    factor_ = kind_ == "cholmod" ? std::make_unique<CholeskyOrLU>() : make_factorization(kind_);
    analyzed_ = false;
    fixed_.clear(), kept_.clear();
    choose_fixed_dofs(g.R);
  } else if (g.R.rows() != R_.rows() || g.R.cols() != R_.cols() || g.R != R_) {
    choose_fixed_dofs(g.R);
  }
  const bool reduced = !fixed_.empty();
  const SparseMatrix Kpp = reduced ? remove_dofs(g.K, kept_) : SparseMatrix();
  const SparseMatrix& A = reduced ? Kpp : g.K;
  if (!analyzed_) factor_->analyze(A);
  analyzed_ = true;
  factor_->factorize(A);
}

void GroupSolver::choose_fixed_dofs(const Eigen::MatrixXd& R) {
  R_ = R;
  std::vector<int> fixed = R.cols() ? fixing_dofs(R) : std::vector<int>{};
  if (fixed == fixed_) return;
  fixed_ = std::move(fixed);  // other dofs fixed (the kernel turned with a finite-strain group): a new pattern
  kept_.clear();
  for (int i = 0, f = 0; i < size_; ++i)
    if (f < static_cast<int>(fixed_.size()) && fixed_[f] == i)
      ++f;
    else if (!fixed_.empty())
      kept_.push_back(i);
  analyzed_ = false;
}

bool GroupSolver::indefinite() const {
  const auto* f = dynamic_cast<const CholeskyOrLU*>(factor_.get());
  return f && f->indefinite();
}

Eigen::VectorXd GroupSolver::apply(const Eigen::VectorXd& b) {
  if (fixed_.empty()) return factor_->solve(b);
  Eigen::VectorXd bp(static_cast<Eigen::Index>(kept_.size()));
  for (size_t i = 0; i < kept_.size(); ++i) bp[static_cast<Eigen::Index>(i)] = b[kept_[i]];
  const Eigen::VectorXd xp = factor_->solve(bp);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(b.size());
  for (size_t i = 0; i < kept_.size(); ++i) x[kept_[i]] = xp[static_cast<Eigen::Index>(i)];
  return x;
}

Eigen::MatrixXd GroupSolver::inverse_block(const std::vector<int>& rows, const std::vector<int>& cols) {
  auto factored = [&](int dof) -> Eigen::Index {  // the dof's row in the factored matrix, −1 when fixed
    if (fixed_.empty()) return dof;
    const auto it = std::lower_bound(kept_.begin(), kept_.end(), dof);
    return it != kept_.end() && *it == dof ? it - kept_.begin() : -1;
  };
  const auto n = static_cast<Eigen::Index>(fixed_.empty() ? size_ : static_cast<long>(kept_.size()));
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, static_cast<Eigen::Index>(cols.size()));
  for (size_t j = 0; j < cols.size(); ++j)
    if (const Eigen::Index p = factored(cols[j]); p >= 0) E(p, static_cast<Eigen::Index>(j)) = 1.0;
  if (rows == cols) {  // K⁺(cols, cols) = Eᵀ K⁺ E: half the triangular work with a Cholesky factor
    Eigen::MatrixXd out = factor_->inverse_quadratic(E);
    return out;
  }
  const Eigen::MatrixXd X = factor_->solve_columns(E);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), E.cols());
  for (size_t i = 0; i < rows.size(); ++i)
    if (const Eigen::Index p = factored(rows[i]); p >= 0) out.row(static_cast<Eigen::Index>(i)) = X.row(p);
  for (size_t j = 0; j < cols.size(); ++j)  // a fixed dof's column: zero, as K⁺ has it
    if (factored(cols[j]) < 0) out.col(static_cast<Eigen::Index>(j)).setZero();
  return out;
}

}  // namespace rollsim
