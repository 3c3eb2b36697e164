#pragma once
// The block structure every solver strategy works on (DESIGN.md): groups, each with its own
// free dofs, stiffness K_g, load f_g, constraint block C_g and kernel R_g, joined by the
// multipliers λ of all constraints (contact C_j, subdomain glue B_i) — paper eq. (1):
//   K_g u_g + C_gᵀ λ = f_g  (every g),   Σ_g C_g u_g = d.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "base/RunStatus.h"
#include "solve/Factorization.h"

namespace rollsim {

/// Where a group's free dofs sit: each one's node coordinates and component, and the rigid-body modes there — for
/// strategies that hand the groups to a library needing geometry (petsc: rigid-body near-null space, corner
/// selection). Empty when not set.
struct DofGeometry {
  Eigen::MatrixXd x;          // free dofs × dim: the coordinates of each free dof's node
  Eigen::VectorXi component;  // per free dof: 0, 1 or 2
  Eigen::MatrixXd modes;      // free dofs × (3 | 6): the body's rigid modes (model/RigidModes, in the body's frame,
                              // supports ignored), so that subdomains sharing a dof have the same row for it
};

struct Group {
  std::string name;
  int body = 0;
  SparseMatrix K;     // free-free stiffness, both triangles stored
  Eigen::VectorXd f;  // external load plus the load of prescribed dofs
  SparseMatrix C;     // multipliers × free dofs of this group (paper's C_j / B_i); 0 × n without constraints
  // How the multipliers enter this group's equations, K_g u_g + C_eqᵀ λ = f_g, where that differs from C: a slipping
  // Coulomb point's friction force μ λ_n moves with its normal multiplier (contact/Friction slip_coupling), which
  // makes the system unsymmetric. Empty when it is C; only strategies that solve_unsymmetric() get one.
  SparseMatrix C_eq;
  // Compliant rows (BlockSystem::compliance) × free dofs: a stiffness that joins this group to another, written as
  // rows with multipliers of their own (the 3D friction direction's turn, contact/FrictionStiffness); 0 × n: none.
  SparseMatrix C_compliant;
  long version = 0;   // bumped by mark_updated (solve/UpdatePolicy) when K is re-assembled: strategies refactor
                      // a group only then
  Eigen::MatrixXd R;  // basis of ker K_g (rigid modes left free by the supports); n × 0 when K_g is regular
  DofGeometry geometry;

  /// The multipliers' block in this group's equations: C_eq when set, else C.
  const SparseMatrix& equation_C() const { return C_eq.rows() > 0 ? C_eq : C; }
};

/// The dofs a constraint block touches (C's columns that hold an entry), in increasing order: a group's interface.
inline std::vector<int> touched_dofs(const SparseMatrix& C) {
  std::vector<int> dofs;
  for (int j = 0; j < C.outerSize(); ++j)
    if (C.outerIndexPtr()[j + 1] > C.outerIndexPtr()[j]) dofs.push_back(j);
  return dofs;
}

/// What a range of multipliers stands for: contact rows (C_j) or the glue of a body's subdomains (B_i).
enum class ConstraintKind { Contact, Glue };

/// A contiguous range of the constraint rows with one meaning — what preconditioners treat differently.
struct ConstraintBlock {
  ConstraintKind kind = ConstraintKind::Contact;
  long begin = 0, end = 0;  // rows [begin, end) of every group's C and of d
  Eigen::VectorXd scaling;  // per row, for preconditioners: 1/multiplicity on glue (empty: ones)
  bool redundant = false;   // glue: fully redundant (diagonal scaling) or not ((B Bᵀ)⁻¹)
  // contact: per row, the body whose groups precondition it (the slave's, whose node the multiplier acts on; empty:
  // every group the row touches) — see InterfacePreconditioner
  std::vector<int> preconditioned_by;

  long size() const { return end - begin; }
};

/// An interface Krylov solve's stopping test (mixed, feti; petsc: its rtol): ‖Pᵀr_k‖ ≤ max(relative × ‖Pᵀr_0‖,
/// absolute), the projected residual being the constraint error its λ leaves. What an inexact Newton iteration asks of
/// its solve (analysis/ForcingSequence).
struct InterfaceTolerance {
  double relative = 0;  // 0: the strategy's solver.cg_tolerance
  double absolute = 0;  // 0: none
  // r_0 the residual at lambda_start (the last iteration's λ, whatever solver.interface_start says), not at the
  // least-norm start: λ is the total multiplier, so only the residual at the last λ is of the size of the correction
  // Newton asks for — the forcing term's reference (a loose tolerance of the least-norm start's residual undoes it)
  bool from_last = false;
  // And at most this on ‖Pᵀr_k‖ (0: no bound): the constraint accuracy Newton's check needs, reached whatever the
  // relative tolerance allows — a relative tolerance of a large first residual (the total multipliers') can leave
  // glue and contact rows unmet by more than the check accepts (a slab in 8 subdomains: 4.2e-7 against 2.0e-8).
  // The fixed forcing asks for it once the residual is balanced (analysis/ForcingSequence).
  double at_most = 0;
};

struct BlockSystem {
  std::vector<Group> groups;
  Eigen::VectorXd d;                    // right-hand side of the constraints, one entry per multiplier
  std::vector<ConstraintBlock> blocks;  // the rows' meaning, in row order (rows in no block: contact, weight 1)
  // The size of the terms d was computed from, when d is a difference (Newton: d = d_total − C u, the larger of
  // ‖d_total‖∞ and ‖C u‖∞): its accuracy is relative to this, not to d. 0: d is data (a linear analysis).
  double d_reference = 0;
  // Stiffness joining two groups (the contact's geometric stiffness between a slave and its master, analysis
  // `contact_tangent: full`): every group's free dofs one after the other; empty (0 × 0) when none. Only strategies
  // that assemble one global matrix (SolverStrategy::assembles_globally) take it; a change refactors that matrix.
  SparseMatrix coupling;
  // Per compliant row (the groups' C_compliant): 1/k of the stiffness k cᵀc it stands for, with c the row. The rows
  // come after every row of d, with multipliers μ that no caller sees: Σ_g C_compliant,g u_g − μ / k = 0, the groups'
  // equations K_g u_g + C_gᵀλ + C_compliant,gᵀ μ = f_g — so the groups' solution u is that of K + Σ k cᵀc. Empty:
  // none. Only strategies that solves_compliant() take them.
  Eigen::VectorXd compliance;
  // A guess of λ (the last Newton iteration's multipliers of the rows that stay, 0 for new rows) where iterative
  // strategies start their interface solve; empty: none (they start from the least-norm λ with Gᵀλ = e).
  Eigen::VectorXd lambda_start;
  // This solve's interface tolerance where a Newton driver sets one; {0, 0}: solver.cg_tolerance.
  InterfaceTolerance interface_tolerance;

  long num_dofs() const {
    long n = 0;
    for (const Group& g : groups) n += g.K.rows() > 0 ? g.K.rows() : g.C.cols();  // a group another process
    return n;                                                                     // assembles: its C's columns
  }
  long num_multipliers() const { return d.size(); }
  /// The glue block (subdomain interfaces), or null when no body is torn.
  const ConstraintBlock* glue() const {
    for (const ConstraintBlock& b : blocks)
      if (b.kind == ConstraintKind::Glue && b.size() > 0) return &b;
    return nullptr;
  }
  /// Every row's preconditioner weight: the blocks' scaling, 1 elsewhere.
  Eigen::VectorXd row_scaling() const {
    Eigen::VectorXd w = Eigen::VectorXd::Ones(num_multipliers());
    for (const ConstraintBlock& b : blocks)
      if (b.scaling.size() == b.size()) w.segment(b.begin, b.size()) = b.scaling;
    return w;
  }
  long num_rigid_modes() const {
    long n = 0;
    for (const Group& g : groups) n += g.R.cols();
    return n;
  }
};

/// Displacements of the free dofs per group and the multipliers.
struct BlockSolution {
  std::vector<Eigen::VectorXd> u;
  Eigen::VectorXd lambda;
  // converged; cancelled when an iterative solve stopped on the observer's request ((u, λ) is its last iterate);
  // not_converged when its CG stopped short of the tolerance ((u, λ) is then no solution)
  RunStatus status;
};

}  // namespace rollsim
