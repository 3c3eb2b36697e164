#pragma once
// Small-strain continuum elements: 4-node plane-strain quad (D = 2) and 8-node hexahedron (D = 3),
// 2-point Gauss rule per direction, full integration or selective B-bar (mean dilatation, Hughes 1980).
#include <Eigen/Dense>
#include <array>

#include "material/Material.h"

namespace rollsim {

template <int D>
struct SolidElement {
  static constexpr int NN = D == 2 ? 4 : 8;     // nodes
  static constexpr int NDOF = D * NN;           // dofs, node-major
  static constexpr int NS = D == 2 ? 4 : 6;     // strain components (2D: xx, yy, zz, xy)
  static constexpr int NGP = D == 2 ? 4 : 8;    // Gauss points
  using Coords = Eigen::Matrix<double, D, NN>;  // column a = coordinates of node a
  using Stiffness = Eigen::Matrix<double, NDOF, NDOF>;
  using Dofs = Eigen::Matrix<double, NDOF, 1>;
  using Stress6 = std::array<double, 6>;           // xx, yy, zz, xy, yz, zx
  using Gradients = Eigen::Matrix<double, D, NN>;  // column a: ∂N_a/∂x

  /// Shape-function gradients with respect to the coordinates x at the Gauss points and at the element centre, and
  /// det J × weight per Gauss point; false if det J ≤ 0 at a Gauss point (an inverted element).
  static bool gradients(const Coords& x, std::array<Gradients, NGP>& dN, std::array<double, NGP>& dv,
                        Gradients& centre);
  /// The same, kept together: what an element's Newton kernel needs of its reference coordinates.
  struct Geometry {
    std::array<Gradients, NGP> dN;  // ∂N/∂X at the Gauss points
    std::array<double, NGP> dv;     // det J × weight at the Gauss points
    Gradients centre;               // ∂N/∂X at the centre
  };
  static bool gradients(const Coords& x, Geometry& g) { return gradients(x, g.dN, g.dv, g.centre); }

  /// Element stiffness K_e = sum_gp B^T C B det J w, C the material's initial tangent.
  static void stiffness(const Coords& x, const Material& mat, Formulation f, Stiffness& Ke);
  /// Stresses at the Gauss points for element displacements ue (the material's update of ε = B ue from the
  /// committed state, NGP × state_size values, or the initial state when null), and the internal force
  /// f_e = sum_gp B^T sigma det J w; returns false if the element is inverted.
  static bool stresses_and_force(const Coords& x, const Material& mat, Formulation f, const Dofs& ue,
                                 std::array<Stress6, NGP>& out, Dofs& fe, const double* committed = nullptr);
  /// The Newton kernel: f_e as above and, when Ke is not null, the consistent tangent K_e = sum_gp B^T D B det J w
  /// (D: the material's algorithmic tangent), from the committed state, writing the trial state (NGP ×
  /// state_size values each; both null for a material without state); false if the element is inverted.
  static bool tangent_and_force(const Coords& x, const Material& mat, Formulation f, const Dofs& ue,
                                const double* committed, double* trial, Stiffness* Ke, Dofs& fe);
  /// ∫ N_a dV over the element for every node a (2-point Gauss rule per direction): the consistent nodal share of
  /// a uniform load per unit volume (a body force b puts b ∫ N_a dV on node a).
  static Eigen::Matrix<double, NN, 1> shape_integrals(const Coords& x);
  /// The shape functions at the Gauss points: row p holds N_a(ξ_p) for every node a (a point's value from its
  /// element's nodes, and a point's share spread back onto them).
  static const Eigen::Matrix<double, NGP, NN>& gauss_shape();
  /// The shape functions and their derivatives with respect to the natural coordinates at `xi` (D of them).
  static void shape_at(const double* xi, Eigen::Matrix<double, NN, 1>& N, Eigen::Matrix<double, D, NN>& dN);
  /// Corner-node value from Gauss-point values (bilinear/trilinear extrapolation).
  static double extrapolate_to_node(const std::array<double, NGP>& gp, int node);
};

extern template struct SolidElement<2>;
extern template struct SolidElement<3>;

}  // namespace rollsim
