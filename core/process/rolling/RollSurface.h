#pragma once
// The roll's surface as an ALE window's top is placed on it. A turning roll's mesh carries its material: the contact
// holds the slab to its facets, and so does the window. A fixed roll (process.roll_mesh: fixed) is a surface of
// revolution whose material turns under a mesh that stays: the contact holds the slab to the true surface — the
// radius interpolated from a facet's nodes, not the facet's chord (contact/ContactConstraints round_facet) —, and the
// window's top must lie there too: on the chords, every column in the arc would be put into the roll by up to the
// sagitta L²/8R and pushed out again at the next step.
#include <array>
#include <cmath>
#include <limits>

#include "model/Model.h"
#include "process/rolling/RollingPass.h"

namespace rollsim {

struct RollSurface {
  bool round = false;                 // the true surface of revolution (a fixed roll), or the facets (a turning one)
  double centre_x = 0, centre_h = 0;  // the hub's axis: its x and height
  int height_axis = 1;                // y in 2D, z in 3D

  RollSurface(const RollingPass& pass, const Model& model) : round(pass.roll_fixed), height_axis(pass.thickness_axis) {
    const auto& c = model.displacements[static_cast<size_t>(pass.hub)].rotation->center;
    centre_x = c[0], centre_h = c[static_cast<size_t>(height_axis)];
  }
  /// A point's distance from the roll's axis.
  double radius(const std::array<double, 3>& p) const {
    return std::hypot(p[0] - centre_x, p[static_cast<size_t>(height_axis)] - centre_h);
  }
  /// Whether a point of the roll lies on its lower side (below the axis): the side the slab meets.
  bool lower(const std::array<double, 3>& p) const { return p[static_cast<size_t>(height_axis)] < centre_h; }
  /// The height of the lower side, at x, of the surface of revolution of radius r about the axis (+∞ beyond it).
  double lower_side(double x, double r) const {
    const double d = r * r - (x - centre_x) * (x - centre_x);
    return d >= 0 ? centre_h - std::sqrt(d) : std::numeric_limits<double>::infinity();
  }
};

}  // namespace rollsim
