#pragma once
// A rolling pass running on its model: refuses a pass the roll cannot bite, tells the observers each increment's
// travel, roll force and torque, ends the analysis once the slab's rear end enters the roll gap (or, asked to, once
// the pass is steady), holds an ALE pass's slab window in place (RollingAle), and measures the whole pass at the end
// (RollingMeasures, RollingReport).
#include <memory>
#include <vector>

#include "process/Process.h"
#include "process/rolling/RollingAle.h"
#include "process/rolling/RollingPass.h"
#include "process/rolling/RollingResults.h"

namespace rollsim {

class RollingRun final : public ProcessRun {
 public:
  RollingRun(RollingPass pass, const Model& model);
  RunStatus refusal() const override;
  std::vector<ProcessFact> facts() const override;
  double expected_share() const override;
  MeasureTable live_table() const override;
  ChartRequest live_chart() const override;
  MeasureRow measure(const IncrementResults& increment) const override;
  std::string over(const IncrementResults& increment) const override;
  ProcessResults finish(const Results& results) const override;
  const MeshMotion* mesh_motion() const override { return ale_.get(); }

 private:
  /// Why the pass is over as steady (stop_at_steady): the increments measured so far are steady.
  std::string steady() const;
  /// Whether the steady rule also waits for the free side (an ALE pass in 3D: steady_state_from's `shape`).
  RollingPass pass_;
  const Model& model_;
  std::unique_ptr<MeshMotion> ale_;             // an ALE pass's window: RollingAle, or RollingAle3d in 3D
  mutable std::vector<RollingIncrement> live_;  // travel, force and torque of every increment measured so far
};

}  // namespace rollsim
