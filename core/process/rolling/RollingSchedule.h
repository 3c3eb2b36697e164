#pragma once
// A rolling schedule (process.passes): plane-strain passes one after the other, each starting from the slab the pass
// before left. What the slab takes to the next pass: its measured exit thickness, its length (its volume kept), and
// the through-thickness profiles of its equivalent plastic strain and temperature over the rolled part that left the
// gap (the slab that entered the arc from before it — the pre-bitten front was cut, never rolled — and is now past
// the exit plane), mapped layer by layer onto the next pass's slab — generated with the same layers (slab_nt, thickness
// grading), so a layer's mean goes to the same layer, uniform along the length. The next slab is stress-free:
// residual stresses and the plastic strain tensor are not carried (the equivalent plastic strain is, for the flow
// stress). Between passes the slab cools in air for the pass's interpass_time (HeatConduction on the slab alone, the
// air on every face but the mid-plane) when the pass has heat_transfer; without it the slab keeps its temperature.
#include <vector>

#include "analysis/Results.h"
#include "base/Measures.h"
#include "base/Schema.h"
#include "model/Model.h"

namespace rollsim {

/// The schema of one entry of process.passes.
const ObjectSchema& pass_schema();

/// True when the project's process is a rolling schedule (process.passes given).
bool is_schedule(const json& project);

/// The process section of pass k: the section's settings with pass k's (reduction or exit_thickness, roll size and
/// speed) in their place, and no `passes`.
json pass_section(const json& process, size_t k);

/// The schedule's checks at the user's paths: plane strain, each pass's thickness below the one it receives (by the
/// nominal thicknesses), one of reduction and exit_thickness per pass, and every pass's own rolling checks
/// (check_rolling on its nominal section, its paths named in process.passes[k] where the pass sets the field).
void check_schedule(const json& project, std::vector<Issue>& issues);

/// What a slab carries from a pass to the next.
struct SlabState {
  double thickness = 0, length = 0;     // [length]
  std::vector<double> layer_strain;     // per element layer from the mid-plane: mean equivalent plastic strain [-]
  double mean_strain = 0;               // its volume mean [-]
  std::vector<double> row_temperature;  // per node row from the mid-plane: mean temperature [°C] (empty: none)
  std::vector<double> cooled;           // per node of the next pass's slab, after the air (empty: not cooled)
  double mean_temperature = 0;          // the volume mean of the temperature it brings (cooled, when it was) [°C]
};

/// One pass of the schedule as it ended, for the schedule's table.
struct PassRecord {
  double entry_thickness = 0, exit_thickness = 0, roll_radius = 0, roll_speed = 0, interpass_time = 0;
  double entry_temperature = 0;  // the slab's mean as the pass began (after the air) [°C]
  double roll_force = 0, roll_torque = 0, roll_power = 0, sims_force = 0;
  double sims_force_carried = 0;  // Sims's with the flow stress from the strain the slab brings (pass 1: the same)
  double slab_temperature = 0, surface_temperature = 0;  // at the pass's end (0: no temperature) [°C]
  bool thermal = false;
};

/// The schedule's run, pass by pass, driven by a front end (`rollsim run`): for each pass k, its project
/// (pass_project) is built into a model as any project is, `cool` lets the slab lose its heat to the air over the
/// inter-pass time on that model's slab (then the project is asked again: its slab_temperature is the cooled mean),
/// `apply` puts what the slab brings on the model, the pass is run and written, and `finish` takes from its results
/// what the next pass receives and what the schedule's table shows.
class ScheduleRun {
 public:
  /// `project` validated (defaults filled: the passes' measures read them), `given` as the user gave it (with the
  /// command line's overrides): the passes' projects are made from it, to be validated as any project.
  ScheduleRun(const json& project, const json& given);
  size_t passes() const { return count_; }
  /// Pass k's project (its process a single pass on the slab the pass before left).
  json pass_project(size_t k) const;
  /// Whether pass k's slab cools in air first (a later pass with heat_transfer and an interpass_time).
  bool cools(size_t k) const;
  /// The slab of `model` (built from pass_project(k)) with what it brings, cooled in air over pass k's
  /// interpass_time: kept for pass_project(k) and apply(k).
  void cool(size_t k, const Model& model);
  /// What the slab brings into pass k on `model` (built from pass_project(k)): initial plastic strain and
  /// temperature. Nothing for the first pass.
  void apply(size_t k, Model& model) const;
  /// Pass k ended with `results` on `model`: its record, and the slab the next pass receives (throws AnalysisError
  /// when no rolled part left the gap: the pass's travel was too short for a next pass).
  void finish(size_t k, const Model& model, const Results& results);
  /// schedule.csv's table (one row per pass finished), its chart and summary.json's `schedule`.
  MeasureTable table() const;
  ChartRequest chart() const;
  nlohmann::json summary() const;
  const std::vector<PassRecord>& records() const { return records_; }

 private:
  /// Pass k's section with its defaults filled in (what its measures read).
  json section(size_t k) const;
  json project_, given_;
  size_t count_ = 0;
  SlabState state_;  // what the next pass receives
  std::vector<PassRecord> records_;
};

}  // namespace rollsim
