#pragma once
// A solver strategy solves the block system; strategies are chosen by name from a registry
// whose names also feed validation, the CLI help and (later) the GUI.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "base/Observer.h"
#include "solve/BlockSystem.h"
#include "solve/SolveStats.h"
#include "solve/SolverOptions.h"

namespace rollsim {

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
  /// True when it takes compliant rows (BlockSystem::compliance: stiffness joining two groups, as rows with a
  /// multiplier of their own) on a system without torn bodies.
  virtual bool solves_compliant() const { return false; }
  /// Why the strategy cannot solve a model with contact pairs ("" when it can): asked before the first solve, since
  /// a frictionless pair may start with no active row.
  virtual std::string contact_refusal() const { return ""; }
};

struct StrategyInfo {
  std::string name;
  std::string description;
  std::function<std::unique_ptr<SolverStrategy>(const SolverOptions&)> make;
};

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
