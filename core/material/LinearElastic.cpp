#include "material/LinearElastic.h"

namespace rollsim {

Tangent6 LinearElastic::tangent3d() const {
  Tangent6 D = Tangent6::Zero();
  const double l = lambda(), m = mu();
  D.topLeftCorner<3, 3>().setConstant(l);
  for (int i = 0; i < 3; ++i) {
    D(i, i) = l + 2.0 * m;
    D(3 + i, 3 + i) = m;
  }
  return D;
}

void LinearElastic::update(const Deformation& d, const double* /*committed*/, double* /*trial*/, Voigt6& stress,
                           Tangent6& tangent) const {
  tangent = tangent3d();
  stress = tangent * d.strain;
}

}  // namespace rollsim
