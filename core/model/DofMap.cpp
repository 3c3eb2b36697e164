#include "model/DofMap.h"

#include "model/PrescribedMotion.h"

namespace rollsim {

DofMap::DofMap(const Body& body, int body_index, const std::vector<DisplacementBC>& bcs)
    : dim_(body.mesh.dim), eq_(static_cast<size_t>(body.mesh.num_nodes()) * dim_, 0), up_(eq_.size(), 0.0) {
  for (const DisplacementBC& bc : bcs) {
    if (bc.body != body_index) continue;
    if (bc.rotation) {
      if (rotation_of_.empty()) rotation_of_.assign(static_cast<size_t>(body.mesh.num_nodes()), -1);
      rotations_.push_back(*bc.rotation);
    }
    for (int n : bc.nodes) {
      if (bc.rotation) rotation_of_[static_cast<size_t>(n)] = static_cast<int>(rotations_.size()) - 1;
      for (int c = 0; c < dim_; ++c)
        if (bc.value[c] || bc.rotation) {
          eq_[static_cast<size_t>(n) * dim_ + c] = -1;
          up_[static_cast<size_t>(n) * dim_ + c] = bc.value[c].value_or(0.0);
        }
    }
  }
  if (!rotations_.empty()) position_ = body.mesh.nodes;
  number();
}

DofMap::DofMap(const DofMap& body_map, const std::vector<int>& nodes)
    : dim_(body_map.dim_),
      eq_(nodes.size() * static_cast<size_t>(dim_)),
      up_(eq_.size()),
      rotations_(body_map.rotations_) {
  for (size_t l = 0; l < nodes.size(); ++l) {
    const size_t n = static_cast<size_t>(nodes[l]);
    for (int c = 0; c < dim_; ++c) {
      eq_[l * dim_ + c] = body_map.eq_[n * dim_ + c] < 0 ? -1 : 0;
      up_[l * dim_ + c] = body_map.up_[n * dim_ + c];
    }
    if (body_map.rotation_of_.empty()) continue;
    rotation_of_.push_back(body_map.rotation_of_[n]);
    position_.push_back(body_map.position_[n]);
  }
  number();
}

void DofMap::number() {
  for (int& e : eq_)
    if (e == 0) e = num_free_++;
}

double DofMap::prescribed(int node, int comp, double load_factor) const {
  const size_t i = static_cast<size_t>(node) * dim_ + comp;
  if (eq_[i] >= 0) return 0.0;
  const double t = load_factor == 1.0 ? up_[i] : load_factor * up_[i];  // exact for 1
  if (rotation_of_.empty() || rotation_of_[static_cast<size_t>(node)] < 0) return t;
  const RigidRotation& r = rotations_[static_cast<size_t>(rotation_of_[static_cast<size_t>(node)])];
  return t + rotation_displacement(r, position_[static_cast<size_t>(node)], load_factor)[comp];
}

Eigen::VectorXd DofMap::expand(const Eigen::VectorXd& free, double load_factor) const {
  Eigen::VectorXd u(static_cast<Eigen::Index>(eq_.size()));
  for (size_t i = 0; i < eq_.size(); ++i)
    u[static_cast<Eigen::Index>(i)] =
        eq_[i] >= 0 ? free[eq_[i]] : prescribed(static_cast<int>(i) / dim_, static_cast<int>(i) % dim_, load_factor);
  return u;
}

Eigen::VectorXd DofMap::restrict_to_free(const Eigen::VectorXd& full) const {
  Eigen::VectorXd f(num_free_);
  for (size_t i = 0; i < eq_.size(); ++i)
    if (eq_[i] >= 0) f[eq_[i]] = full[static_cast<Eigen::Index>(i)];
  return f;
}

}  // namespace rollsim
