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
  // slave_body[r]: the body of its first free term — a contact row's slave (ContactConstraints writes the slave node
  // first), or its master where every slave term is prescribed (a slave node on a symmetry plane, along its normal)
  std::vector<int> slave_body;
  // per body, when set: what the multipliers add to the bodies' equations beyond Cᵀ (slipping Coulomb friction,
  // contact/Friction slip_coupling), rows × free dofs; empty: nothing (a symmetric system)
  std::vector<SparseMatrix> coupling;
};

BodyConstraints body_constraints(const std::vector<ConstraintRow>& rows,
                                 const std::vector<std::unique_ptr<DofMap>>& dofs, double load_factor = 1.0);

/// A sticking point whose relative motion along an axis e is held on both sides by the supports (its slave node and
/// every master node it projects onto with a weight have that component prescribed: a node of the slab's width
/// symmetry plane on the roll's barrel centre plane) keeps one tangential row, along n × e, instead of two: the second
/// row's free terms are round-off (a weight of 1e-16 across the edge, a tangent a hair off e), a direction the
/// supports hold already, and the interface solve could not meet it (a contact row unmet by 3.4e-7 at a limit of
/// 3.4e-7 on the 3D pass with both mid-planes held). The rows stay in order; the row that stays has comp
/// kSupportedTangent and dir n × e, and its multiplier the force along it.
void hold_supported_tangents(std::vector<ConstraintRow>& rows, const std::vector<std::unique_ptr<DofMap>>& dofs);

/// The terms of `extra` (one row per input row of `rows`, as slip_coupling gives them) on the bodies' free dofs, in
/// the rows of `c` (its `kept` numbering), into c.coupling; terms on prescribed dofs drop (they load no free dof).
/// c.coupling stays empty when no row has a term.
void add_coupling(const std::vector<ConstraintRow>& extra, const std::vector<std::unique_ptr<DofMap>>& dofs,
                  BodyConstraints& c);

}  // namespace rollsim
