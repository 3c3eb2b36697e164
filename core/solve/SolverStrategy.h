#pragma once
// A solver strategy solves the block system; strategies are chosen by name from a registry
// whose names also feed validation, the CLI help and (later) the GUI.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "solve/BlockSystem.h"
#include "solve/Observer.h"
#include "solve/SolveStats.h"

namespace rollsim {

struct SolverOptions {
  double cg_tolerance = 1e-4;
  int threads = 1;                           // groups factored and solved concurrently (mixed / feti)
  std::string preconditioner = "none";       // interface preconditioner: none, lumped, dirichlet (feti)
  std::string multipliers = "nonredundant";  // subdomain glue: nonredundant, redundant (feti)
  std::string projector = "identity";        // metric Q of the rigid-mode projector with a preconditioner:
                                             // identity (Q = I, the paper's) or preconditioner (Q = M⁻¹)
  std::string interface_start = "zero";      // mixed / feti: the interface CG starts from BlockSystem::lambda_start
                                             // (previous) or from the least-norm feasible λ (zero, the paper's)
  std::string interface_solver = "krylov";   // mixed / feti: projected CG / GMRES (krylov, the paper's) or F formed
                                             // and factored (dense: InterfaceFlexibility, DenseInterfaceSolve)
  std::string petsc_method = "bddc";         // petsc: bddc (PCBDDC in CG) or fetidp (KSPFETIDP)
  std::string petsc_options;                 // petsc: options passed through to PETSc, e.g. "-ksp_monitor"
};

class SolverStrategy {
 public:
  virtual ~SolverStrategy() = default;
  /// Solves the constrained block system (paper eq. (1)) as linear solve number stats().solves + 1, reporting to
  /// `observer` (may be null) its factorizations, CG iterations and end; iterative strategies stop at the observer's
  /// cancel request and return their last iterate (BlockSolution::cancelled).
  virtual BlockSolution solve(const BlockSystem& system, AnalysisObserver* observer = nullptr) = 0;
  virtual const SolveStats& stats() const = 0;
  /// True when the strategy wants partitioned bodies torn into subdomain groups (feti).
  virtual bool uses_subdomains() const { return false; }
  /// Relative accuracy of the multipliers it returns (of the largest |λ|): what decides that a multiplier is zero.
  virtual double multiplier_tolerance() const { return 1e-10; }
  virtual const SolverOptions& options() const {
    static const SolverOptions defaults;
    return defaults;
  }
  /// The groups among `groups` this process assembles (all of them; petsc: its MPI rank's subdomain only — the
  /// other ranks build the others).
  virtual std::vector<size_t> local_groups(std::vector<size_t> groups) const { return groups; }
  /// True when it solves systems whose groups carry C_eq ≠ C (the unsymmetric coupling of slipping Coulomb friction);
  /// the Newton driver lags the friction force one iteration behind the normal force for the others.
  virtual bool solves_unsymmetric() const { return false; }
  /// True when it assembles one global matrix, which can take stiffness joining two groups (BlockSystem::coupling).
  virtual bool assembles_globally() const { return false; }
  /// Why the strategy cannot solve a model with contact pairs ("" when it can): asked before the first solve, since
  /// a frictionless pair may start with no active row.
  virtual std::string contact_refusal() const { return ""; }
};

struct StrategyInfo {
  std::string name;
  std::string description;
  std::function<std::unique_ptr<SolverStrategy>(const SolverOptions&)> make;
};

/// The words of each solver option, named once: the schema, the CLI's checks and help, and the strategies read them.
const std::vector<std::string>& preconditioner_names();    // none, lumped, dirichlet
const std::vector<std::string>& multiplier_names();        // nonredundant, redundant
const std::vector<std::string>& projector_names();         // identity (Q = I), preconditioner (Q = M⁻¹)
const std::vector<std::string>& petsc_method_names();      // bddc, fetidp
const std::vector<std::string>& interface_start_names();   // zero, previous (the last Newton iteration's λ)
const std::vector<std::string>& interface_solver_names();  // krylov, dense
/// "a, b or c": for messages that list the valid words.
std::string one_of(const std::vector<std::string>& words);

/// All strategies, in the order shown to users.
const std::vector<StrategyInfo>& solver_registry();
std::vector<std::string> solver_names();
/// `solver.mode: auto` (project/SolverChoice.h chooses a registry name from the model).
inline constexpr const char* kAutoSolver = "auto";
/// The values of solver.mode and --solver: the registry's names, then `auto`.
std::vector<std::string> solver_mode_names();
/// Throws std::invalid_argument listing the valid names (`auto` among them) for an unknown name, and for `auto`.
std::unique_ptr<SolverStrategy> make_solver(const std::string& name, const SolverOptions& options);

}  // namespace rollsim
