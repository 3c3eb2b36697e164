#pragma once
// A process: what a project's `process` section stands for (a rolling pass today; a hot pass or a multi-pass
// schedule next). It declares its section's schema, expands the section into ordinary bodies, materials, contacts and
// conditions — so that everything below sees a plain multi-body model — and, once the model is built, starts a
// ProcessRun: its refusal of a run it cannot do, its measures of each increment while the analysis goes on, and its
// results afterwards. Chosen by name (process.type) from the registry (process/ProcessRegistry); a new process is a
// new implementation there, with no change to the analyses, Model, Results, the observers or the writers.
#include <memory>
#include <string>
#include <vector>

#include "analysis/IncrementMeasure.h"
#include "analysis/MeshMotion.h"
#include "analysis/Results.h"
#include "base/Measures.h"
#include "base/RunStatus.h"
#include "base/Schema.h"
#include "model/Model.h"

namespace rollsim {

/// One thing a process is, in its own terms, known before anything is solved: "bite angle" "12.0°".
struct ProcessFact {
  std::string name;      // "bite angle"
  std::string value;     // with its unit: "12.0°", "62.9 mm"
  std::string note;      // how it follows, or what it means: "cos α = 1 − Δh / 2R"
  bool warning = false;  // the fact stops the run or needs the user's eye (a pass that does not bite)
};

/// A process running on a built model.
class ProcessRun : public IncrementMeasure {
 public:
  /// Why the run must not be solved (a status that is not converged, e.g. no_bite), or converged when it may.
  virtual RunStatus refusal() const { return {}; }
  /// What the run is in the process's terms, before it is solved (a pass: its bite angle, contact length, whether
  /// it bites, its speed): `rollsim check` and the window's forecast show them.
  virtual std::vector<ProcessFact> facts() const { return {}; }
  /// The share of the analysis's load (0…1] the run is expected to reach: a pass ends once its slab has gone
  /// through the roll gap, whatever travel is left (IncrementMeasure::over).
  virtual double expected_share() const { return 1; }
  /// Where a body's nodes go after each step when its material flows through a mesh held in place (an ALE run,
  /// analysis/AleStep), or null: the run is Lagrangian.
  virtual const MeshMotion* mesh_motion() const { return nullptr; }
  /// Its measures of `results` (every completed increment): tables, charts, summary section, report.
  virtual ProcessResults finish(const Results& results) const = 0;
};

class Process {
 public:
  virtual ~Process() = default;
  virtual std::string name() const = 0;  // process.type
  /// The section's fields (its variant of the `process` object; `type` is the registry's).
  virtual const ObjectSchema& schema() const = 0;
  /// Checks of the validated project's section that need more than one field or more of the project (keys the
  /// process would ignore), as issues at the user's paths (`process.<field>`), never a generated body's.
  virtual void check(const json& project, std::vector<Issue>& issues) const = 0;
  /// `project` with what the section generates appended (bodies, materials, contacts, conditions, increments).
  virtual json expand(const json& project) const = 0;
  /// How the user makes its steps smaller, in the section's terms with the current value (a diverged run's advice;
  /// NewtonOptions::smaller_steps).
  virtual std::string smaller_steps(const json& section) const = 0;
  /// How far a run is at load factor `fraction` (0…1), in the section's terms ("travel 12.5 of 120 mm"): a
  /// progress that counts the process, not the increments (whose count grows with every cut-back).
  virtual std::string progress(const json& section, double fraction) const = 0;
  /// The files its runs write (tables and charts): an output folder's earlier run is cleared of them.
  virtual std::vector<std::string> outputs() const = 0;
  /// The run on `model`, built from expand(project).
  virtual std::unique_ptr<ProcessRun> start(const json& section, const Model& model) const = 0;
};

}  // namespace rollsim
