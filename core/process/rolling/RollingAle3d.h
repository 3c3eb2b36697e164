#pragma once
// The mesh motion of a 3D ALE rolling pass (process.formulation: ale, dimension 3; the plane-strain one is
// RollingAle): the slab's window is held around the roll gap while its material flows through. Its nodes lie on lines
// along x (one per width position and thickness level, as meshed); after each step every line's node at each x goes
// to where that material line now crosses the plane of its x (across the width a cubic through the line's nodes
// around it, in height their chord) — so the side
// face follows the spread and the top the free surface —, a top node that touches the roll (or would lie inside it)
// onto the roll's deformed surface there. Points before the entry face's new place hold material that flowed in during
// the step: virgin.
#include <string>
#include <vector>

#include "analysis/MeshMotion.h"
#include "model/Model.h"
#include "process/rolling/RollSurface.h"
#include "process/rolling/RollingPass.h"

namespace rollsim {

class RollingAle3d final : public MeshMotion {
 public:
  RollingAle3d(const RollingPass& pass, const Model& model);
  int body() const override { return slab_; }
  Positions placed(const std::vector<Positions>& current, const std::vector<char>& touching) const override;
  bool inflow(const std::array<double, 3>& p, const Positions& current) const override;
  std::vector<int> inflow_face() const override { return entry_; }
  std::string describe() const override;

 private:
  /// The height of the roll's deformed outer surface's lower side above (x, y), +∞ where none lies there.
  double roll_under(double x, double y, const Positions& roll) const;
  int slab_ = 0, roll_ = 1;
  std::vector<double> x_;                        // the window's node planes along x, ascending
  std::vector<std::vector<int>> lines_;          // per material line: its nodes by x (one per plane)
  std::vector<char> top_;                        // per line: on the top face
  std::vector<std::array<double, 3>> entry_of_;  // per line: its first node as meshed (the virgin entry section)
  std::vector<int> entry_;                       // the entry face's nodes
  std::vector<std::array<int, 4>> roll_facets_;  // the roll's outer surface
  RollSurface surface_;
};

}  // namespace rollsim
