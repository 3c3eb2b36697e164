#pragma once
// The mesh motion of an ALE rolling pass (process.formulation: ale; analysis/AleStep): the slab's mesh is a window
// held around the roll gap while its material flows through. After each step every column of the slab's nodes goes
// back to its x; its top follows the free surface the step left (the slab's top, interpolated at that x), or the
// roll's deformed surface between the top nodes that touch the roll and wherever the free surface would lie inside it
// (before the arc the free top's last segment meets the roll: a column whose node went into the arc in a long step is
// left off the roll, and inactive — contact/refind_contacts —, where the material at its x has not reached it); its
// other nodes keep their share of the height as meshed (the symmetry plane at 0). Before the entry face's new place
// the top keeps its height, and points there hold material that flowed in during the step: virgin. Plane strain, a
// structured slab (columns of one x).
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "analysis/MeshMotion.h"
#include "model/Model.h"
#include "process/rolling/RollSurface.h"
#include "process/rolling/RollingPass.h"

namespace rollsim {

class RollingAle final : public MeshMotion {
 public:
  /// The motion of `pass`'s slab, its window as meshed in `model` (built from the pass).
  RollingAle(const RollingPass& pass, const Model& model);
  int body() const override { return slab_; }
  Positions placed(const std::vector<Positions>& current, const std::vector<char>& touching) const override;
  bool inflow(const std::array<double, 3>& p, const Positions& current) const override;
  std::vector<int> inflow_face() const override { return entry_; }
  std::string describe() const override;

 private:
  struct Column {
    double x = 0;
    std::vector<int> nodes;     // bottom to top
    std::vector<double> share;  // each node's height over the column's top, as meshed
  };
  /// The slab's top after a step: its nodes by x, the span of those touching the roll (the arc), the last two free
  /// ones before it.
  struct Top {
    std::vector<std::array<double, 2>> surface;
    double arc_from = std::numeric_limits<double>::infinity(), arc_to = -arc_from;
    std::array<double, 2> before_last_free{0, 0}, last_free{0, 0};
  };
  /// The top's height at x under the roll's current surface (`roll`): on the roll within the arc; before it, the free
  /// top's last segment carried on until it meets the roll (a column whose node went into the arc during the step
  /// while the material at its x has not reached the roll stays off it); elsewhere the top interpolated at x.
  double top_at(double x, const Top& top, const Positions& roll) const;
  int slab_ = 0, roll_ = 1;
  std::vector<Column> columns_;                 // by x
  std::vector<int> entry_;                      // the entry face's nodes, bottom to top
  double entry_height_ = 0;                     // its top as meshed: the virgin material's
  std::vector<std::array<int, 2>> roll_edges_;  // the roll's outer surface, node pairs
  RollSurface surface_;
};

}  // namespace rollsim
