#pragma once
// The one place where groups get their matrices (DESIGN.md): for a chosen list of groups, the stiffness K_g and the
// residual r_g = f_ext − f_int(u_g) — the linear analysis asks once for every group at u = 0; a Newton iteration
// asks for the groups its update policy selects (paper §1, selective update) at the current iterate.
#include <Eigen/Dense>
#include <vector>

#include "model/DofMap.h"
#include "model/Model.h"
#include "solve/BlockSystem.h"

namespace rollsim {

/// Where a group's matrices come from: its mesh and material (a whole body, or a subdomain's local body), its dof
/// map, and the external load on its nodes (node-major, every dof; at a subdomain interface node, this
/// subdomain's share).
struct GroupSource {
  const Body* body = nullptr;
  const DofMap* dofs = nullptr;
  Eigen::VectorXd nodal_load;
};

class GroupAssembler {
 public:
  /// Appends the source of the next group (group order).
  void add(GroupSource source) { sources_.push_back(std::move(source)); }
  size_t size() const { return sources_.size(); }
  const GroupSource& source(size_t g) const { return sources_[g]; }

  /// For each listed group g: K_g, and f_g = r_g = λ f_ext − f_int(u) on its free dofs, u being the free
  /// displacement `u_free[g]` (empty: zero) with the prescribed dofs at λ times their value (λ: load factor).
  /// The caller bumps the versions (mark_updated) of the groups whose K it wants refactored.
  void assemble(const std::vector<size_t>& groups, const std::vector<Eigen::VectorXd>& u_free, double load_factor,
                BlockSystem& sys) const;

 private:
  std::vector<GroupSource> sources_;
};

/// Every group index of a system, ascending.
std::vector<size_t> all_groups(const BlockSystem& sys);

}  // namespace rollsim
