#pragma once
// The sparse matrix type of the model's layers (assembly, subdomain blocks, contact rows). solve/ names the same
// type for itself, since it sees no model.
#include <Eigen/Sparse>

namespace rollsim {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

}  // namespace rollsim
