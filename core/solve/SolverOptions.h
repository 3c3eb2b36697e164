#pragma once
// The options of the solver strategies, typed, and the table that declares them to the project schema (the solver
// section, beside `mode` and `update`): every choice an enum with its words, every default the member's initializer,
// every field's range and documentation its bind(...) line. A new option is a member, its line in the table and the
// code that reads it. Header-only: the petsc module, which links nothing of rollsim_core, reads the same type.
#include <string>
#include <vector>

#include "base/BoundField.h"
#include "base/SchemaFields.h"
#include "base/Words.h"
#include "solve/PetscOptionsCheck.h"

namespace rollsim {

enum class Preconditioner { None, Lumped, Dirichlet };    // feti's interface preconditioner
enum class GlueMultipliers { NonRedundant, Redundant };   // feti's subdomain glue: k − 1 or k(k − 1)/2 rows per dof
enum class ProjectorMetric { Identity, Preconditioner };  // Q of the rigid-mode projector: I (the paper's) or M⁻¹
enum class InterfaceStart { Zero, Previous };             // where a Newton iteration's interface Krylov solve starts
enum class InterfaceSolver { Krylov, Dense };             // projected CG / GMRES, or F formed and factored
enum class PetscMethod { Bddc, FetiDp, Mumps, Mixed };    // PCBDDC in CG, KSPFETIDP, MUMPS on eq. (1), mixed over MPI

template <>
inline const std::vector<std::string>& words<Preconditioner>() {
  static const std::vector<std::string> w{"none", "lumped", "dirichlet"};
  return w;
}
template <>
inline const std::vector<std::string>& words<GlueMultipliers>() {
  static const std::vector<std::string> w{"nonredundant", "redundant"};
  return w;
}
template <>
inline const std::vector<std::string>& words<ProjectorMetric>() {
  static const std::vector<std::string> w{"identity", "preconditioner"};
  return w;
}
template <>
inline const std::vector<std::string>& words<InterfaceStart>() {
  static const std::vector<std::string> w{"zero", "previous"};
  return w;
}
template <>
inline const std::vector<std::string>& words<InterfaceSolver>() {
  static const std::vector<std::string> w{"krylov", "dense"};
  return w;
}
template <>
inline const std::vector<std::string>& words<PetscMethod>() {
  static const std::vector<std::string> w{"bddc", "fetidp", "mumps", "mixed"};
  return w;
}

struct SolverOptions {
  double cg_tolerance = 1e-4;  // relative residual of the interface Krylov solve (mixed / feti; petsc's rtol); the
                               // project's unset value under Newton: RunConfig's rule
  int threads = 1;             // groups factored and solved concurrently (mixed / feti), BLAS threads
  Preconditioner preconditioner = Preconditioner::None;
  GlueMultipliers multipliers = GlueMultipliers::NonRedundant;
  ProjectorMetric projector = ProjectorMetric::Identity;
  InterfaceStart interface_start = InterfaceStart::Zero;  // Previous: from BlockSystem::lambda_start
  InterfaceSolver interface_solver = InterfaceSolver::Krylov;
  PetscMethod petsc_method = PetscMethod::Bddc;
  std::string petsc_options;             // petsc: options passed through to PETSc, e.g. "-ksp_monitor"
  int max_interface_iterations = 10000;  // mixed / feti: iterations of one interface CG / GMRES before it gives up
};

/// The solver section's option fields, in the order shown to users.
inline const std::vector<BoundField<SolverOptions>>& solver_option_fields() {
  using namespace schema;
  using S = SolverOptions;
  static const std::vector<BoundField<S>> table = {
      bind(flag(count("threads", "threads for the factorization (BLAS) and parallel groups", 256), "threads"),
           &S::threads),
      bind(flag(str("preconditioner",
                    "interface preconditioner of `feti` (none: the paper's unpreconditioned "
                    "projected CG)"),
                "preconditioner"),
           &S::preconditioner),
      bind(str("multipliers",
               "subdomain glue of `feti`: nonredundant (k − 1 constraints per dof shared by k subdomains, the paper's) "
               "or redundant (all k(k − 1)/2 pairs)"),
           &S::multipliers),
      bind(
          flag(str("projector",
                   "metric Q of the rigid-mode projector P = I − QG(GᵀQG)⁻¹Gᵀ of `feti` with a preconditioner: "
                   "identity (Q = I, the paper's; always without a preconditioner) or preconditioner (Q = M⁻¹: 15–25 % "
                   "fewer iterations, but M⁻¹G costs a preconditioner solve per floating neighbour's mode, once per "
                   "factorization)"),
               "projector"),
          &S::projector),
      bind(str("interface_start",
               "where the interface CG / GMRES of `mixed` and `feti` starts in a Newton analysis: zero (the "
               "least-norm λ with Gᵀλ = e, the paper's) or previous (the last iteration's multipliers of the rows "
               "that stay, its tolerance still relative to the zero start's residual: 27–30 % fewer CG iterations on "
               "the 3D pass, the roll force within 5e-6 of zero's, docs/BENCHMARKS-ROLLING.md)"),
           &S::interface_start),
      bind(flag(str("interface_solver",
                    "how `mixed` and `feti` solve their condensed interface problem: krylov (projected CG, or GMRES "
                    "when slipping friction makes it unsymmetric; the paper's, F never formed) or dense (F formed "
                    "from each group's flexibility on the dofs its constraints touch — one block solve per touched "
                    "dof, kept while the group keeps its factor — and factored by dense LU: exact λ, for interfaces "
                    "of up to a few thousand multipliers)"),
                "interface-solver"),
           &S::interface_solver),
      bind(flag(str("petsc_method",
                    "method of `petsc`: bddc (PCBDDC preconditioning CG on the whole problem) or fetidp (KSPFETIDP: "
                    "CG on the FETI-DP multipliers, the inner BDDC's coarse space), contact-free, run as mpirun -n P "
                    "with one subdomain per rank; or mumps (paper eq. (1) whole — stiffness, contact and glue rows — "
                    "as one distributed matrix factored by MUMPS's LU: contact of every kind, any number of ranks, "
                    "each assembling the tangents of its share of the groups); or mixed (the paper's mixed method "
                    "over MPI: each rank assembles and factors its own groups — bodies, or a partition's "
                    "subdomains — with CHOLMOD, only those whose tangent changed, and every rank runs the projected "
                    "CG / GMRES on the contact and glue multipliers, its products summed over the ranks)"),
                "petsc-method"),
           &S::petsc_method),
      bind(
          [] {
            Field f = flag(str("petsc_options",
                               "`petsc`: options passed through to PETSc (e.g. \"-ksp_monitor -pc_bddc_use_faces\"); "
                               "an option PETSc does not use is refused, and so is one that names a file or starts a "
                               "program (`-ksp_monitor ascii:FILE`, `-log_view :FILE`, `-options_file`, debuggers)"),
                           "petsc-options");
            f.check = [](const nlohmann::json& v) { return petsc_options_problem(v.get<std::string>()); };
            return f;
          }(),
          &S::petsc_options),
      without_default(bind(flag(below(positive("cg_tolerance", "-",
                                               "relative residual tolerance of the interface CG (mixed/feti; petsc: "
                                               "its Krylov solver's rtol). Unset: 1e-4 in a linear analysis; under "
                                               "Newton with analysis.forcing fixed analysis.tolerance / 100 (1e-10 "
                                               "by default), since the constraint error a looser solve leaves keeps "
                                               "Newton's checks from being met (a looser one is warned of); under "
                                               "eisenstat_walker the loosest tolerance of an iteration (unset: 1e-5; "
                                               "project/RunConfig)"),
                                      1.0),
                                "cg-tolerance"),
                           &S::cg_tolerance)),
      bind(flag(count("max_interface_iterations",
                      "iterations one interface CG / GMRES of `mixed` and `feti` may take; a solve still short of "
                      "cg_tolerance after them ends not_converged (iteration_limit), or cuts a Newton step back",
                      1e6),
                "max-interface-iterations"),
           &S::max_interface_iterations),
  };
  return table;
}

}  // namespace rollsim
