#pragma once
// Numbering of one body's dofs: free dofs get consecutive equation numbers (node-major),
// prescribed dofs are eliminated and keep their prescribed value: a translation scaled by the load factor,
// or a rigid rotation whose angle grows with it.
#include <Eigen/Dense>
#include <vector>

#include "model/Model.h"

namespace rollsim {

class DofMap {
 public:
  DofMap(const Body& body, int body_index, const std::vector<DisplacementBC>& bcs);
  /// The map of part of a body: local node l is node `nodes[l]` of `body_map`, with its prescribed dofs and values.
  DofMap(const DofMap& body_map, const std::vector<int>& nodes);

  int dim() const { return dim_; }
  int num_free() const { return num_free_; }
  int num_prescribed() const { return static_cast<int>(eq_.size()) - num_free_; }
  /// Equation number of dof (node, component), or -1 if prescribed.
  int equation(int node, int comp) const { return eq_[static_cast<size_t>(node) * dim_ + comp]; }
  /// The prescribed value of dof (node, component) at a load factor (0 for a free dof).
  double prescribed(int node, int comp, double load_factor = 1.0) const;
  /// Full nodal displacement vector (node-major) from the free solution, prescribed values at `load_factor`.
  Eigen::VectorXd expand(const Eigen::VectorXd& free, double load_factor = 1.0) const;
  /// Free-dof part of a full nodal vector.
  Eigen::VectorXd restrict_to_free(const Eigen::VectorXd& full) const;

 private:
  void number();

  int dim_;
  int num_free_ = 0;
  std::vector<int> eq_;
  std::vector<double> up_;  // the translation at load factor 1
  // rigid rotations: per node the index in rotations_ or -1, and its reference position (empty when none)
  std::vector<RigidRotation> rotations_;
  std::vector<int> rotation_of_;
  std::vector<std::array<double, 3>> position_;
};

}  // namespace rollsim
