#include "solve/CholmodView.h"

#include <stdexcept>

namespace rollsim {

cholmod_sparse cholmod_view(const SparseMatrix& A, int stype) {
  if (!A.isCompressed()) throw std::invalid_argument("CHOLMOD needs a compressed sparse matrix");
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(A.rows());
  s.ncol = static_cast<size_t>(A.cols());
  s.nzmax = static_cast<size_t>(A.nonZeros());
  s.p = const_cast<int*>(A.outerIndexPtr());
  s.i = const_cast<int*>(A.innerIndexPtr());
  s.x = const_cast<double*>(A.valuePtr());
  s.stype = stype;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

Eigen::VectorXd cholmod_solve_vector(cholmod_factor& L, const Eigen::VectorXd& b, cholmod_common& common) {
  cholmod_dense rhs{};
  rhs.nrow = rhs.nzmax = rhs.d = static_cast<size_t>(b.size());
  rhs.ncol = 1;
  rhs.x = const_cast<double*>(b.data());
  rhs.xtype = CHOLMOD_REAL;
  rhs.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, &L, &rhs, &common);
  if (!x) throw std::runtime_error("CHOLMOD solve failed (status " + std::to_string(common.status) + ")");
  Eigen::VectorXd out = Eigen::Map<Eigen::VectorXd>(static_cast<double*>(x->x), b.size());
  cholmod_free_dense(&x, &common);
  return out;
}

}  // namespace rollsim
