#pragma once
// Structured Q4 generator: quarter model of a rectangular plate with a central circular hole.
#include "mesh/Mesh.h"

namespace rollsim {

/// Quarter plate [0, W] x [0, H] minus the disk of radius a centred at the origin (lengths in model units).
/// The quarter circle is split into n_around equal arcs; the first half is joined by straight radial lines to
/// equally spaced points on the edge x = W, the second half to equally spaced points on the edge y = H, so the
/// hole point at 45 degrees is joined to the corner (W, H).
struct PlateWithHoleSpec {
  double half_width = 1.0;    // W: plate extent along x from the symmetry line x = 0
  double half_height = 1.0;   // H: plate extent along y from the symmetry line y = 0
  double hole_radius = 0.25;  // a: 0 < a < min(W, H)
  int n_around = 8;           // elements along the quarter circle; even, at least 2
  int n_radial = 6;           // elements along each line from the hole to the outer edges; at least 1
  double grading = 1.0;       // radial size ratio of each element to its neighbour nearer the hole; >= 1
};

/// Nodes and elements are numbered with the direction that has fewer nodes varying fastest.
/// Surfaces and node sets: "left" (x = 0), "bottom" (y = 0), "right" (x = W), "top" (y = H), "hole";
/// element set "all"; node set "all". Throws std::invalid_argument naming the offending field.
Mesh make_plate_with_hole(const PlateWithHoleSpec& spec);

}  // namespace rollsim
