#pragma once
// Constraint rows written in body terms (body, node, component) become the block system's C_g and d:
// free dofs get their coefficient in the owning group, prescribed dofs move their known part to d.
#include <memory>
#include <vector>

#include "contact/ContactConstraints.h"
#include "model/DofMap.h"
#include "solve/BlockSystem.h"

namespace rollsim {

/// Groups are the bodies, in order (group g ↔ body g). Rows without any free dof are dropped and their
/// indices returned in `dropped` (they constrain prescribed dofs only).
void set_constraints(const std::vector<ConstraintRow>& rows, const std::vector<std::unique_ptr<DofMap>>& dofs,
                     BlockSystem& sys, std::vector<int>* kept = nullptr);

}  // namespace rollsim
