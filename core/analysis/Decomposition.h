#pragma once
// One body torn into subdomain groups plus its interface constraints — the part of the BlockSystem that the FETI
// strategy (paper §2: [K_i B_iᵀ C_iᵀ; B_i 0 0; C_i 0 0]) gets for that body.
#include <string>
#include <vector>

#include "analysis/GroupAssembler.h"
#include "model/DofMap.h"
#include "model/Model.h"
#include "partition/Interface.h"
#include "partition/Partition.h"
#include "partition/Subdomain.h"
#include "solve/BlockSystem.h"

namespace rollsim {

struct DecomposeOptions {
  Multipliers multipliers = Multipliers::NonRedundant;
  bool split_disconnected = true;  // split subdomains made of several pieces (a warning says so) or refuse them
  bool assemble = true;            // false: groups carry R and C only (counting, GUI preview)
};

struct BodyDecomposition {
  int body = 0;
  int body_free_dofs = 0;             // the undivided body's free dofs
  Partition partition;                // as used (after automatic splitting)
  std::vector<Subdomain> subdomains;  // local bodies and dof maps, kept for re-assembly (selective update)
  Interface interface;
  Multipliers multipliers = Multipliers::NonRedundant;
  std::vector<Group> groups;              // one per subdomain: K_i, f_i, C = B_i (rows: this body's multipliers), R_i
  Eigen::VectorXd d;                      // zeros: Σ_i B_i u_i = 0
  long paper_convention_multipliers = 0;  // the paper's count for this partition (paper_convention_count)
  std::vector<std::string> warnings;      // automatic splits

  long num_multipliers() const { return d.size(); }
  long num_rigid_modes() const;
};

/// Group of one subdomain without its matrices — paper §2: R_i = kernel_basis(local mesh, local dofs), C left
/// 0 × n (see boolean_blocks); the GroupAssembler fills K_i and f_i from subdomain_source.
Group subdomain_group(const Subdomain& s, int body_index, const std::string& body_name);

/// Where subdomain s's K_i and f_i come from: the body's element code on the local mesh, and the body's external
/// nodal load (node-major, every dof) shared equally among the `multiplicity[node]` subdomains holding a node, so
/// that Σ_i L_i f_i = f (L_i: local -> body).
GroupSource subdomain_source(const Subdomain& s, int body_index, const Eigen::VectorXd& nodal_load,
                             const std::vector<int>& multiplicity);

/// The follower pressures of a body (on its facets) restricted to subdomain s, on its local elements' facets. Each
/// facet lies in one subdomain, whose group carries its whole load.
std::vector<FollowerPressure> subdomain_follower(const Subdomain& s, const std::vector<FollowerPressure>& body_loads);

/// Tears body `b` of the model along `partition`. Throws PartitionError listing every problem of the partition
/// (with paths under "bodies[b].partition").
BodyDecomposition decompose_body(const Model& model, int b, Partition partition, const DecomposeOptions& options = {});

/// The same from the parts: the body, its dof map and its external nodal load (node-major, every dof).
BodyDecomposition decompose_body(const Body& body, int b, const DofMap& dofs, const Eigen::VectorXd& nodal_load,
                                 Partition partition, const DecomposeOptions& options = {});

/// How gather_free settles the copies of an interface dof: their mean, or the lowest subdomain's copy.
enum class InterfaceValue { Average, FirstCopy };

/// Body free-dof vector from the subdomain vectors u_i (one per group, local free dofs).
Eigen::VectorXd gather_free(const BodyDecomposition& dec, const std::vector<Eigen::VectorXd>& u,
                            InterfaceValue how = InterfaceValue::Average);

/// Columns of a constraint block written on the undivided body's free dofs (e.g. contact C_j, or a load as a row)
/// moved onto the subdomains: a dof shared by k subdomains goes to every copy with 1/k of its coefficient (the copies
/// are equal by B u = 0, so the row says the same; a contact row at a node on a subdomain boundary is then
/// preconditioned by every subdomain holding the node, not the one copy's too soft Schur complement: the slab in 8
/// subdomains, its arc cut by one, 26.9 → 23.2 interface iterations per Newton iteration, docs/BENCHMARKS-PETSC.md).
std::vector<SparseMatrix> split_constraint_columns(const SparseMatrix& C_body, const BodyDecomposition& dec);

/// Appends the groups (moved out of `dec`) and their multipliers to a system: the new rows follow the existing
/// multipliers; every group's C gets the new total row count.
void append_to_system(BlockSystem& sys, BodyDecomposition& dec);

}  // namespace rollsim
