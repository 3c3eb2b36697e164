#pragma once
// The mesh motion of an ALE rolling pass (process.formulation: ale; analysis/AleStep): the slab's mesh is a window
// held around the roll gap while its material flows through. After each step every column of the slab's nodes goes
// back to its x; its top follows the free surface the step left (the slab's top, interpolated at that x), or the
// roll's deformed surface where the column's top node touches the roll or the free surface would lie inside it (a
// node entering the arc, put back off the roll but still in contact, would otherwise be pulled onto it by its contact
// row at every step); its other nodes keep their share of the height as meshed (the symmetry plane at 0). Before the
// entry face's new place the top keeps its height, and points there hold material that flowed in during the step:
// virgin. Plane strain, a structured slab (columns of one x).
#include <string>
#include <vector>

#include "analysis/MeshMotion.h"
#include "model/Model.h"
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
  /// The top's height at x: the slab's current top surface (`top`, by x), under the roll's current surface — on it
  /// where the column's top node touches the roll (`touching`: the material there is in contact).
  double top_at(double x, const std::vector<std::array<double, 2>>& top, const Positions& roll, bool touching) const;
  int slab_ = 0, roll_ = 1;
  std::vector<Column> columns_;                 // by x
  std::vector<int> entry_;                      // the entry face's nodes, bottom to top
  std::vector<std::array<int, 2>> roll_edges_;  // the roll's outer surface, node pairs
};

}  // namespace rollsim
