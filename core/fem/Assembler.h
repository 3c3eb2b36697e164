#pragma once
// Assembly of one group's stiffness over its free dofs. The sparsity pattern and the
// element -> value-slot scatter map are computed once; assemble() only rewrites values.
#include <Eigen/Sparse>
#include <vector>

#include "model/DofMap.h"
#include "model/Model.h"

namespace rollsim {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

class Assembler {
 public:
  Assembler(const Body& body, const DofMap& dofs);

  /// K_ff (both triangles stored) and the load from prescribed dofs, f_D = -K_fp u_p.
  void assemble(SparseMatrix& K, Eigen::VectorXd& f_dirichlet) const;

 private:
  const Body& body_;
  const DofMap& dofs_;
  SparseMatrix pattern_;
  std::vector<int> slot_;  // per element, per (i, j) of the element matrix: value index or -1
};

/// Element dof -> equation (or -1) for element e, node-major.
void element_equations(const Mesh& mesh, const DofMap& dofs, int e, int* eq);

}  // namespace rollsim
