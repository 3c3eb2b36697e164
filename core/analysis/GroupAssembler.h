#pragma once
// The one place where groups get their matrices (DESIGN.md): for a chosen list of groups, the stiffness K_g and the
// residual r_g = f_ext − f_int(u_g) — the linear analysis asks once for every group at u = 0; a Newton iteration
// asks for the groups its update policy selects (paper §1, selective update) at the current iterate.
#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "fem/Assembler.h"
#include "fem/Loads.h"
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
  int model_body = 0;                      // the model's body this group belongs to
  std::vector<int> body_elements;          // local element -> that body's element (empty: the same numbering)
  std::vector<FollowerPressure> follower;  // pressures on its facets that follow the surface (not in nodal_load)
};

/// Where a Newton assembly stopped: an inverted element (group, local element), or none (group < 0).
struct InvertedElement {
  int group = -1, element = -1;
  explicit operator bool() const { return group >= 0; }
};

class GroupAssembler {
 public:
  /// Appends the source of the next group (group order), with its initial integration-point state.
  void add(GroupSource source);
  size_t size() const { return sources_.size(); }
  const GroupSource& source(size_t g) const { return sources_[g]; }

  /// For each listed group g: K_g, and f_g = r_g = λ f_ext − f_int(u) on its free dofs, u being the free
  /// displacement `u_free[g]` (empty: zero) with the prescribed dofs at load factor λ.
  /// The caller bumps the versions (mark_updated) of the groups whose K it wants refactored.
  void assemble(const std::vector<size_t>& groups, const std::vector<Eigen::VectorXd>& u_free, double load_factor,
                BlockSystem& sys) const;

  /// The Newton assembly at the iterate `u_free` (one vector per group), prescribed dofs at load factor
  /// `at.prescribed`: for the groups in `which`, f_g = r_g = at.load f_ext − f_int(u_g, committed state) and the trial
  /// state; for those also in `tangent`, K_g, the consistent tangent (the others keep theirs: the selective
  /// update); a floating finite-strain group's kernel R is then taken in the current configuration (its rigid
  /// rotation turns with it). With at.prescribed_step ≠ 0, f_int is predicted by the tangent at the prescribed dofs
  /// moved on to load factor at.prescribed + at.prescribed_step (the first iteration of a step). Stops at an inverted
  /// element, named.
  struct Factors {
    double load = 1, prescribed = 1, prescribed_step = 0;
  };
  InvertedElement assemble_newton(const std::vector<size_t>& which, const std::vector<size_t>& tangent,
                                  const std::vector<Eigen::VectorXd>& u_free, Factors at, BlockSystem& sys);
  /// The time of the step the next assemblies are for [s] (a rate-dependent material's Δt; 0: no time).
  void set_step_time(double dt) {
    for (IntegrationState& s : states_) s.dt = dt;
    forget_point_updates();
  }
  /// Threads for each group's element kernels (fem/Assembler: the result does not depend on the count).
  void set_threads(int threads) { threads_ = threads; }
  /// The groups whose tangents this process assembles (default: all). Under `petsc` every MPI rank runs the Newton
  /// driver with every group's residual and state (so every rank takes the same decisions and rank 0 can write every
  /// body's fields) but assembles the tangent of its own subdomain only (SolverStrategy::local_groups): the others'
  /// K_g stay as they were, unused there. tangent_evaluations() still counts a tangent asked for on any rank.
  void set_local(const std::vector<size_t>& groups);
  /// True when group g's tangent does not depend on its displacement (a material without state, small strain):
  /// assembled once, it never needs re-assembly.
  bool constant_tangent(size_t g) const {
    return states_[g].per_element == 0 && sources_[g].body->kinematics == Kinematics::Small;
  }
  /// Every group's trial state becomes its committed state (an increment converged).
  void commit();
  /// The committed state of the `elements` elements of body `body`, gathered from its groups (element-major;
  /// empty for a material without state).
  std::vector<double> committed_state(int body, int elements) const;
  /// Sets the committed (and trial) state of body `body` from `all` (element-major, as committed_state gives it): a
  /// staggered field, such as the points' temperatures after the heat step, written back between steps.
  void set_committed_state(int body, const std::vector<double>& all);
  /// Frees the kept assemblers (a linear analysis assembles once: their patterns would only add to its peak memory).
  void release_assemblers() { assemblers_.clear(); }
  /// Tangent evaluations per group so far (assemble and assemble_newton with K).
  const std::vector<long>& tangent_evaluations() const { return evaluations_; }

 private:
  /// A finite-strain group's kernel after a tangent: the geometric modes of the displaced body, cut to those its
  /// tangent maps to zero when that tangent was assembled here (model/RigidModes' stiffness_kernel).
  static void follow_kernel(Group& group, const GroupSource& src, const Eigen::VectorXd& u, bool tangent_here);
  /// Adds the follower pressures of group g at displacement u, times `factor`, to its residual f and, when K is
  /// given, their load stiffness −factor ∂f/∂u, symmetrized as the element tangents are (the solvers factor a
  /// symmetric K; Abaqus does the same unless told UNSYMM).
  void add_follower_pressures(size_t g, const Eigen::VectorXd& u, double factor, Eigen::VectorXd& f,
                              SparseMatrix* K) const;
  /// Group g's Assembler (sparsity pattern and scatter map), built on first use and kept: a Newton iteration then
  /// writes values only (the pattern was a third of an assembly of the 16³ cube, rebuilt at every iteration).
  const Assembler& assembler(size_t g) const;

  std::vector<GroupSource> sources_;
  std::vector<IntegrationState> states_;
  void forget_point_updates() { std::fill(memo_ready_.begin(), memo_ready_.end(), 0); }

  std::vector<char> local_;  // per group: its tangent is assembled here (empty: every group's)
  // per group: its assembler's kept point updates (PointMemo) are those of its last assembly, under its state as it is
  std::vector<char> memo_ready_;
  int threads_ = 1;
  mutable std::vector<long> evaluations_;
  mutable std::vector<std::unique_ptr<Assembler>> assemblers_;  // per group, built by assembler(g)
};

/// Every group index of a system, ascending.
std::vector<size_t> all_groups(const BlockSystem& sys);

}  // namespace rollsim
