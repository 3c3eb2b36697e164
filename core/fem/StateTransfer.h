#pragma once
// Carrying a body's fields from one mesh to another over the same region (a remesh, analysis/Remeshing): the
// integration-point state of each new point from the old element it lies in — the bilinear interpolation of that
// element's four Gauss-point values, the place held within their square (so a point that did not move gets its own
// value back, and one near the element's edge its nearest points' values); nodal fields by the old mesh's shape
// functions. Every carried value is a convex combination of old ones: no new extremes (a plastic strain never turns
// negative, a tensor that was positive definite stays so), and no averaging across elements (a lumped L2 projection
// onto the nodes first took 20 % off the peak plastic strain at a punch's corner, and its stresses left the
// equilibrium so far that Newton could not restore it). Conservation is not built in: summary.json reports the
// plastic strain's integral before and after each transfer. transfer_points and transfer_nodes: 2D quad meshes; the
// locator, current_state and integration_points: quads and hexes.
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "mesh/Mesh.h"
#include "model/Model.h"

namespace rollsim {

using Point3 = std::array<double, 3>;

/// Where a point lies in a mesh: its element and local coordinates (ξ, η, ζ) in [−1, 1]^D.
struct MeshPlace {
  int element = -1;
  double xi = 0, eta = 0, zeta = 0;  // ζ: hexes only
};

/// Finds points in a quad or hex mesh whose nodes are at `x` (the mesh's connectivity, other positions).
class PointLocator {
 public:
  PointLocator(const Mesh& mesh, const std::vector<Point3>& x);
  /// The element holding p, searched from element `near` and its neighbours outward; a point outside every element
  /// (a boundary that moved by less than an element): the element and local coordinates nearest to it.
  MeshPlace locate(const Point3& p, int near) const;

 private:
  /// Local coordinates of p in element e (xi: D of them) by Newton on the isoparametric map, clamped to the element;
  /// the distance left.
  double local(int e, const Point3& p, double* xi) const;
  const Mesh& mesh_;
  const std::vector<Point3>& x_;
  std::vector<std::vector<int>> neighbours_;  // per element: the elements sharing a node with it
};

/// The integration-point state of `body` displaced by `u` (node-major) as it reads on the current configuration:
/// the material's rebase_state at every point's deformation gradient (F̄ under F-bar) — the state a mesh of the
/// current positions starts from.
std::vector<double> current_state(const Body& body, const Eigen::VectorXd& u, std::vector<double> state);

/// Node positions of `mesh` displaced by `u` (node-major, dim per node).
std::vector<Point3> displaced_nodes(const Mesh& mesh, const Eigen::VectorXd& u);

/// The integration points of a quad mesh at its own node positions (element-major, 4 per element).
std::vector<Point3> integration_points(const Mesh& mesh);
/// The same with its nodes at `x` (a displaced configuration).
std::vector<Point3> integration_points(const Mesh& mesh, const std::vector<Point3>& x);

/// Point values (`width` per integration point, element-major) of `from`, its nodes at `x`, carried to the
/// integration points of `to` (at its own node positions).
std::vector<double> transfer_points(const Mesh& from, const std::vector<Point3>& x, const std::vector<double>& values,
                                    int width, const Mesh& to);

/// Nodal values of `from`, its nodes at `x`, carried to the nodes of `to` (quads): interpolated, then the lumped L2
/// projection of what the interpolation lost (the old field minus the new over each of `to`'s elements, 4 × 4 Gauss
/// points on each quarter) added, and what that puts beyond the old values' range handed to the neighbouring nodes
/// with room (a repair): a linear field and a node whose elements did not move keep their values, ∫ v dV is kept to
/// the quadrature's accuracy, and no value leaves the old range. (A thin chilled skin under a node moved deeper lost
/// 7 % of its deficit to interpolation alone; carried this way its heat stays, smeared over the coarser element.)
std::vector<double> transfer_nodes(const Mesh& from, const std::vector<Point3>& x, const std::vector<double>& values,
                                   const Mesh& to);

/// ∫ v dV of one point value (component `component` of `width`) over a quad mesh with its nodes at `x`.
double integral(const Mesh& mesh, const std::vector<Point3>& x, const std::vector<double>& values, int width,
                int component);

}  // namespace rollsim
