// Factory for the sparse symmetric factorizations by name ("skyline", "cholmod").
#include "solve/Factorization.h"

#include "base/Memory.h"
#include "solve/CholmodFactorization.h"
#include "solve/SkylineFactorization.h"
#include "solve/UmfpackFactorization.h"

namespace rollsim {

void check_factor_fits(double bytes, long rows, const std::string& what) {
  const double left = memory_left_bytes();
  if (bytes <= left) return;
  throw OutOfMemory("out of memory: " + what + " of " + std::to_string(rows) + " rows needs at least " +
                        gigabytes(bytes) + " and " + memory_left_source() + " leaves this run " + gigabytes(left) +
                        " — a coarser mesh, `feti` with more subdomains, or a machine with more memory",
                    bytes);
}

Eigen::MatrixXd Factorization::solve_columns(const Eigen::MatrixXd& B) {
  Eigen::MatrixXd X(B.rows(), B.cols());
  for (Eigen::Index j = 0; j < B.cols(); ++j) X.col(j) = solve(B.col(j));
  return X;
}

Eigen::MatrixXd Factorization::inverse_quadratic(const Eigen::MatrixXd& E) { return E.transpose() * solve_columns(E); }

std::unique_ptr<Factorization> make_factorization(const std::string& kind, int trailing) {
  if (kind == "skyline") return std::make_unique<SkylineFactorization>(trailing);
  if (kind == "cholmod" && trailing > 0) return std::make_unique<UmfpackFactorization>();
  if (kind == "cholmod") return std::make_unique<CholmodFactorization>();
  throw std::invalid_argument("unknown factorization '" + kind + "' (valid: skyline, cholmod)");
}

}  // namespace rollsim
