#pragma once
// A generalized inverse K⁺ of one group's stiffness (paper eqs. (5)-(6)). A regular K is factored as is.
// A floating group (kernel R with r columns) has r dofs fixed — those where R is best conditioned, chosen by
// column-pivoted QR of Rᵀ, so that no rigid motion survives them — and K⁺ = [Kpp⁻¹ 0; 0 0] (the paper's
// reordering). Then K K⁺ b = b for every b with Rᵀb = 0, which is all projected CG needs. Kind "cholmod" factors with
// CholeskyOrLU: a tangent that is not positive definite (a compressed finite-strain subdomain) goes to LU.
#include <memory>
#include <vector>

#include "solve/BlockSystem.h"

namespace rollsim {

class GroupSolver {
 public:
  /// `kind`: a factorization name of make_factorization ("cholmod", "skyline").
  explicit GroupSolver(std::string kind) : kind_(std::move(kind)) {}
  /// Analyzes on the first call (or when the size or the fixed dofs change) and factors K (or Kpp). The fixed dofs
  /// are chosen again whenever the kernel R changes (a finite-strain group's rigid modes follow its rotation).
  /// Throws SingularMatrix naming the group, its column in the group's own numbering.
  void factorize(const Group& g);
  /// K⁺ b
  Eigen::VectorXd apply(const Eigen::VectorXd& b);
  /// K⁺(rows, cols): K⁺'s columns at the dofs `cols`, solved for together (Factorization::solve_columns), at the
  /// dofs `rows` (a fixed dof's row and column are zero); rows == cols asks for Eᵀ K⁺ E
  /// (Factorization::inverse_quadratic: with a Cholesky factor, no back substitution)
  Eigen::MatrixXd inverse_block(const std::vector<int>& rows, const std::vector<int>& cols);
  const FactorStats& stats() const { return factor_->stats(); }
  const std::vector<int>& fixed_dofs() const { return fixed_; }
  /// True when the factor is of an indefinite matrix (K⁺ is then indefinite, and so may the interface operator be).
  bool indefinite() const;

 private:
  std::string kind_;
  std::unique_ptr<Factorization> factor_;
  std::vector<int> fixed_;  // dofs set to zero in K⁺ (floating groups)
  std::vector<int> kept_;   // kept_[i]: dof of row i of Kpp; empty when nothing is fixed
  Eigen::MatrixXd R_;       // the kernel the fixed dofs were chosen for
  long size_ = -1;
  bool analyzed_ = false;
  void factorize_values(const Group& g);
  void choose_fixed_dofs(const Eigen::MatrixXd& R);
};

}  // namespace rollsim
