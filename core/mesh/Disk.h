#pragma once
// Structured generator of a solid disk (Q4, 2D) or a solid cylinder with its axis along y (H8, 3D): the o-grid of
// mesh/OGrid.h — a square core and a ring around it in each quarter, so no element degenerates at the centre — over
// whole quarters of the circle: the whole disk, a half or a quarter.
#include "mesh/Mesh.h"

namespace rollsim {

/// The section is the disk of `radius` about (c0, c1): in 2D the x-y plane; in 3D the x-z plane, the angle measured
/// from +x towards +z as in CylinderSpec, swept from y = y0 to y0 + length.
struct DiskSpec {
  int dim = 2;
  double c0 = 0.0, c1 = 0.0;   // centre (length): 2D (x, y); 3D the axis position (x, z)
  double radius = 1.0;         // > 0 (length)
  int n_core = 2;              // elements along each edge of a quarter's square core (a quarter arc has 2 n_core)
  int n_ring = 2;              // elements across the ring, from the core to the round surface
  double core_fraction = 0.5;  // half-side of a quarter's core / the radius, in [0.2, 0.7]
  double theta0 = 0.0;         // start of the span (degrees, a multiple of 90)
  double theta1 = 360.0;       // end of the span (degrees, a multiple of 90; 0 < theta1 − theta0 <= 360)
  double y0 = 0.0;             // 3D: first end face (length)
  double length = 1.0;         // 3D: axial extent > 0 (length)
  int n_axial = 1;             // 3D: elements along y
};

/// Positively oriented elements, quarter by quarter from theta0. Surfaces (and node sets of the same name): "outer"
/// (the round surface); for a span short of 360 degrees "start" (the radius at theta0) and "end" (at theta1); in 3D
/// "ymin" and "ymax". Node set "center": the node at the centre (3D: the nodes on the axis); element set "all"; node
/// set "all". Throws std::invalid_argument naming the offending field.
Mesh make_disk(const DiskSpec& spec);

}  // namespace rollsim
