#pragma once
// Numbering of one body's dofs: free dofs get consecutive equation numbers (node-major),
// prescribed dofs are eliminated and keep their prescribed value.
#include <Eigen/Dense>
#include <vector>

#include "model/Model.h"

namespace rollsim {

class DofMap {
 public:
  DofMap(const Body& body, int body_index, const std::vector<DisplacementBC>& bcs);

  int dim() const { return dim_; }
  int num_free() const { return num_free_; }
  int num_prescribed() const { return static_cast<int>(eq_.size()) - num_free_; }
  /// Equation number of dof (node, component), or -1 if prescribed.
  int equation(int node, int comp) const { return eq_[static_cast<size_t>(node) * dim_ + comp]; }
  double prescribed(int node, int comp) const { return up_[static_cast<size_t>(node) * dim_ + comp]; }
  /// Full nodal displacement vector (node-major) from the free solution, prescribed values times `load_factor`.
  Eigen::VectorXd expand(const Eigen::VectorXd& free, double load_factor = 1.0) const;
  /// Free-dof part of a full nodal vector.
  Eigen::VectorXd restrict_to_free(const Eigen::VectorXd& full) const;

 private:
  int dim_;
  int num_free_ = 0;
  std::vector<int> eq_;
  std::vector<double> up_;
};

}  // namespace rollsim
