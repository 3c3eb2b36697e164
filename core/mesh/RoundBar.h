#pragma once
// Structured H8 generator: a solid round bar with its axis along z, the quarter x >= 0, y >= 0 of its section
// meshed as an o-grid (a square core and a ring around it), swept along z, with an optional neck (a radius that
// grows linearly from z = 0) — the necking bar of Simo (1988) and de Souza Neto et al. (2008, §14).
#include "mesh/Mesh.h"

namespace rollsim {

/// The bar occupies 0 <= z <= length; z = 0 is where the neck is (the mid-length symmetry plane of a whole bar).
/// The section at z has radius r(z) = radius · (neck_ratio + (1 − neck_ratio) · min(z / taper_length, 1)).
struct RoundBarSpec {
  double radius = 1.0;         // full radius R > 0 (length)
  double length = 1.0;         // axial extent > 0 (length)
  int n_core = 2;              // elements along each edge of the square core (the quarter arc has 2 n_core); >= 1
  int n_ring = 2;              // elements across the ring from the core to the surface; >= 1
  int n_axial = 4;             // elements along z; >= 1
  double core_fraction = 0.5;  // half-side of the square core / the radius, in [0.2, 0.7]
  double neck_ratio = 1.0;     // radius at z = 0 / radius, in (0, 1] (1: no neck)
  double taper_length = 0.0;   // axial extent of the neck's taper, in (0, length]; 0: the whole length
  double axial_grading = 1.0;  // each element along z is this times the one before it (> 1: finer at the neck)
};

/// Positively oriented H8 elements, numbered section by section from z = 0. Surfaces (and node sets of the same
/// name): "xmin" (the plane x = 0), "ymin" (y = 0), "zmin" (z = 0), "zmax" (z = length), "outer" (the round
/// surface); element set "all"; node set "all". Throws std::invalid_argument naming the offending field.
Mesh make_round_bar(const RoundBarSpec& spec);

/// The radius of the section at z, as the generator places its surface nodes.
double round_bar_radius(const RoundBarSpec& spec, double z);

}  // namespace rollsim
