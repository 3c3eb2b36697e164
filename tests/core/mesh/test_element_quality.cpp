// The element quality written as `jacobian_ratio` (mesh/ElementQuality): 1 under a rigid motion, the volume ratio
// under a uniform stretch, negative once an element has folded — in 2D and 3D.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/ElementQuality.h"

namespace test_element_quality {

using namespace rollsim;

namespace {
Mesh unit_element(int dim) {
  Mesh m;
  m.dim = dim;
  m.type = dim == 2 ? ElementType::Quad4 : ElementType::Hex8;
  m.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  if (dim == 3) m.nodes.insert(m.nodes.end(), {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}});
  for (int i = 0; i < static_cast<int>(m.nodes.size()); ++i) m.connectivity.push_back(i);
  return m;
}
/// Displacements taking each node x to f(x).
template <class F>
std::vector<double> moved(const Mesh& m, F f) {
  std::vector<double> u;
  for (const auto& x : m.nodes) {
    const auto y = f(x);
    for (int c = 0; c < m.dim; ++c) u.push_back(y[c] - x[c]);
  }
  return u;
}
}  // namespace

TEST(ElementQuality, RigidMotionIsOneStretchIsTheVolumeRatioFoldingIsNegative) {
  for (const int dim : {2, 3}) {
    SCOPED_TRACE(dim);
    const Mesh m = unit_element(dim);
    const double c = std::cos(0.7), s = std::sin(0.7);
    const auto turned = moved(m, [&](auto x) {
      return decltype(x){c * x[0] - s * x[1] + 3, s * x[0] + c * x[1], x[2]};
    });
    EXPECT_NEAR(corner_jacobian_ratio(m, turned.data(), 0), 1.0, 1e-12);
    const auto squeezed = moved(m, [](auto x) { return decltype(x){x[0], 0.5 * x[1], x[2]}; });
    EXPECT_NEAR(corner_jacobian_ratio(m, squeezed.data(), 0), 0.5, 1e-12);
    auto folded = moved(m, [](auto x) { return x; });
    folded[2 * dim + 0] = -0.5, folded[2 * dim + 1] = -1.5;  // node 2 pushed across the opposite corner
    EXPECT_LT(corner_jacobian_ratio(m, folded.data(), 0), 0.0);
  }
}

}  // namespace test_element_quality
