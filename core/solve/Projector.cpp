#include "solve/Projector.h"

namespace rollsim {

Projector::Projector(const SparseMatrix& G, const SparseMatrix* QG) : G_(G), QG_(QG ? *QG : G) {
  if (G.cols() == 0) return;
  const Eigen::MatrixXd GtQG = Eigen::MatrixXd(SparseMatrix(G.transpose() * QG_));
  qr_.compute(GtQG);
  qr_.setThreshold(1e-10);
  if (qr_.rank() < GtQG.cols())
    throw SingularMatrix("GᵀQG is singular: the constraints do not hold every rigid mode", -1);
}

}  // namespace rollsim
