#pragma once
// One step of an ALE run (arbitrary Lagrangian–Eulerian, split by steps; the Newton driver takes it after every
// converged step when a process gives a MeshMotion): the body the material flows through gets its nodes put back where
// the motion says (a rolling pass's slab window: every column at its x, the top following the free surface or the
// roll) and becomes its new reference, its displacement zero; its state, read on the configuration the step ended in
// (fem/StateTransfer::current_state: C_p⁻¹ becoming b_e), is advected onto the new points. A continuous field through
// the old points (their values extrapolated to the corners and averaged at the nodes) carries what is smooth: each
// new point takes its value where the point lies. What that field does not hold of a point's value — its own part,
// the value minus the field at the point — stays with the point while its material is still in the element, and
// leaves with the material: it is scaled by 1 − (how far the material moved) / (the element's extent along the move),
// an upwind step of that part with nothing behind it. A point that did not move keeps its value; a constant field is
// carried exactly. The result is clamped to the values of the two elements involved (no new extremes); zero (virgin)
// where the motion says material flowed in, and the continuous field zero on its inflow face (an inflow boundary:
// what stood at the entry is washed out). Keeping each point's own part in place (the scheme before 2026-11-30) let
// whatever the steps added there pile up while the material passed: the paper's pass lost 8 % of its force over 150 mm
// in 2 mm steps. Interpolating the old element's points alone (StateTransfer::transfer_points, a remesh's) carried
// no change to a point past its element's points and diverged the 64 × 12 pass in 1 mm steps, and so did taking the
// nearest old point's value: the elastic strain's error is multiplied by E/σ_y ≈ 2000 in the stress. Quads and hexes;
// the same elements before and after.
#include <Eigen/Dense>
#include <vector>

#include "analysis/MeshMotion.h"
#include "fem/StateTransfer.h"
#include "model/Model.h"

namespace rollsim {

/// The moving body after an ALE step: its new node positions and its state advected onto their points.
struct AleRemap {
  std::vector<Point3> nodes;
  std::vector<double> state;
};

/// The remap of `body` (displaced by `u`, its committed point state `committed`), every body's current node
/// positions `current`, `touching`: which of its nodes are in contact. Throws AnalysisError when the placed mesh
/// would fold an element.
AleRemap ale_remap(const Body& body, const Eigen::VectorXd& u, const std::vector<double>& committed,
                   const std::vector<MeshMotion::Positions>& current, const std::vector<char>& touching,
                   const MeshMotion& motion);

/// Point values (`width` each, element-major) of `from` with its nodes at `x`, advected to the points of `to` (the
/// same elements at other positions), zero at every point `motion` calls inflow.
std::vector<double> advected_points(const Mesh& from, const std::vector<Point3>& x, const std::vector<double>& values,
                                    int width, const Mesh& to, const MeshMotion& motion);

}  // namespace rollsim
