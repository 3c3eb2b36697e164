#pragma once
// The partition table of the GUI's partition painter (issue 6, item 3): per subdomain the counts the FETI solver
// will see for a map — elements, nodes, free dofs, interface multipliers, rigid modes, pieces — and an estimated
// Cholesky cost, with the predicted cost of the partition against one domain. PartitionReporter recomputes only
// what a paint stroke changed. The cost model is described in docs/PARTITIONS.md ("The partition table").
#include <memory>
#include <string>
#include <vector>

#include "mesh/Mesh.h"
#include "model/DofMap.h"
#include "model/Model.h"
#include "partition/Partition.h"

namespace rollsim {

/// Size of the Cholesky factor L of a stiffness matrix, as CHOLMOD counts it (Common->lnz, Common->fl).
struct FactorEstimate {
  double nnz = 0;    // Σ_j c_j, c_j: entries of column j of L, diagonal included
  double flops = 0;  // Σ_j c_j²
  bool operator==(const FactorEstimate&) const = default;
};

/// The factor of K on the free dofs of (mesh, dofs) under an AMD ordering of the node graph (nodes with a free dof,
/// joined when they share an element; all free dofs of a node consecutive): exact for that ordering (no numerical
/// cancellation assumed). `node_order`, if given, receives the mesh nodes in elimination order.
FactorEstimate estimate_factor(const Mesh& mesh, const DofMap& dofs, std::vector<int>* node_order = nullptr);

/// Predicted cost, in flops, of solving with a partition: per subdomain i
///   c_i = factorizations · flops(L_i) + (cg_iterations · substitutions_per_iteration + 2) · 4 nnz(L_i)
/// (4 nnz(L) flops per forward + back substitution; the 2 are K⁺f before and u_i after the CG), against one domain
///   c_0 = flops(L_0) + 4 nnz(L_0).
/// Defaults: the Dirichlet preconditioner (K_i and K_ii factored, one K⁺ and one K_ii⁻¹ substitution per CG
/// iteration, K_ii's factor taken as K_i's) and 25 iterations, the issue-5 anchors' ceiling (2D ≤ 20, 3D ≤ 25).
/// Lumped: factorizations = 1, substitutions_per_iteration = 1, cg_iterations ≈ 45.
struct CostModel {
  double cg_iterations = 25;
  double factorizations = 2;
  double substitutions_per_iteration = 2;
};

/// c_i of the CostModel for one factor [flops]: what the table's cost column and `solver.mode: auto` weigh.
double predicted_cost(const FactorEstimate& factor, const CostModel& model);
/// c_0, one domain factored and substituted once [flops].
double one_domain_cost(const FactorEstimate& factor);

struct SubdomainReport {
  int id = 0;
  int elements = 0;
  int nodes = 0;
  int dofs = 0;                     // free dofs (the body's Dirichlet conditions eliminated)
  long multipliers = 0;             // rows of B_i: non-redundant multipliers on free dofs (count_multipliers)
  long paper_multipliers = 0;       // the same rows by the paper's rule (paper_convention_count)
  int rigid_modes = 0;              // columns of kernel_basis for this subdomain as extract_subdomains builds it
  int rigid_modes_after_split = 0;  // Σ over its pieces: what decompose_body finds after split_disconnected
  int pieces = 0;                   // facet-connected pieces (subdomain_pieces)
  FactorEstimate factor;            // estimate_factor of the subdomain
  double cost = 0;                  // c_i of the CostModel [flops]
  bool floating() const { return rigid_modes_after_split > 0; }
  bool operator==(const SubdomainReport&) const = default;
};

struct PartitionReport {
  std::vector<SubdomainReport> subdomains;  // one per id 0 .. num_subdomains − 1 (empty when the map length is wrong)
  std::vector<PartitionProblem> problems;   // exactly check_partition's; empty: the FETI solver takes the map as is
  int body_elements = 0;
  int body_dofs = 0;
  long dofs = 0;                     // Σ subdomain dofs (an interface dof once per copy)
  long multipliers = 0;              // count_multipliers(find_interface(...), dofs, NonRedundant)
  long paper_multipliers = 0;        // paper_convention_count(find_interface(...), dim)
  long rigid_modes = 0;              // Σ rigid_modes
  long rigid_modes_after_split = 0;  // Σ rigid_modes_after_split
  FactorEstimate subdomain_factors;  // Σ over the subdomains
  FactorEstimate one_domain;         // estimate_factor of the whole body
  double cost = 0;                   // Σ c_i [flops]
  double one_domain_cost = 0;        // c_0 [flops]
  double predicted_ratio = 0;        // cost / one_domain_cost: below 1 the partition pays
};

struct ReporterOptions {
  CostModel cost;
  std::string path = "partition";  // prefix of the problems' paths, as check_partition's `path`
  int threads = 2;                 // subdomains recomputed concurrently
};

/// Keeps the report of one body's partition up to date. The first update computes every subdomain; later ones
/// compare the map with the previous one and recompute only the subdomains whose element sets changed and the
/// interface around the moved elements. Any map is accepted: a wrong length, ids out of range (their elements
/// then belong to no subdomain), empty or disconnected subdomains are listed in `problems`.
/// The body and its dof map must outlive the reporter.
class PartitionReporter {
 public:
  PartitionReporter(const Body& body, const DofMap& dofs, ReporterOptions options = {});
  ~PartitionReporter();
  PartitionReporter(const PartitionReporter&) = delete;
  PartitionReporter& operator=(const PartitionReporter&) = delete;

  const PartitionReport& update(const Partition& p);
  const PartitionReport& report() const;
  /// Subdomains recomputed by the last update.
  int last_recomputed() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace rollsim
