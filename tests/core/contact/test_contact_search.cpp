// The contact search on a convex master: a slave node in a vertex's region — under the roll's lowest node, where
// neither neighbouring segment's own projection reaches — is found at that vertex (it used to drop out of contact);
// a node beyond the end of an open master surface is still ignored; a node on a vertex two segments share gets the
// same segment whichever side of the vertex round-off puts it (the 3D pass converged to two states 3.4e-5 apart when
// a node on a roll edge took either facet). Restricting the candidate facets to those whose
// bounding box is within reach (FacetCandidates::Boxes) finds the same points as projecting on every facet, on these
// cases and on every sample's contact pairs.
#include <gtest/gtest.h>

#include <filesystem>

#include "contact/ContactSearch.h"
#include "mesh/Annulus.h"
#include "mesh/StructuredBlock.h"
#include "project/ModelBuilder.h"

namespace test_contact_search {

using namespace rollsim;

namespace {
Mesh slab_under(double top, double shift = 0) {
  BlockSpec s;
  s.n = {2, 1, 1};
  s.size = {1.0, 1.0, 1.0};
  s.origin = {-0.5 + shift, top - 1.0, 0.0};
  return make_block(s);
}
}  // namespace

TEST(ContactSearch, ANodeInAConvexVertexRegionIsFoundAtTheVertex) {
  AnnulusSpec ring;
  ring.cx = 0, ring.cy = 10, ring.inner_radius = 2, ring.outer_radius = 5, ring.n_radial = 1, ring.n_around = 24;
  const Mesh roll = make_annulus(ring);
  const Mesh slab = slab_under(4.9);  // its top's middle node right under the lowest vertex (0, 5), 0.1 below
  const auto points = find_contact_points(slab, slab.surfaces.at("ymax"), roll, roll.surfaces.at("outer"), 1.0);
  ASSERT_EQ(points.size(), 3u);
  bool middle = false;
  for (const ContactPoint& c : points) {
    if (slab.nodes[static_cast<size_t>(c.slave_node)][0] != 0.0) continue;
    middle = true;
    double at_vertex = 0;
    for (size_t k = 0; k < c.master_nodes.size(); ++k) {
      const auto& X = roll.nodes[static_cast<size_t>(c.master_nodes[k])];
      if (std::abs(X[0]) < 1e-12 && std::abs(X[1] - 5.0) < 1e-12) at_vertex = c.N[k];
    }
    EXPECT_DOUBLE_EQ(at_vertex, 1.0);
    EXPECT_GT(c.gap, 0.099);  // 0.1 along a normal tilted by half a segment's 15°
    EXPECT_LE(c.gap, 0.1 + 1e-12);
  }
  EXPECT_TRUE(middle);
}

TEST(ContactSearch, ANodeBeyondTheEndOfAnOpenMasterIsIgnored) {
  AnnulusSpec quarter;  // a quarter ring ending at its lowest point: (0, 5) ends the surface
  quarter.cx = 0, quarter.cy = 10, quarter.inner_radius = 2, quarter.outer_radius = 5, quarter.n_radial = 1;
  quarter.n_around = 6, quarter.theta0 = 180, quarter.theta1 = 270;
  const Mesh roll = make_annulus(quarter);
  const Mesh slab = slab_under(4.9);
  const auto points = find_contact_points(slab, slab.surfaces.at("ymax"), roll, roll.surfaces.at("outer"), 1.0);
  for (const ContactPoint& c : points) EXPECT_LT(slab.nodes[static_cast<size_t>(c.slave_node)][0], 0.0);
}

namespace {
void expect_same_points(const std::vector<ContactPoint>& a, const std::vector<ContactPoint>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].slave_node, b[i].slave_node);
    EXPECT_EQ(a[i].master_nodes, b[i].master_nodes);
    EXPECT_EQ(a[i].N, b[i].N);
    EXPECT_EQ(a[i].gap, b[i].gap);
  }
}
}  // namespace

TEST(ContactSearch, BoundingBoxesFindWhatTheExhaustiveSearchFinds) {
  AnnulusSpec ring;
  ring.cx = 0, ring.cy = 10, ring.inner_radius = 2, ring.outer_radius = 5, ring.n_radial = 1, ring.n_around = 24;
  const Mesh roll = make_annulus(ring);
  for (const double top : {4.9, 5.0, 5.5, 7.0}) {
    const Mesh slab = slab_under(top);
    const auto& ss = slab.surfaces.at("ymax");
    const auto& ms = roll.surfaces.at("outer");
    expect_same_points(find_contact_points(slab, ss, roll, ms, 1.0, FacetCandidates::Boxes),
                       find_contact_points(slab, ss, roll, ms, 1.0, FacetCandidates::All));
  }
}

TEST(ContactSearch, BoundingBoxesFindTheSamePointsOnEverySamplesPairs) {
  const std::filesystem::path samples = std::filesystem::path(ROLLSIM_SOURCE_DIR) / "samples";
  int pairs = 0;
  for (const char* name : {"block-indent-2d-50x30", "block-indent-3d-10x6x4", "cylinder-indent-2d",
                           "cylinder-plastic-3d", "block-plastic-3d", "rolling-2d-36x6", "rolling-3d-16x8x4"}) {
    SCOPED_TRACE(name);
    const Model m = build_model(load_project(samples / (std::string(name) + ".json")));
    for (const ContactPair& p : m.contacts) {
      const Mesh& slave = m.bodies[static_cast<size_t>(p.slave_body)].mesh;
      const Mesh& master = m.bodies[static_cast<size_t>(p.master_body)].mesh;
      const auto& ss = slave.surfaces.at(p.slave_surface);
      const auto& ms = master.surfaces.at(p.master_surface);
      const auto boxes = find_contact_points(slave, ss, master, ms, p.search_distance, FacetCandidates::Boxes);
      EXPECT_FALSE(boxes.empty());
      expect_same_points(boxes, find_contact_points(slave, ss, master, ms, p.search_distance, FacetCandidates::All));
      ++pairs;
    }
  }
  EXPECT_EQ(pairs, 7);
}

TEST(ContactSearch, ANodeOnAVertexGetsTheSameSegmentOnEitherSideOfItsRoundOff) {
  AnnulusSpec ring;
  ring.cx = 0, ring.cy = 10, ring.inner_radius = 2, ring.outer_radius = 5, ring.n_radial = 1, ring.n_around = 24;
  const Mesh roll = make_annulus(ring);
  std::vector<std::vector<int>> masters;
  for (double shift : {-1e-13, 1e-13}) {  // the slab's middle top node on the lowest vertex (0, 5), a hair left, right
    const Mesh slab = slab_under(5.0, shift);
    for (const ContactPoint& c :
         find_contact_points(slab, slab.surfaces.at("ymax"), roll, roll.surfaces.at("outer"), 1.0))
      if (std::abs(slab.nodes[static_cast<size_t>(c.slave_node)][0]) < 1e-12) masters.push_back(c.master_nodes);
  }
  ASSERT_EQ(masters.size(), 2u);
  EXPECT_EQ(masters[0], masters[1]);
}

}  // namespace test_contact_search
