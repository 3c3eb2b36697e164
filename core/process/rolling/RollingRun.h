#pragma once
// A rolling pass running on its model: refuses a pass the roll cannot bite, tells the observers each increment's
// travel, roll force and torque, ends the analysis once the slab's rear end enters the roll gap, and measures the whole
// pass at the end (RollingMeasures, RollingReport).
#include "process/Process.h"
#include "process/rolling/RollingPass.h"

namespace rollsim {

class RollingRun final : public ProcessRun {
 public:
  RollingRun(RollingPass pass, const Model& model) : pass_(pass), model_(model) {}
  RunStatus refusal() const override;
  std::vector<ProcessFact> facts() const override;
  double expected_share() const override;
  MeasureTable live_table() const override;
  ChartRequest live_chart() const override;
  MeasureRow measure(const IncrementResults& increment) const override;
  std::string over(const IncrementResults& increment) const override;
  ProcessResults finish(const Results& results) const override;

 private:
  RollingPass pass_;
  const Model& model_;
};

}  // namespace rollsim
