#pragma once
// The block structure every solver strategy works on (DESIGN.md): groups, each with its own
// free dofs, stiffness K_g, load f_g, constraint block C_g and kernel R_g, joined by the
// multipliers λ of all constraints (contact C_j, subdomain glue B_i) — paper eq. (1):
//   K_g u_g + C_gᵀ λ = f_g  (every g),   Σ_g C_g u_g = d.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "solve/Factorization.h"
#include "solve/RunStatus.h"

namespace rollsim {

struct Group {
  std::string name;
  int body = 0;
  SparseMatrix K;     // free-free stiffness, both triangles stored
  Eigen::VectorXd f;  // external load plus the load of prescribed dofs
  SparseMatrix C;     // multipliers × free dofs of this group (paper's C_j / B_i); 0 × n without constraints
  long version = 0;   // bumped by mark_updated (solve/UpdatePolicy) when K is re-assembled: strategies refactor
                      // a group only then
  Eigen::MatrixXd R;  // basis of ker K_g (rigid modes left free by the supports); n × 0 when K_g is regular
};

struct BlockSystem {
  std::vector<Group> groups;
  Eigen::VectorXd d;        // right-hand side of the constraints, one entry per multiplier
  Eigen::VectorXd scaling;  // per multiplier, for preconditioners: 1/multiplicity on subdomain glue (empty: ones)
  long glue_begin = 0, glue_end = 0;  // the rows gluing subdomains (B_i), for the preconditioners' scaling
  bool glue_redundant = false;        // fully redundant glue: diagonal scaling; otherwise (B Bᵀ)⁻¹

  long num_dofs() const {
    long n = 0;
    for (const Group& g : groups) n += g.K.rows();
    return n;
  }
  long num_multipliers() const { return d.size(); }
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
