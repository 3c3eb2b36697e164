// One ALE step's advection (analysis/AleStep): the state of a mesh whose material moved on is carried back onto the
// mesh held in place — a constant field exactly, a step without a new extreme, virgin (zero) where material flowed in,
// and the inflow face holding the virgin state, which washes what stood at the entry out, a point's own part flowing on
// with its material — and a placement that would
// fold an element is refused with the body's name.
#include <gtest/gtest.h>

#include <algorithm>

#include "analysis/AleStep.h"
#include "analysis/AnalysisError.h"
#include "fem/SolidElement.h"
#include "mesh/StructuredBlock.h"

namespace test_ale_step {

using namespace rollsim;

namespace {
/// A 6 × 3 block on [0, 6] × [0, 3], its material moved on by `shift` along x and flowing in at x = 0.
struct Flow final : MeshMotion {
  explicit Flow(double s) : shift(s) {}
  int body() const override { return 0; }
  Positions placed(const std::vector<Positions>& current, const std::vector<char>&) const override {
    Positions back = current[0];
    for (auto& x : back) x[0] -= shift;
    return back;
  }
  bool inflow(const std::array<double, 3>& p, const Positions&) const override { return p[0] < shift; }
  std::string describe() const override { return "a block flowing along x"; }
  double shift;
};

Mesh block() {
  BlockSpec s;
  s.n = {6, 3, 1};
  s.size = {6.0, 3.0, 1.0};
  return make_block(s);
}

std::vector<Point3> moved(const Mesh& m, double shift) {
  std::vector<Point3> x = m.nodes;
  for (auto& p : x) p[0] += shift;
  return x;
}

constexpr int kPoints = SolidElement<2>::NGP;
}  // namespace

TEST(AleStep, AConstantFieldIsCarriedExactlyAndInflowIsVirgin) {
  const Mesh m = block();
  const Flow flow(0.3);
  const int width = 2;
  const std::vector<double> values(static_cast<size_t>(m.num_elements()) * kPoints * width, 0.7);
  const std::vector<double> out = advected_points(m, moved(m, flow.shift), values, width, m, flow);
  ASSERT_EQ(out.size(), values.size());
  int virgin = 0;
  for (double v : out) {
    EXPECT_TRUE(v == 0.7 || v == 0.0) << v;
    virgin += v == 0.0;
  }
  // the first column's points nearer the entry than the shift: x = 0.5 ∓ 0.5/√3 → only 0.211 < 0.3
  EXPECT_EQ(virgin, 3 * 2 * width);
}

TEST(AleStep, TheInflowFaceWashesTheFirstElementsOutToVirgin) {
  const Mesh m = block();
  struct Entry final : MeshMotion {  // Flow, with its entry face at x = 0 an inflow boundary
    explicit Entry(const Mesh& mesh) : flow(0.3) {
      for (int n = 0; n < mesh.num_nodes(); ++n)
        if (mesh.nodes[static_cast<size_t>(n)][0] == 0.0) face.push_back(n);
    }
    int body() const override { return 0; }
    Positions placed(const std::vector<Positions>& c, const std::vector<char>& t) const override {
      return flow.placed(c, t);
    }
    bool inflow(const std::array<double, 3>& p, const Positions& c) const override { return flow.inflow(p, c); }
    std::vector<int> inflow_face() const override { return face; }
    std::string describe() const override { return "a block flowing in at x = 0"; }
    Flow flow;
    std::vector<int> face;
  } entry(m);
  std::vector<double> values(static_cast<size_t>(m.num_elements()) * kPoints, 0.7);
  values = advected_points(m, moved(m, 0.3), values, 1, m, entry);
  for (int e = 0; e < m.num_elements(); ++e)
    for (int p = 0; p < kPoints; ++p) {
      const double v = values[static_cast<size_t>(e * kPoints + p)];
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, 0.7);
      if (e / 3 >= 2) EXPECT_EQ(v, 0.7) << "element " << e;  // beyond the face's reach (column e / 3): exactly
    }
  // the first column's points past the inflow take in virgin material: no longer the 0.7 that stood there
  EXPECT_LT(values[1], 0.7);
  for (int step = 1; step < 20; ++step) values = advected_points(m, moved(m, 0.3), values, 1, m, entry);
  // 6 units of travel, the block's length: what stood in it has flowed out, what is left near the entry is virgin
  for (int e = 0; e < 3; ++e)
    for (int p = 0; p < kPoints; ++p) EXPECT_LT(values[static_cast<size_t>(e * kPoints + p)], 0.05) << e;
}

TEST(AleStep, AStepIsCarriedWithoutANewExtreme) {
  const Mesh m = block();
  const Flow flow(0.4);
  std::vector<double> values;  // 1 in the three columns nearer the entry, 0 past them
  for (int e = 0; e < m.num_elements(); ++e)
    for (int p = 0; p < kPoints; ++p) values.push_back(e % 6 < 3 ? 1.0 : 0.0);
  std::vector<double> out = advected_points(m, moved(m, flow.shift), values, 1, m, flow);
  for (double v : out) {
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1.0);
  }
  // the step moved downstream: a point just past the old step (column 3) now holds some of the 1
  EXPECT_GT(out[static_cast<size_t>(3) * kPoints], 0.0);
  EXPECT_LT(*std::min_element(out.begin(), out.end()), 1e-12);
}

TEST(AleStep, APointsOwnPartLeavesWithItsMaterial) {
  // One point's value above a smooth field (zero): the part the continuous recovery does not hold must flow on with the
  // material as the rest does, not stay at the point while the material passes (a steady source there would pile up
  // step after step: the pass's force drifted down by 8 % over 150 mm in 2 mm steps)
  const Mesh m = block();
  const Flow flow(0.25);
  const size_t spike = static_cast<size_t>(1 * 6 + 1) * kPoints + 1;  // row 1, column 1, its downstream lower point
  std::vector<double> values(static_cast<size_t>(m.num_elements()) * kPoints, 0.0);
  values[spike] = 1.0;
  for (int step = 0; step < 8; ++step) values = advected_points(m, moved(m, flow.shift), values, 1, m, flow);
  // two elements of travel later the point holds little of it; what left is downstream (columns 2 to 4)
  EXPECT_LT(values[spike], 0.15);
  double downstream = 0;
  for (int e = 0; e < m.num_elements(); ++e)
    for (int p = 0; p < kPoints; ++p) {
      EXPECT_GE(values[static_cast<size_t>(e * kPoints + p)], 0.0);
      EXPECT_LE(values[static_cast<size_t>(e * kPoints + p)], 1.0);
      if (e % 6 >= 2 && e % 6 <= 4) downstream += values[static_cast<size_t>(e * kPoints + p)];
    }
  EXPECT_GT(downstream, values[spike]);
}

TEST(AleStep, APlacementThatFoldsAnElementIsRefusedNamingTheBody) {
  Body body;
  body.name = "slab";
  body.mesh = block();
  struct Fold final : MeshMotion {
    int body() const override { return 0; }
    Positions placed(const std::vector<Positions>& current, const std::vector<char>&) const override {
      Positions p = current[0];
      std::swap(p[0], p[1]);  // two nodes of the first element change places
      return p;
    }
    bool inflow(const std::array<double, 3>&, const Positions&) const override { return false; }
    std::string describe() const override { return "a fold"; }
  } fold;
  try {
    ale_remap(body, Eigen::VectorXd::Zero(2 * body.mesh.num_nodes()), {}, {body.mesh.nodes}, {}, fold);
    FAIL() << "accepted";
  } catch (const AnalysisError& e) {
    EXPECT_NE(std::string(e.what()).find("the mesh of body 'slab' put back in place would fold an element"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace test_ale_step
