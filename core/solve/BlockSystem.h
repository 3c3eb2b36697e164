#pragma once
// The block structure every solver strategy works on (DESIGN.md): groups, each with its own
// free dofs, stiffness K_g and load f_g. Constraint blocks (contact C_j, subdomain glue B_i)
// join this structure with the contact and FETI strategies.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "solve/Factorization.h"

namespace rollsim {

struct Group {
  std::string name;
  int body = 0;
  SparseMatrix K;     // free-free stiffness, both triangles stored
  Eigen::VectorXd f;  // external load plus the load of prescribed dofs
};

struct BlockSystem {
  std::vector<Group> groups;
  long num_dofs() const {
    long n = 0;
    for (const Group& g : groups) n += g.K.rows();
    return n;
  }
};

}  // namespace rollsim
