#pragma once
// Structured Q4 generator: annulus or annular sector (e.g. the cross-section of a roll), plus the angular
// layout it shares with the 3D cylinder generator.
#include <array>

#include "mesh/Mesh.h"

namespace rollsim {

/// Annulus r_i <= r <= r_o about (cx, cy), angles theta0..theta1 in degrees, counter-clockwise from +x.
/// A span of 360 degrees closes the ring (the last column of nodes is the first one); a smaller span does not.
struct AnnulusSpec {
  double cx = 0.0;            // centre x (length)
  double cy = 0.0;            // centre y (length)
  double inner_radius = 0.5;  // r_i > 0 (length); use a small hub radius for a solid-looking roll
  double outer_radius = 1.0;  // r_o > r_i (length)
  int n_radial = 4;           // elements across the wall; at least 1
  int n_around = 32;          // elements along the angular span; each must span less than 180 degrees
  double theta0 = 0.0;        // start angle (degrees)
  double theta1 = 360.0;      // end angle (degrees); 0 < theta1 - theta0 <= 360
};

/// Nodes and elements are numbered with the direction that has fewer nodes varying fastest; a closed ring is
/// numbered around in the folded order 0, n-1, 1, n-2, ... so the seam does not widen the bandwidth.
/// Surfaces and node sets: "inner", "outer", and for partial spans "start" (theta0) and "end" (theta1);
/// element set "all"; node set "all". Throws std::invalid_argument naming the offending field.
Mesh make_annulus(const AnnulusSpec& spec);

namespace detail {

/// Angular positions of a ring or ring sector (shared by the annulus and cylinder generators).
struct RingLayout {
  RingLayout(double theta0_deg, double theta1_deg, int n_around);
  double theta0;  // degrees
  double span;    // degrees
  int n_around;   // elements around
  bool closed;    // full turn: position n_around is position 0
  /// Distinct node positions around.
  int positions() const { return closed ? n_around : n_around + 1; }
  /// Unit vector of position i (0..n_around); exact on multiples of 90 degrees.
  std::array<double, 2> direction(int i) const;
  /// Numbering rank of position i in 0..n-1 (n = positions() for nodes, n_around for elements): identity for a
  /// sector; for a closed ring 0, n-1, 1, n-2, ... get ranks 0, 1, 2, 3, ... so ring neighbours are <= 2 apart.
  int rank(int i, int n) const;
  /// Inverse of rank().
  int position(int rank, int n) const;
};

/// Throws std::invalid_argument("<spec>.<field> ...") if the radial/angular part of a ring spec is invalid.
void validate_ring(const char* spec, double inner_radius, double outer_radius, int n_radial, int n_around,
                   double theta0, double theta1);

}  // namespace detail
}  // namespace rollsim
