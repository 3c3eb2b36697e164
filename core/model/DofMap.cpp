#include "model/DofMap.h"

namespace rollsim {

DofMap::DofMap(const Body& body, int body_index, const std::vector<DisplacementBC>& bcs)
    : dim_(body.mesh.dim), eq_(static_cast<size_t>(body.mesh.num_nodes()) * dim_, 0), up_(eq_.size(), 0.0) {
  for (const DisplacementBC& bc : bcs) {
    if (bc.body != body_index) continue;
    for (int n : bc.nodes)
      for (int c = 0; c < dim_; ++c)
        if (bc.value[c]) {
          eq_[static_cast<size_t>(n) * dim_ + c] = -1;
          up_[static_cast<size_t>(n) * dim_ + c] = *bc.value[c];
        }
  }
  for (int& e : eq_)
    if (e == 0) e = num_free_++;
}

Eigen::VectorXd DofMap::expand(const Eigen::VectorXd& free, double load_factor) const {
  Eigen::VectorXd u(static_cast<Eigen::Index>(eq_.size()));
  for (size_t i = 0; i < eq_.size(); ++i)
    u[static_cast<Eigen::Index>(i)] = eq_[i] >= 0 ? free[eq_[i]] : load_factor * up_[i];  // exact for 1
  return u;
}

Eigen::VectorXd DofMap::restrict_to_free(const Eigen::VectorXd& full) const {
  Eigen::VectorXd f(num_free_);
  for (size_t i = 0; i < eq_.size(); ++i)
    if (eq_[i] >= 0) f[eq_[i]] = full[static_cast<Eigen::Index>(i)];
  return f;
}

}  // namespace rollsim
