// The consistent linearisation of slipping Coulomb friction: a slipping point's friction force μ N = −μ λ_n along its
// friction direction d enters the equations through its normal row's multiplier — terms μ d on the slave node and
// −μ N_k d on the master nodes — and leaves the loads; a sticking point, or one whose force the shear cap fixes, has
// no such terms and keeps its load.
#include <gtest/gtest.h>

#include <filesystem>

#include "contact/Friction.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

namespace test_slip_coupling {

using namespace rollsim;

namespace {
struct CoulombPair {
  Model model;
  std::vector<PairState> pairs;
  size_t slipping = 0, sticking = 1;
  Eigen::Vector3d d{1, 0, 0};  // the slipping point's friction direction (the pair's tangent in the x-y plane)
};

CoulombPair coulomb_pair(double shear_limit) {
  CoulombPair s{
      build_model(load_project(std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples" / "cylinder-indent-2d.json")), {}};
  ContactPair& p = s.model.contacts.at(0);
  p.kind = ContactKind::Coulomb;
  p.friction = 0.3;
  p.shear_limit = shear_limit;
  s.pairs = search_contacts(s.model);
  PairState& st = s.pairs.at(0);
  EXPECT_GE(st.points.size(), 2u);
  for (size_t j = 0; j < st.points.size(); ++j) st.active[j] = j <= 1;
  s.d = st.points[s.slipping].tangent[0];
  st.slip[s.slipping] = 1, st.friction_dir[s.slipping] = s.d, st.normal_force[s.slipping] = 10.0;
  st.slip[s.sticking] = 0, st.normal_force[s.sticking] = 5.0;
  return s;
}
}  // namespace

TEST(SlipCoupling, TheSlippingPointsNormalRowCarriesMuTimesItsFrictionDirection) {
  CoulombPair s = coulomb_pair(0.0);
  const std::vector<ConstraintRow> rows = contact_rows(s.model, s.pairs);
  const std::vector<ConstraintRow> extra = slip_coupling(s.model, s.pairs, rows);
  ASSERT_EQ(extra.size(), rows.size());
  const ContactPoint& c = s.pairs[0].points[s.slipping];
  int coupled = 0;
  for (size_t r = 0; r < rows.size(); ++r) {
    if (rows[r].point != static_cast<int>(s.slipping) || rows[r].comp >= 0) {
      EXPECT_TRUE(extra[r].terms.empty()) << "row " << r;
      continue;
    }
    ++coupled;
    Eigen::Vector3d on_slave = Eigen::Vector3d::Zero(), on_master = Eigen::Vector3d::Zero();
    for (const ConstraintTerm& t : extra[r].terms)
      (t.body == s.model.contacts[0].slave_body && t.node == c.slave_node ? on_slave : on_master)[t.comp] += t.coef;
    EXPECT_LT((on_slave - 0.3 * s.d).norm(), 1e-14);
    EXPECT_LT((on_master + 0.3 * s.d).norm(), 1e-14);  // Σ N_k = 1
  }
  EXPECT_EQ(coupled, 1);
  // the loads: its force is in the matrix now, so only `All` counts it (the reactions' view)
  const auto all = friction_loads(s.model, s.pairs, FrictionLoads::All);
  const auto capped = friction_loads(s.model, s.pairs, FrictionLoads::Capped);
  const int dim = s.model.dim, slave = s.model.contacts[0].slave_body;
  EXPECT_NEAR(all[slave][c.slave_node * dim], 0.3 * 10.0 * s.d[0], 1e-12);
  EXPECT_EQ(capped[slave].cwiseAbs().maxCoeff(), 0.0);
}

TEST(SlipCoupling, AForceTheShearCapFixesStaysALoad) {
  CoulombPair s = coulomb_pair(1e-9);  // μ N far above the cap × the tributary length
  const std::vector<ConstraintRow> rows = contact_rows(s.model, s.pairs);
  for (const ConstraintRow& r : slip_coupling(s.model, s.pairs, rows)) EXPECT_TRUE(r.terms.empty());
  EXPECT_FALSE(slip_moves_with_normal(s.model.contacts[0], s.pairs[0], s.slipping));
  const auto capped = friction_loads(s.model, s.pairs, FrictionLoads::Capped);
  EXPECT_GT(capped[s.model.contacts[0].slave_body].cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace test_slip_coupling
