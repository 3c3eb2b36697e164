#pragma once
// The flat-rolling pass, a process (process.type: rolling): from the pass geometry
// (slab length × width × thickness, roll radius and barrel, reduction) and mesh densities it generates the
// slab and roll bodies, their materials, the slab–roll contact pair and the symmetry / support conditions, so
// that the rest of the engine sees an ordinary multi-body project. Symmetry: half thickness always (the slab's
// mid-plane), half width in 3D. Axes: x rolling direction, y thickness (2D) / width (3D), z thickness (3D).
#include "base/Schema.h"
#include "model/Model.h"
#include "process/Process.h"
#include "process/rolling/RollingPass.h"

namespace rollsim {

/// The schema of the section (fields, units, defaults: the paper's pass, slab 300 × 350 × 100 mm, roll radius
/// 300 mm, 13.2 % reduction).
const ObjectSchema& rolling_process_schema();

/// Checks of the validated project's pass that need more than one field (the grading against slab_nx, the hub
/// inside the roll, the slab within the barrel) or that refuse what the pass would ignore (friction_coefficient
/// without coulomb friction, entries of `materials` no body uses), named by the user's paths (`process.<field>`,
/// `materials[i]`).
void check_rolling(const json& project, std::vector<Issue>& issues);

/// `project` with the bodies, materials, contacts and conditions of its pass appended. The section must already be
/// validated (defaults filled).
json expand_rolling(const json& project);

/// The pass as its measures need it (bodies, the hub's rotation, nominal geometry) from the validated `section`, on
/// `model` built from expand_rolling(project).
RollingPass rolling_pass(const json& section, const Model& model);

/// The slab's flow stress for the closed forms (Sims's force, a Coulomb pass's shear limit) from the validated
/// `section`: σ_0, or its law's mean over the pass's strain (2/√3) ln(h0/h1) at the pass's mean rate and the slab's
/// temperature (Simpson's rule, 64 intervals), starting from `strain_before` (a schedule's later pass: what the slab
/// brings).
double pass_flow_stress(const json& section, double strain_before = 0);

/// The rolling pass as a process of the registry (process.type: rolling).
class RollingProcess final : public Process {
 public:
  std::string name() const override { return "rolling"; }
  const ObjectSchema& schema() const override { return rolling_process_schema(); }
  void check(const json& project, std::vector<Issue>& issues) const override { check_rolling(project, issues); }
  json expand(const json& project) const override { return expand_rolling(project); }
  std::string smaller_steps(const json& section) const override;
  std::string progress(const json& section, double fraction) const override;
  std::vector<std::string> outputs() const override;
  std::unique_ptr<ProcessRun> start(const json& section, const Model& model) const override;
};

}  // namespace rollsim
