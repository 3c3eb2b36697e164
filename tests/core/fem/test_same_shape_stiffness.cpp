// SameShapeStiffness (fem/ElementLoop.h): an element stiffness is kept by the element's coordinates relative to its
// first node, so that congruent elements share one computation, bit for bit, and an element of another shape never
// gets a kept matrix.
#include <gtest/gtest.h>

#include "fem/ElementLoop.h"
#include "material/LinearElastic.h"

namespace test_same_shape_stiffness {

using namespace rollsim;

TEST(SameShapeStiffness, CongruentElementsShareTheirStiffnessAndOthersDoNot) {
  using El = SolidElement<3>;
  const LinearElastic steel(210000, 0.3);
  El::Coords cube;
  cube << 0, 1, 1, 0, 0, 1, 1, 0,  //
      0, 0, 1, 1, 0, 0, 1, 1,      //
      0, 0, 0, 0, 1, 1, 1, 1;
  El::Coords sheared = cube;
  sheared(0, 6) += 0.1;
  El::Stiffness cube_K, sheared_K;
  El::stiffness(cube, steel, Formulation::BBar, cube_K);
  El::stiffness(sheared, steel, Formulation::BBar, sheared_K);
  ASSERT_GT((cube_K - sheared_K).norm(), 1e-3 * cube_K.norm());
  SameShapeStiffness<3> shapes;
  EXPECT_EQ(shapes.of(cube, steel, Formulation::BBar), cube_K);
  EXPECT_EQ(shapes.of(sheared, steel, Formulation::BBar), sheared_K);  // not the cube's, kept before it
  EXPECT_EQ(shapes.of(cube, steel, Formulation::BBar), cube_K);        // the kept one
}

}  // namespace test_same_shape_stiffness
