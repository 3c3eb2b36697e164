// The registry of solver strategies (names feed validation, CLI help and the GUI).
#include <stdexcept>

#include "solve/GlobalDirect.h"
#include "solve/MixedStrategy.h"
#include "solve/PetscStrategy.h"
#include "solve/SolverStrategy.h"

namespace rollsim {

const std::vector<StrategyInfo>& solver_registry() {
  static const std::vector<StrategyInfo> registry = {
      {"skyline", "global matrix, active-column LDL^T with reverse Cuthill-McKee ordering (the paper's ACTCOL)",
       [](const SolverOptions&) { return std::make_unique<GlobalDirect>("skyline"); }},
      {"direct",
       "global matrix, CHOLMOD supernodal Cholesky with AMD/METIS ordering (modern baseline); with contact multipliers "
       "UMFPACK LU",
       [](const SolverOptions&) { return std::make_unique<GlobalDirect>("cholmod"); }},
      {"mixed",
       "each body factored on its own (CHOLMOD), CG on the condensed contact interface, projected CG for floating "
       "bodies (the paper's mixed method)",
       [](const SolverOptions& o) { return std::make_unique<MixedStrategy>(o); }},
      {"feti",
       "FETI: partitioned bodies torn into subdomains, each factored on its own, projected CG on the subdomain and "
       "contact multipliers with an optional lumped / Dirichlet preconditioner",
       [](const SolverOptions& o) { return std::make_unique<MixedStrategy>(o, true); }},
      {"petsc",
       "PETSc (optional build) over MPI (mpirun -n P), linear or Newton: the subdomains as an unassembled MATIS "
       "matrix, one per rank, solved by PCBDDC in CG or KSPFETIDP (contact-free); with contact of every kind, the "
       "paper's mixed method with each rank's own groups, or paper eq. (1) whole factored by MUMPS on any number of "
       "ranks (--petsc-method)",
       [](const SolverOptions& o) { return make_petsc_strategy(o); }},
  };
  return registry;
}

std::string one_of(const std::vector<std::string>& words) {
  std::string s;
  for (size_t i = 0; i < words.size(); ++i) s += (i == 0 ? "" : i + 1 == words.size() ? " or " : ", ") + words[i];
  return s;
}

std::vector<std::string> solver_names() {
  std::vector<std::string> names;
  for (const auto& s : solver_registry()) names.push_back(s.name);
  return names;
}

std::vector<std::string> solver_mode_names() {
  std::vector<std::string> names = solver_names();
  names.push_back(kAutoSolver);
  return names;
}

std::unique_ptr<SolverStrategy> make_solver(const std::string& name, const SolverOptions& options) {
  for (const auto& s : solver_registry())
    if (s.name == name) return s.make(options);
  if (name == kAutoSolver)  // a caller's mistake, not the user's: run_project resolves `auto` first
    throw std::invalid_argument("solver 'auto' names no strategy: choose_solver_mode resolves it from the model");
  std::string valid;
  for (const auto& n : solver_mode_names()) valid += (valid.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown solver '" + name + "' (valid: " + valid + ")");
}

}  // namespace rollsim
