// The rolling process section: the paper's pass generates a slab and a roll whose surfaces meet at the entry of
// the bite (gap within the roll polygon's chord sagitta), half thickness (and half width in 3D) by symmetry;
// bad process values are refused with their JSON path.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/ContactConstraints.h"
#include "project/ModelBuilder.h"
#include "project/Project.h"

using namespace rollsim;

namespace {
Model rolling(int dim) {
  json j = {{"dimension", dim}, {"process", {{"type", "rolling"}}}};
  return build_model(parse_project(j.dump(), "rolling"));
}
}  // namespace

TEST(RollingProcess, GeneratesSlabAndRollThatMeetAtTheBite) {
  for (const int dim : {2, 3}) {
    SCOPED_TRACE(dim);
    const Model m = rolling(dim);
    ASSERT_EQ(m.bodies.size(), 2u);
    EXPECT_EQ(m.bodies[0].name, "slab");
    EXPECT_EQ(m.bodies[1].name, "roll");
    ASSERT_EQ(m.contacts.size(), 1u);
    const auto pairs = search_contacts(m);
    double gap = 1e300;
    for (const ContactPoint& c : pairs[0].points) gap = std::min(gap, c.gap);
    // the slab's front top edge lies on the circle; the mesh's chords pass inside it by R (1 − cos(π/n))
    const double sagitta = 300 * (1 - std::cos(M_PI / 120));
    EXPECT_GE(gap, -1e-9);
    EXPECT_LE(gap, sagitta + 1e-9);
    // half thickness 50 mm; the roll's lowest point at the exit half thickness 43.4 mm
    double top = -1e300, roll_bottom = 1e300;
    const int up = dim == 2 ? 1 : 2;
    for (const auto& x : m.bodies[0].mesh.nodes) top = std::max(top, x[up]);
    for (const auto& x : m.bodies[1].mesh.nodes) roll_bottom = std::min(roll_bottom, x[up]);
    EXPECT_NEAR(top, 50.0, 1e-9);
    EXPECT_NEAR(roll_bottom, 43.4, 1e-9);
  }
}

TEST(RollingProcess, BadValuesNameTheirPath) {
  json j = {{"dimension", 2}, {"process", {{"reduction", 1.5}}}};
  try {
    parse_project(j.dump(), "bad");
    FAIL() << "accepted";
  } catch (const ProjectError& e) {
    EXPECT_NE(std::string(e.what()).find("process.reduction"), std::string::npos) << e.what();
  }
  json none = {{"dimension", 2}};
  try {
    parse_project(none.dump(), "empty");
    FAIL() << "accepted";
  } catch (const ProjectError& e) {
    EXPECT_NE(std::string(e.what()).find("no body: give `bodies` or a `process`"), std::string::npos) << e.what();
  }
}

TEST(RollingProcess, SlabPartitionBySpecOrPaintedMap) {
  json j = {{"dimension", 2}, {"process", {{"type", "rolling"}, {"slab_nx", 4}, {"slab_nt", 2}}}};
  j["process"]["slab_partition"] = "2x1";
  const Model sliced = build_model(parse_project(j.dump(), "rolling"));
  ASSERT_EQ(sliced.bodies[0].partition.num_subdomains, 2);
  j["process"].erase("slab_partition");
  j["process"]["slab_partition_map"] = sliced.bodies[0].partition.element_subdomain;
  const Model painted = build_model(parse_project(j.dump(), "rolling"));
  EXPECT_EQ(painted.bodies[0].partition.element_subdomain, sliced.bodies[0].partition.element_subdomain);
  EXPECT_EQ(painted.bodies[1].partition.num_subdomains, 1);  // the roll stays one domain
}
