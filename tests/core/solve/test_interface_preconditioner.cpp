// The FETI preconditioners of the interface (solve/InterfacePreconditioner): a contact row is preconditioned by the
// groups of the body its block names (the slave's), the other side entering at a tenth, a node shared by subdomains
// with their stiffness together; a row no body claims takes every group it touches in full. Checked on the lumped
// preconditioner, whose blocks are K_bb: M⁻¹ e_r is then Σ_g w_g² (C_g K_bb C_gᵀ)_rr exactly.
#include <gtest/gtest.h>

#include "solve/InterfacePreconditioner.h"

namespace test_interface_preconditioner {

using namespace rollsim;

namespace {
/// A group of body `body` with stiffness diag(k, 1) and one constraint row on its dof 0 with coefficient `coef`.
Group group(int body, double k, double coef) {
  Group g;
  g.name = "body " + std::to_string(body);
  g.body = body;
  g.K.resize(2, 2);
  g.K.insert(0, 0) = k;
  g.K.insert(1, 1) = 1.0;
  g.K.makeCompressed();
  g.f = Eigen::VectorXd::Zero(2);
  g.C.resize(1, 2);
  g.C.insert(0, 0) = coef;
  g.C.makeCompressed();
  g.R.resize(2, 0);
  return g;
}

/// A slave body 0 (stiffness 3 at the row's dof) against a master body 1 (stiffness 50): one contact row u_s − u_m.
BlockSystem contact_pair(std::vector<int> preconditioned_by) {
  BlockSystem sys;
  sys.groups = {group(0, 3.0, 1.0), group(1, 50.0, -1.0)};
  sys.d = Eigen::VectorXd::Zero(1);
  ConstraintBlock contact;
  contact.kind = ConstraintKind::Contact;
  contact.begin = 0, contact.end = 1;
  contact.preconditioned_by = std::move(preconditioned_by);
  sys.blocks = {contact};
  return sys;
}

double apply_to_the_row(const BlockSystem& sys) {
  const auto M = make_interface_preconditioner(Preconditioner::Lumped);
  M->setup(sys);
  return M->apply(sys, Eigen::VectorXd::Ones(1))[0];
}
}  // namespace

TEST(InterfacePreconditioner, AContactRowIsPreconditionedByItsSlaveSideTheMasterAtATenth) {
  // the slave's 3, the master's 50 weighted by 0.1² (w C K_bb Cᵀ w)
  EXPECT_DOUBLE_EQ(apply_to_the_row(contact_pair({0})), 3.0 + 0.01 * 50.0);
  // the row claimed by the other body: the roles swap
  EXPECT_DOUBLE_EQ(apply_to_the_row(contact_pair({1})), 0.01 * 3.0 + 50.0);
}

TEST(InterfacePreconditioner, ARowOnANodeTwoSubdomainsShareWeighsTheirStiffnessTogether) {
  // the slave node in two subdomains of body 0 (stiffness 3 and 5 there), each copy holding half of the row
  BlockSystem sys = contact_pair({0});
  sys.groups = {group(0, 3.0, 0.5), group(0, 5.0, 0.5), group(1, 50.0, -1.0)};
  EXPECT_DOUBLE_EQ(apply_to_the_row(sys), 3.0 + 5.0 + 0.01 * 50.0);
}

TEST(InterfacePreconditioner, ARowNoBodyClaimsTakesEveryGroupInFull) {
  EXPECT_DOUBLE_EQ(apply_to_the_row(contact_pair({})), 3.0 + 50.0);
}

}  // namespace test_interface_preconditioner
