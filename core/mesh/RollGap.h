#pragma once
// The roll gap as the meshes see it: the roll's outer surface is the polygon of its mesh (n_around chords of a
// circle, the first node at angle 0), and a slab that enters the pass already bitten has its top surface cut to
// that polygon between the entry of the bite and the exit plane, so that it touches the roll along the whole arc
// without penetrating a chord (the "pre-bitten" entry: the state a pusher would leave it in when the roll grips).
#include "mesh/Mesh.h"
#include "mesh/RadiusProfile.h"

namespace rollsim {

/// The roll's outer polygon in the rolling plane: axis at (x, t) = (cx, ct), radius R through its nodes, n_around
/// nodes starting at angle 0 (the annulus and cylinder generators' layout); n_around 0: the circle itself (a fixed
/// roll, whose contact holds the slab to its true surface).
struct RollPolygon {
  double cx = 0, ct = 0, radius = 1;
  int n_around = 120;

  /// Height t of the polygon's lower side at x, or +∞ where x is beyond the roll (|x − cx| ≥ R).
  double lower_surface(double x) const;
};

/// Cuts the slab's top surface down to the roll polygon where the polygon lies below it: a node at thickness
/// coordinate t (axis `thickness_axis`, the slab's mid-plane at t = 0, its top at t = top) moves to
/// t · min(top, lower_surface(x)) / top. In 3D a profiled roll's radius is roll.radius + profile.at(y) at the node's
/// width coordinate y (axis 1): the polygon of that radius is the roll mesh's surface there when the profile is
/// sampled at the roll's axial nodes. `flat_exit`: past the roll's axis (x > cx) the top stays at the gap, the
/// polygon's height at cx — a slab that has already left the gap there (an ALE window's exit). Throws
/// std::invalid_argument when the cut leaves no thickness.
void cut_to_roll(Mesh& slab, int thickness_axis, double top, const RollPolygon& roll, const RadiusProfile& profile = {},
                 bool flat_exit = false);

}  // namespace rollsim
