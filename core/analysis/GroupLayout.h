#pragma once
// How the bodies become the block system's groups (DESIGN.md): one group per body, or — for a partitioned body
// when the strategy works on subdomains (feti) — one group per subdomain, glued by the interface rows B_i
// (paper §2). The multipliers are ordered [contact; interface]: contact rows change with the active set, the
// interface rows never do. A body without free dofs (moved wholly by its conditions: a rigid roll) has no group.
#include <memory>
#include <optional>
#include <vector>

#include "analysis/ConstraintAssembly.h"
#include "analysis/Decomposition.h"
#include "analysis/GroupAssembler.h"
#include "analysis/Results.h"
#include "contact/ContactStiffness.h"
#include "solve/BlockSystem.h"

namespace rollsim {

class GroupLayout {
 public:
  /// The groups with their kernels and interface rows, not yet assembled. `split`: tear partitioned bodies into
  /// subdomains.
  GroupLayout(const Model& model, bool split, Multipliers choice);

  /// K_g and f_g = r_g for the listed groups (GroupAssembler::assemble); the caller bumps their versions.
  void assemble(const std::vector<size_t>& groups, const std::vector<Eigen::VectorXd>& u_free, double load_factor) {
    assembler_.assemble(groups, u_free, load_factor, sys_);
  }

  GroupAssembler& assembler() { return assembler_; }
  const GroupAssembler& assembler() const { return assembler_; }
  BlockSystem& system() { return sys_; }
  const BlockSystem& system() const { return sys_; }
  const std::vector<std::unique_ptr<DofMap>>& body_dofs() const { return dofs_; }
  /// Adds a load on the bodies' free dofs (one vector per body) to the residuals f_g of the listed groups (a dof
  /// shared by subdomains loads one of them, as a constraint term does).
  void add_body_load(const std::vector<Eigen::VectorXd>& load, const std::vector<size_t>& groups);
  /// Adds stiffness entries on the bodies' dofs (the contact's geometric stiffness) to the tangents K_g of the listed
  /// groups: an entry whose two dofs lie in one group (for a torn body: one subdomain holding both) goes into that
  /// group's K where K's pattern has it; an entry joining two groups goes into `cross` (every group's free dofs one
  /// after the other, BlockSystem::coupling) when given. Returns how many nonzero entries dropped.
  long add_body_stiffness(const std::vector<StiffnessEntry>& entries, const std::vector<size_t>& groups,
                          SparseMatrix* cross);
  /// Puts the contact rows (blocks on the bodies' free dofs) in front of the interface rows; with a coupling
  /// (contact.coupling), the groups' C_eq as well.
  void set_contact(const BodyConstraints& contact);
  /// Stiffness Σ_i k_i c_iᵀc_i (c_i: rows[i] on the bodies' dofs) as compliant rows (BlockSystem::compliance; terms on
  /// prescribed dofs drop, a row left without terms goes); no rows clears them. False, with nothing set, when a row
  /// touches a torn body (its dofs lie in several subdomains).
  bool set_compliant(const std::vector<ConstraintRow>& rows, const std::vector<double>& stiffness);
  /// Body b's nodes moved under its material (an ALE step) to `nodes`: its subdomains' local meshes take their nodes'
  /// new positions (the body's own mesh is the model's, moved by the caller).
  void move_nodes(int b, const std::vector<std::array<double, 3>>& nodes);
  /// Free-dof vector of every body from the groups' solution (interface copies averaged).
  std::vector<Eigen::VectorXd> body_solution(const BlockSolution& sol) const;

  long subdomains() const { return static_cast<long>(sys_.groups.size()); }
  long interface_multipliers() const { return interface_rows_; }
  long paper_convention_multipliers() const { return paper_rows_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  struct BodyGroups {
    int first = 0, count = 1;  // count 0: a body without free dofs has no group
    std::optional<BodyDecomposition> dec;
  };
  void add_body(const Model& model, int b, bool split, Multipliers choice);
  /// The group and its equation holding (body, node, comp), in the subdomain `within` when ≥ 0; group −1: none.
  std::pair<int, int> group_equation(int body, int node, int comp, int within = -1) const;
  int free_dofs(size_t group) const { return assembler_.source(group).dofs->num_free(); }

  BlockSystem sys_;
  GroupAssembler assembler_;
  std::vector<std::unique_ptr<DofMap>> dofs_;
  std::vector<BodyGroups> bodies_;
  std::vector<SparseMatrix> interface_C_;  // per group: its interface rows, in the global interface numbering
  std::vector<double> interface_scaling_;
  long interface_rows_ = 0, paper_rows_ = 0;
  bool redundant_ = false;  // fully redundant glue
  std::vector<std::string> warnings_;
};

}  // namespace rollsim
