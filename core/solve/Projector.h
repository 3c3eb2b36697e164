#pragma once
// The rigid-mode projectors of the interface solvers (paper eqs. (7)-(8)): ProjectedCG's, and ProjectedGMRES's
// oblique one for an unsymmetric interface.
#include <Eigen/Dense>

#include "solve/Factorization.h"

namespace rollsim {

/// The projectors P = I − QG(GᵀQG)⁻¹Gᵀ (search directions) and Pᵀ = I − G(GᵀQG)⁻¹(QG)ᵀ (residuals), with GᵀQG
/// factored once; Q = I when no QG is given (then P = Pᵀ). G is sparse: a floating group's modes touch only its
/// own constraint rows, so in FETI G has a few hundred nonzeros per column out of tens of thousands of rows (3D 40³
/// in 5×5×5 subdomains: 60k multipliers × 750 modes, 360 MB dense); dense, the products with G and Gᵀ made the
/// projection the most expensive part of every CG iteration and GᵀG a 30 GFlop product.
class Projector {
 public:
  /// Throws SingularMatrix (column −1) when GᵀQG is singular: the constraints do not hold some rigid mode.
  Projector(const SparseMatrix& G, const SparseMatrix* QG);
  /// P y: a direction in ker Gᵀ
  Eigen::VectorXd direction(const Eigen::VectorXd& y) const {
    return G_.cols() == 0 ? y : Eigen::VectorXd(y - QG_ * coarse(G_.transpose() * y));
  }
  /// Pᵀ r: the residual seen from ker Gᵀ
  Eigen::VectorXd residual(const Eigen::VectorXd& r) const {
    return G_.cols() == 0 ? r : Eigen::VectorXd(r - G_ * coarse(QG_.transpose() * r));
  }
  /// λ0 = QG(GᵀQG)⁻¹e, which satisfies Gᵀλ0 = e
  Eigen::VectorXd start(const Eigen::VectorXd& e, Eigen::Index rows) const {
    return G_.cols() == 0 ? Eigen::VectorXd(Eigen::VectorXd::Zero(rows)) : Eigen::VectorXd(QG_ * coarse(e));
  }
  /// A guess λ moved onto Gᵀλ = e: λ + QG(GᵀQG)⁻¹(e − Gᵀλ)
  Eigen::VectorXd feasible(const Eigen::VectorXd& guess, const Eigen::VectorXd& e) const {
    return G_.cols() == 0 ? guess : Eigen::VectorXd(guess + start(e - G_.transpose() * guess, guess.size()));
  }
  /// α = −(GᵀQG)⁻¹(QG)ᵀ r, so that r + Gα = b − Fλ + Gα is annihilated by (QG)ᵀ
  Eigen::VectorXd amplitudes(const Eigen::VectorXd& r) const {
    return G_.cols() == 0 ? Eigen::VectorXd() : Eigen::VectorXd(-coarse(QG_.transpose() * r));
  }
  /// α = −(GᵀQG)⁻¹Gᵀ r, so that r + QG α is annihilated by Gᵀ: the amplitudes of an unsymmetric interface problem
  /// F λ − QG α = b, Gᵀλ = e (projected_gmres: QG = C R, G = C_eq R)
  Eigen::VectorXd amplitudes_unsymmetric(const Eigen::VectorXd& r) const {
    return G_.cols() == 0 ? Eigen::VectorXd() : Eigen::VectorXd(-coarse(G_.transpose() * r));
  }

 private:
  Eigen::VectorXd coarse(const Eigen::VectorXd& v) const { return qr_.solve(v); }  // (GᵀQG)⁻¹ v
  const SparseMatrix& G_;
  const SparseMatrix& QG_;
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr_;
};

}  // namespace rollsim
