#include "material/LinearElastic.h"

namespace rollsim {

Tangent6 LinearElastic::hooke(double l, double m) {
  Tangent6 D = Tangent6::Zero();
  D.topLeftCorner<3, 3>().setConstant(l);
  for (int i = 0; i < 3; ++i) {
    D(i, i) = l + 2.0 * m;
    D(3 + i, 3 + i) = m;
  }
  return D;
}

void LinearElastic::update(const Deformation& d, const double* /*committed*/, double* /*trial*/, Voigt6& stress,
                           Tangent6& tangent) const {
  tangent = C_;
  stress.noalias() = C_ * d.strain;
}

}  // namespace rollsim
