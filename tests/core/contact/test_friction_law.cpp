// Coulomb's law as update_friction applies it to a slipping point (contact/Friction.h): its friction force points
// along its trial force δ d₀ − v_t — the direction where the step began while the slip is small against the elastic
// slip δ, against the slip once it is large — and a slip back along the force by less than 2δ puts the trial force
// inside the cone: the point sticks where the step began, once per step.
#include <gtest/gtest.h>

#include <algorithm>

#include "../../common/SlippingBlock.h"
#include "contact/Friction.h"

namespace test_friction_law {

using namespace rollsim;
using testing_support::Slipping;
using testing_support::slipping;

namespace {
const Eigen::Vector3d kStartDirection(0.6, 0.8, 0.0);

/// The block on its base, every point slipping along kStartDirection where the step began.
Slipping slipping_along_start_direction() {
  Slipping s = slipping(3);
  for (Eigen::Vector3d& d0 : s.pairs[0].start_direction) d0 = kStartDirection;
  return s;
}

/// The block moved rigidly by `shift` over the step, its base at rest.
std::vector<Eigen::VectorXd> block_moved(const Slipping& s, const Eigen::Vector3d& shift) {
  std::vector<Eigen::VectorXd> u = s.start;
  const int block = s.model.contacts[0].slave_body;
  for (Eigen::Index i = 0; i < u[block].size(); ++i) u[block][i] = shift[i % 3];
  return u;
}

/// The tangential slip of point j over the step from s.start to u.
Eigen::Vector3d slip(const Slipping& s, size_t j, const std::vector<Eigen::VectorXd>& u) {
  const ContactPair& p = s.model.contacts[0];
  const ContactPoint& c = s.pairs[0].points[j];
  const Eigen::Vector3d v = relative_position(p, c, u, 3) - relative_position(p, c, s.start, 3);
  return v - v.dot(c.normal) * c.normal;
}

std::pair<double, double> elastic_slip_range(const Slipping& s) {
  double lo = 1e300, hi = 0;
  for (const ContactPoint& c : s.pairs[0].points) {
    lo = std::min(lo, elastic_slip(s.model.contacts[0], c, 3));
    hi = std::max(hi, elastic_slip(s.model.contacts[0], c, 3));
  }
  return {lo, hi};
}
}  // namespace

TEST(FrictionLaw, ASlipSmallAgainstTheElasticSlipKeepsTheDirectionWhereTheStepBegan) {
  Slipping s = slipping_along_start_direction();
  for (Eigen::VectorXd& u : s.u) u *= 1e-4;  // slips of 1e-6 against δ of 1e-3
  ASSERT_EQ(update_friction(s.model, s.rows, s.lambda, s.u, s.start, s.pairs), 0);
  for (size_t j = 0; j < s.pairs[0].points.size(); ++j) {
    EXPECT_GT(friction_direction(s.pairs[0], j).dot(kStartDirection), 1 - 1e-4) << "point " << j;
    EXPECT_LT(friction_direction(s.pairs[0], j).dot(-slip(s, j, s.u).normalized()), 0.999) << "point " << j;
  }
}

TEST(FrictionLaw, ASlipLargeAgainstTheElasticSlipOpposesTheFrictionForce) {
  Slipping s = slipping_along_start_direction();
  for (Eigen::VectorXd& u : s.u) u *= 100;  // slips of 1 against δ of 1e-3
  ASSERT_EQ(update_friction(s.model, s.rows, s.lambda, s.u, s.start, s.pairs), 0);
  for (size_t j = 0; j < s.pairs[0].points.size(); ++j)
    EXPECT_GT(friction_direction(s.pairs[0], j).dot(-slip(s, j, s.u).normalized()), 1 - 1e-4) << "point " << j;
}

TEST(FrictionLaw, ASlipBackByLessThanTwiceTheElasticSlipSticksOncePerStep) {
  Slipping s = slipping_along_start_direction();
  const auto [lo, hi] = elastic_slip_range(s);
  ASSERT_LT(hi, 2 * lo * (1 + 1e-12));  // the facets' sizes within a factor 2
  const size_t n = s.pairs[0].points.size();
  // along the force (against the slip before) by 1.5 δ: the trial force (δ − 1.5 δ) d₀ is inside the cone
  const std::vector<Eigen::VectorXd> back = block_moved(s, 1.5 * lo * kStartDirection);
  std::vector<PairState> once = s.pairs;
  std::fill(once[0].switches.begin(), once[0].switches.end(), 0);
  EXPECT_EQ(update_friction(s.model, s.rows, s.lambda, back, s.start, once), static_cast<int>(n));
  EXPECT_TRUE(std::none_of(once[0].slip.begin(), once[0].slip.end(), [](char c) { return c; }));
  // a point that has used its return slips on, along its trial force
  std::vector<PairState> again = s.pairs;
  EXPECT_EQ(update_friction(s.model, s.rows, s.lambda, back, s.start, again), 0);
  // by 2.5 δ: the trial force turns over, and the point slips the other way
  std::vector<PairState> over = s.pairs;
  std::fill(over[0].switches.begin(), over[0].switches.end(), 0);
  EXPECT_EQ(update_friction(s.model, s.rows, s.lambda, block_moved(s, 2.5 * hi * kStartDirection), s.start, over), 0);
  for (size_t j = 0; j < n; ++j) EXPECT_NEAR(friction_direction(over[0], j).dot(kStartDirection), -1, 1e-12);
}

}  // namespace test_friction_law
