#include "mesh/RollGap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rollsim {

double RollPolygon::lower_surface(double x) const {
  if (n_around <= 0) {  // the circle itself
    const double d = radius * radius - (x - cx) * (x - cx);
    return d > 0 ? ct - std::sqrt(d) : std::numeric_limits<double>::infinity();
  }
  double best = std::numeric_limits<double>::infinity();
  const double step = 2 * std::numbers::pi / n_around;
  for (int k = 0; k < n_around; ++k) {  // the chords of the lower half that span x
    const double x0 = cx + radius * std::cos(k * step), x1 = cx + radius * std::cos((k + 1) * step);
    const double t0 = ct + radius * std::sin(k * step), t1 = ct + radius * std::sin((k + 1) * step);
    if (t0 > ct && t1 > ct) continue;
    const double lo = std::min(x0, x1), hi = std::max(x0, x1);
    if (x < lo || x > hi || hi == lo) continue;
    best = std::min(best, t0 + (t1 - t0) * (x - x0) / (x1 - x0));
  }
  return best;
}

void cut_to_roll(Mesh& slab, int thickness_axis, double top, const RollPolygon& roll, const RadiusProfile& profile,
                 bool flat_exit) {
  for (auto& X : slab.nodes) {
    RollPolygon here = roll;
    if (slab.dim == 3) here.radius += profile.at(X[1]);
    const double surface = here.lower_surface(flat_exit ? std::min(X[0], roll.cx) : X[0]);
    if (!(surface < top)) continue;
    if (surface <= 1e-6 * top)
      throw std::invalid_argument("the roll cuts the slab through its whole thickness at x = " + std::to_string(X[0]));
    X[static_cast<size_t>(thickness_axis)] *= surface / top;
  }
}

}  // namespace rollsim
