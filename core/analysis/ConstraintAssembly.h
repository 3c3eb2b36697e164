#pragma once
// Constraint rows written in body terms (body, node, component) become blocks on each body's free dofs:
// free dofs get their coefficient, prescribed dofs move their known part (times the increment's load factor) to the
// right-hand side d.
#include <memory>
#include <vector>

#include "contact/ContactConstraints.h"
#include "model/DofMap.h"
#include "solve/Factorization.h"

namespace rollsim {

struct BodyConstraints {
  std::vector<SparseMatrix> C;  // per body: rows × its free dofs
  Eigen::VectorXd d;
  std::vector<int> kept;  // kept[r]: the input row of constraint r (rows on prescribed dofs only are dropped)
};

BodyConstraints body_constraints(const std::vector<ConstraintRow>& rows,
                                 const std::vector<std::unique_ptr<DofMap>>& dofs, double load_factor = 1.0);

}  // namespace rollsim
