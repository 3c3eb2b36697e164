#pragma once
// Structured H8 generator: hollow cylinder (or cylindrical sector) with its axis parallel to y (a 3D roll).
#include "mesh/Mesh.h"
#include "mesh/RadiusProfile.h"

namespace rollsim {

/// Hollow cylinder r_i <= r <= r_o about the axis x = cx, z = cz, for y0 <= y <= y0 + length. The angle theta
/// is measured in the x-z plane from +x towards +z: x = cx + r cos(theta), z = cz + r sin(theta), so the
/// x-z section matches AnnulusSpec's x-y section (theta = 270 is the bottom of the roll).
struct CylinderSpec {
  double cx = 0.0;              // axis position x (length)
  double cz = 0.0;              // axis position z (length)
  double y0 = 0.0;              // first end face y = y0 (length)
  double length = 1.0;          // axial extent > 0 (length)
  double inner_radius = 0.5;    // r_i > 0 (length)
  double outer_radius = 1.0;    // r_o > r_i (length)
  int n_radial = 2;             // elements across the wall; at least 1
  int n_around = 24;            // elements along the angular span; each must span less than 180 degrees
  int n_axial = 4;              // elements along y; at least 1
  double theta0 = 0.0;          // start angle (degrees)
  double theta1 = 360.0;        // end angle (degrees); 0 < theta1 - theta0 <= 360, 360 closes the ring
  RadiusProfile outer_profile;  // the outer radius at y is outer_radius + outer_profile.at(y) (a crowned or grooved
                                // roll), sampled at the axial nodes; the inner radius stays
};

/// Positively oriented H8 elements. Nodes and elements are numbered with the direction that has fewest nodes
/// varying fastest (closed rings in the folded order of AnnulusSpec). Surfaces and node sets: "inner", "outer",
/// "ymin", "ymax", and for partial spans "start" (theta0) and "end" (theta1); element set "all"; node set "all".
/// Throws std::invalid_argument naming the offending field.
Mesh make_cylinder(const CylinderSpec& spec);

}  // namespace rollsim
