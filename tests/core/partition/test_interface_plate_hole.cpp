// Paper Example 3 (Tables VI, VII): the quarter plate with a hole in 2 and 4 subdomains. The paper's figure of
// the partitions is lost; its counts fix them. 2 subdomains: one floating with 1 rigid mode; 4: three floating
// with 1, 2 and 1 modes; multipliers 142 and 426 = 3 × 142, so the 4-subdomain cuts are three disjoint lines of
// equal length with no crosspoint. Angular sectors along the mesh's own lines from the hole to the outer edges do
// all of it: cut at the hole's 45° point (the line to the corner (W, H)) for 2, and at 22.5°, 45°, 67.5° for 4.
//   sector  0°–22.5°: on the symmetry line y = 0 (u_y = 0 along a line)      -> 1 mode (x translation)
//   sector 22.5°–45°: touches the supports at the corner node only (u_y given) -> 2 modes
//   sector 45°–67.5°: on the loaded edge y = H (u_y given along a line)       -> 1 mode
//   sector 67.5°–90°: on x = 0 and y = H                                      -> held
// A cut line has n_radial + 1 nodes: the paper's 142 = 71 × 2 means n_radial = 70 (the sample uses 24).
#include <gtest/gtest.h>

#include <cmath>

#include "PartitionFixtures.h"
#include "mesh/PlateWithHole.h"

namespace test_interface_plate_hole {

using namespace rollsim;

namespace {
/// Sector of every element: how many of the mesh lines j ∈ cuts (hole point at angle j·90°/n_around joined to
/// the outer edge point of the generator, mesh/PlateWithHole.h) lie clockwise of its centroid.
Partition sectors(const Mesh& mesh, const PlateWithHoleSpec& spec, const std::vector<int>& cuts) {
  Partition p;
  p.num_subdomains = static_cast<int>(cuts.size()) + 1;
  p.description = "explicit";
  const double half = spec.n_around / 2.0;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    double cx = 0, cy = 0;
    for (int k = 0; k < 4; ++k) {
      cx += mesh.nodes[mesh.element(e)[k]][0] / 4;
      cy += mesh.nodes[mesh.element(e)[k]][1] / 4;
    }
    int s = 0;
    for (int j : cuts) {
      const double t = M_PI / 2 * j / spec.n_around;
      const double px = spec.hole_radius * std::cos(t), py = spec.hole_radius * std::sin(t);
      const double qx = j <= half ? spec.half_width : spec.half_width * (spec.n_around - j) / half;
      const double qy = j <= half ? spec.half_height * j / half : spec.half_height;
      s += (qx - px) * (cy - py) - (qy - py) * (cx - px) > 0 ? 1 : 0;
    }
    p.element_subdomain.push_back(s);
  }
  return p;
}

PlateWithHoleSpec sample_spec() {  // samples/plate-hole-2d.json
  PlateWithHoleSpec spec;
  spec.half_width = spec.half_height = 4.0;
  spec.hole_radius = 1.0;
  spec.n_around = 32;
  spec.n_radial = 24;
  spec.grading = 1.06;
  return spec;
}
}  // namespace

TEST(PlateHoleInterface, FloatingSubdomainsOfTheSample) {
  const Model model = test::sample_model("plate-hole-2d");
  const Mesh& mesh = model.bodies[0].mesh;
  const PlateWithHoleSpec spec = sample_spec();
  const BodyDecomposition two = decompose_body(model, 0, sectors(mesh, spec, {16}));
  EXPECT_EQ(test::modes_per_group(two), (std::vector<int>{1, 0}));
  const BodyDecomposition four = decompose_body(model, 0, sectors(mesh, spec, {8, 16, 24}));
  EXPECT_EQ(test::modes_per_group(four), (std::vector<int>{1, 2, 1, 0}));
  for (const Subdomain& s : four.subdomains)  // the cuts are mesh lines: every sector has 8 × 24 elements
    EXPECT_EQ(s.body.mesh.num_elements(), spec.n_around / 4 * spec.n_radial);
  EXPECT_TRUE(four.warnings.empty());
  for (const Group& g : four.groups)
    if (g.R.cols() > 0) EXPECT_LE(Eigen::MatrixXd(g.K * g.R).norm(), 1e-12 * g.K.norm()) << g.name;
  // three disjoint cut lines of n_radial + 1 nodes; every dof counted: 3 × 25 × 2
  EXPECT_EQ(two.paper_convention_multipliers, 50);
  EXPECT_EQ(four.paper_convention_multipliers, 150);
  EXPECT_EQ(four.num_multipliers(), 148);  // u_y prescribed at the cuts' outer ends (W, H) and (W/2, H)
}

TEST(PlateHoleInterface, PaperMultiplierCountsWithSeventyRadialElements) {
  // Table VI: 142 (2 subdomains) and 426 (4) extra equations.
  PlateWithHoleSpec spec = sample_spec();
  spec.n_radial = 70;
  Model held = test::sample_model("plate-hole-2d");  // the sample's supports, on the finer mesh
  held.bodies[0].mesh = make_plate_with_hole(spec);
  held.displacements.clear();
  const Mesh& mesh = held.bodies[0].mesh;
  test::support(held, test::nodes_in_box(held, {0, 0, 0}, {0, 4, 0}), 0);
  test::support(held, test::nodes_in_box(held, {0, 0, 0}, {4, 0, 0}), 1);
  test::support(held, test::nodes_in_box(held, {0, 4, 0}, {4, 4, 0}), 1, 0.01);
  DecomposeOptions counting;
  counting.assemble = false;
  const BodyDecomposition two = decompose_body(held, 0, sectors(mesh, spec, {16}), counting);
  const BodyDecomposition four = decompose_body(held, 0, sectors(mesh, spec, {8, 16, 24}), counting);
  EXPECT_EQ(two.paper_convention_multipliers, 142);
  EXPECT_EQ(four.paper_convention_multipliers, 426);
  EXPECT_EQ(test::modes_per_group(two), (std::vector<int>{1, 0}));
  EXPECT_EQ(test::modes_per_group(four), (std::vector<int>{1, 2, 1, 0}));
}

}  // namespace test_interface_plate_hole
