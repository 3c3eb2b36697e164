#pragma once
// CHOLMOD supernodal Cholesky with CHOLMOD's choice of AMD / METIS ordering (the modern baseline). Solves go
// through supernodal_solve (SupernodalSolve.h), not cholmod_solve. One object is used by one thread at a time.
#include <cholmod.h>

#include <string>

#include "solve/Factorization.h"

namespace rollsim {

/// How CHOLMOD orders and amalgamates. The defaults are rollsim's (chosen in docs/BENCHMARKS.md, "Factorization");
/// `cholmod_defaults()` are CHOLMOD's own, kept to measure against.
struct CholmodSettings {
  /// auto (rollsim's): METIS nested dissection on the node graph (NodeOrdering.h) when the mesh's nodes have at least
  /// kNestedDissectionDegree neighbours (3D), AMD below (2D: as good a factor at 1e4-1e5 dofs, 3-4× cheaper to
  /// compute); automatic: CHOLMOD's own choice (AMD, then METIS on the dof graph too when AMD's fill is poor);
  /// nodes: METIS on the node graph always; amd, metis, nesdis: that CHOLMOD ordering alone.
  std::string ordering = "auto";
  // supernode amalgamation (CHOLMOD's Common->nrelax / zrelax): supernodes of up to nrelax[i] columns merge while
  // the fraction of explicit zeros stays under zrelax[i]
  int nrelax[3] = {4, 16, 48};
  double zrelax[3] = {0.8, 0.1, 0.05};
  static CholmodSettings cholmod_defaults();
  /// Mean node degree (mean_node_degree) from which `auto` orders by nested dissection: quadrilaterals have 9,
  /// triangles ~7, hexahedra 27, tetrahedra ~15.
  static constexpr double kNestedDissectionDegree = 12;
};

/// Thrown when the Cholesky factorization meets a negative (or zero) pivot: the matrix is indefinite or singular,
/// which a symmetric indefinite factorization (CholeskyOrLU) can tell apart.
struct NotPositiveDefinite : SingularMatrix {
  using SingularMatrix::SingularMatrix;
};

class CholmodFactorization final : public Factorization {
 public:
  explicit CholmodFactorization(CholmodSettings settings = {});
  ~CholmodFactorization() override;
  CholmodFactorization(const CholmodFactorization&) = delete;
  CholmodFactorization& operator=(const CholmodFactorization&) = delete;

  void analyze(const SparseMatrix& A) override;
  void factorize(const SparseMatrix& A) override;
  Eigen::VectorXd solve(const Eigen::VectorXd& b) override;
  Eigen::MatrixXd solve_columns(const Eigen::MatrixXd& B) override;
  /// Eᵀ A⁻¹ E = WᵀW with W = L⁻¹ P E: a forward substitution over the columns' reaches, no back substitution
  /// (supernodal_inverse_quadratic).
  Eigen::MatrixXd inverse_quadratic(const Eigen::MatrixXd& E) override;
  const FactorStats& stats() const override { return stats_; }

 private:
  void check_factored() const;
  double factor_bytes() const;  // of the analysed factor: its values and (supernodal, a fraction) indices
  /// cholmod_solve2 of `system` (CHOLMOD_A, CHOLMOD_L, …) with the columns of B: the result, in X_
  const double* solve_block(int system, const Eigen::MatrixXd& B);
  CholmodSettings settings_;
  cholmod_common common_;
  cholmod_factor* factor_ = nullptr;
  Eigen::VectorXd work_;                                      // supernodal_solve's scratch
  cholmod_dense *X_ = nullptr, *Y_ = nullptr, *E_ = nullptr;  // solve_columns' result and workspace (cholmod_solve2)
  FactorStats stats_;
};

}  // namespace rollsim
