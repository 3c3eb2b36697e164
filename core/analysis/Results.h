#pragma once
// Fields and scalars produced by an analysis, per body; read by the writers.
#include <Eigen/Dense>
#include <array>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/Measures.h"
#include "base/RunStatus.h"
#include "solve/AutoChoice.h"
#include "solve/SolveStats.h"

namespace rollsim {

struct Model;

struct BodyResults {
  Eigen::VectorXd displacement;  // node-major, dim components per node [length]
  Eigen::VectorXd nodal_force;   // internal minus external force at every dof: reactions at supports [force]
  std::vector<std::array<double, 6>> element_stress;  // element mean (xx, yy, zz, xy, yz, zx) [stress]
  std::vector<std::array<double, 6>> nodal_stress;    // extrapolated from Gauss points, averaged at nodes
  std::vector<int> subdomain;                         // per element (0 while bodies are not partitioned)
  std::vector<double> plastic_strain;  // per element: mean equivalent plastic strain (plastic bodies only) [-]
  // per element: mean temperature, the material's plus the rise from plastic work (bodies whose material has a flow
  // stress law or a heat capacity only), or the mean of its nodes' in a body that conducts heat [°C]
  std::vector<double> temperature;
  Eigen::VectorXd nodal_temperature;  // per node, bodies that conduct heat (analysis/HeatConduction) [°C]
  // per node, sized only when the model has contact pairs: f·n / tributary length (2D) or area (3D) of each
  // contact point of a slave surface (positive in compression), 0 on every other node [stress]
  Eigen::VectorXd contact_pressure;
  Eigen::VectorXd contact_slip;  // per node, sized like contact_pressure: tangential sliding so far [length]
  // per node, dim components (node-major), sized with contact_pressure: the tangential part of the contact force on
  // each slave point over its tributary measure — the friction (shear) traction on the slave surface [stress]
  Eigen::VectorXd contact_shear;
  // every integration point's committed state (element-major, the material's state_size() each), kept only where a
  // run stopped for a remesh (analysis/Remeshing carries it to the next segment)
  std::vector<double> point_state;
};

/// Resultants of one contact pair on its slave surface (forces on the slave body).
struct ContactResult {
  std::string name;
  double normal_force = 0;      // Σ f·n, positive in compression [force]
  double tangential_force = 0;  // |Σ (f − (f·n) n)| [force]
  double max_pressure = 0;      // max of f·n / tributary measure [stress]
  double measure = 0;           // contact length (2D) / area (3D) of the active points [length / length²]
  int active_nodes = 0, candidate_nodes = 0;
};

/// One load increment: every load and prescribed displacement times `load_factor`, solved to equilibrium (its own
/// active-set loop), with the fields and contact resultants of that state.
struct IncrementResults {
  double load_factor = 1;         // i / N (Newton: where the step ended, after any cut-back)
  int active_set_iterations = 0;  // linear solves of this increment's active-set loop (Newton: its iterations)
  int newton_iterations = 0;      // Newton driver: iterations of the converged attempt (0: linear driver)
  int cutbacks = 0;               // Newton driver: failed attempts before this step converged
  long cg_iterations = 0;         // interface CG iterations of those solves (0 for direct strategies)
  std::vector<BodyResults> bodies;
  std::vector<ContactResult> contacts;
  // the model these fields belong to when it is not the run's own: a remeshed run's later segments (null: the run's)
  std::shared_ptr<const Model> model;
};

/// A Newton run that stopped for a remesh (NewtonOptions::remesh_quality): the body and its element whose smallest
/// corner Jacobian ratio fell below the limit after the last converged step.
struct RemeshDue {
  int body = -1, element = -1;
  double quality = 1;
};

/// One remesh of a run (analysis/Remeshing), as summary.json lists it.
struct RemeshRecord {
  int increment = 0;        // the converged increments before it
  double load_factor = 0;   // where it happened, on the run's load factor
  std::string body;         // the body whose nodes were moved back to their spread
  int element = -1;         // its element whose quality fell below the limit
  double quality = 1;       // that element's smallest corner Jacobian ratio against the segment's start [-]
  double shape_before = 1;  // the body's worst corner sine (1: right angles, 0: a folded corner) before the move
  double shape_after = 1;   // and after it
  std::string nodes_kept;   // why its nodes stayed where they were (the run went on from there); "": moved
  // the check field, the equivalent plastic strain: its integral over the body [volume] and largest value [-], before
  // and after the transfer (a conservative, bounded transfer keeps the first and never raises the second)
  double plastic_strain_integral_before = 0, plastic_strain_integral_after = 0;
  double plastic_strain_max_before = 0, plastic_strain_max_after = 0;
  // the body's volume mean temperature before and after the transfer (a body with temperatures; NaN: none) [°C]
  double mean_temperature_before = std::numeric_limits<double>::quiet_NaN();
  double mean_temperature_after = std::numeric_limits<double>::quiet_NaN();
};

/// One Newton iteration, as convergence.csv lists it.
struct NewtonIteration {
  int increment = 0;  // converged steps before it + 1
  int attempt = 0;    // 0, then 1, 2, … after cut-backs of this step
  int iteration = 0;  // 1-based within the attempt
  double load_factor = 0;
  double residual = 0;      // ‖f_ext − f_int − Cᵀλ‖ at the iterate before this iteration's solve [force]
  double relative = 0;      // residual / the attempt's first residual
  double correction = 0;    // ‖du‖ of this iteration's solve [length]
  double step_length = 1;   // η of the line search that followed (1: the full step kept)
  int refactored = 0;       // groups given a new tangent (and factor) for this iteration's solve
  int contact_changes = 0;  // frictionless statuses changed by this iteration's solve
  long cg_iterations = 0;   // interface CG iterations of this iteration's solve
  std::string tangents;     // every group's tangent choice and why (base/Observer.h: describe)
};

struct Timing {
  double total_s = 0, stiffness_s = 0, analyze_s = 0, factorize_s = 0, solve_s = 0, recovery_s = 0;
  double heat_s = 0;            // the heat steps (analysis/HeatConduction): assembly, factorization and solve
  int heat_factorizations = 0;  // of the heat system, one per converged step
};

struct Results {
  // How the run ended (base/RunStatus.h); only a converged run is a result. A cancelled run holds the fields of its
  // last iterate: the last completed linear solve when the cancel came between solves, or the interrupted CG's current
  // iterate (every group in equilibrium with it, Gᵀλ = e met, the constraints C u = d not yet to tolerance); no bodies
  // when it came before the first solve. A run that did not converge holds the increments it completed and no fields of
  // the failed one.
  RunStatus status;
  std::vector<BodyResults> bodies;
  long dofs = 0;
  long multipliers = 0;  // contact multipliers of the last solve
  long rigid_modes = 0;  // floating-body and floating-subdomain modes handled by the solver
  long subdomains = 0;   // groups of the block system (bodies, or their subdomains under feti)
  long interface_multipliers = 0, paper_convention_multipliers = 0;
  int active_set_iterations = 0;  // linear solves of every increment's active-set loop together
  std::vector<ContactResult> contacts;
  // Load increments requested (analysis.increments) and the ones completed, in order, each with its fields. After a
  // converged (or diverged) run the last entry equals `bodies` / `contacts` — what the writers of a single state
  // read; after a cancel `bodies` may hold an interrupted increment that `increments` does not list.
  int load_increments = 1;
  std::vector<IncrementResults> increments;
  Timing timing;
  SolveStats solver;  // what the solver strategy counted over the whole run (factorizations, CG iterations, …)
  // Newton driver only: every iteration, and the tangent (stiffness) evaluations per group
  std::vector<NewtonIteration> newton;
  std::map<std::string, long> stiffness_evaluations;
  std::optional<AutoChoice> auto_choice;  // solver.mode was `auto`: what it chose and why
  std::string update_policy;  // the Newton driver's update policy (`always`, `selective:0.01`); empty: linear
  std::optional<ProcessResults> process;  // a process's measures over the completed increments (process/)
  std::vector<std::string> warnings;      // what the run met that the user should know (summary.json's `warnings`)
  // remeshing (analysis.remesh_quality): why a segment stopped (Newton driver), the remeshes of the whole run, and
  // the model of `bodies` when it is not the run's own (null: the run's)
  std::optional<RemeshDue> remesh_due;
  std::vector<RemeshRecord> remeshes;
  int ale_steps =
      0;  // an ALE run (analysis/AleStep): the steps after which a body's mesh was put back under its material
  std::shared_ptr<const Model> model;
};

/// The model the fields of `increment` belong to: the run's own, or a later segment's after a remesh.
inline const Model& model_of(const IncrementResults& increment, const Model& run_model) {
  return increment.model ? *increment.model : run_model;
}

}  // namespace rollsim
