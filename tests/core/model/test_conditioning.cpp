// Models whose answer double precision cannot carry are warned about (model/Conditioning): Young's moduli many
// decades apart, and nearly incompressible bodies under full integration (they lock); ordinary models are not.
#include <gtest/gtest.h>

#include "model/Conditioning.h"

namespace test_conditioning {

using namespace rollsim;

namespace {
Body body(const std::string& name, double E, double nu, Formulation f = Formulation::Full) {
  Body b;
  b.name = name;
  b.material.E = E;
  b.material.nu = nu;
  b.formulation = f;
  return b;
}
}  // namespace

TEST(Conditioning, ModuliFifteenDecadesApartAreWarnedAbout) {
  Model m;
  m.bodies = {body("soft", 1e5, 0.3), body("stiff", 1e20, 0.3)};
  const auto w = conditioning_warnings(m);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("ratio of 1e+15"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("'stiff'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("about 1 significant digits"), std::string::npos) << w[0];
}

TEST(Conditioning, NearIncompressibilityUnderFullIntegrationIsWarnedAbout) {
  Model m;
  m.bodies = {body("rubber", 10, 0.4999999), body("bbar", 10, 0.4999999, Formulation::BBar)};
  const auto w = conditioning_warnings(m);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("body 'rubber'"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("\"bbar\""), std::string::npos) << w[0];
}

TEST(Conditioning, TheRollingPassIsNotWarnedAbout) {
  Model m;  // the main job: steel roll and hot slab, ν 0.3, the slab under F-bar
  m.bodies = {body("slab", 1e5, 0.3, Formulation::BBar), body("roll", 2.1e5, 0.3)};
  EXPECT_TRUE(conditioning_warnings(m).empty());
}

}  // namespace test_conditioning
