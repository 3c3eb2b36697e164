#pragma once
// Projected GMRES on an unsymmetric interface problem — slipping Coulomb friction solved consistently under `mixed`
// and `feti`, where the multipliers enter the groups' equations through C_eq ≠ C (contact/Friction slip_coupling):
//   F λ − G α = b,   G̃ᵀ λ = e,   F = Σ C_g K_g⁺ C_eq,gᵀ,   G = [C_g R_g],   G̃ = [C_eq,g R_g],   e = [R_gᵀ f_g].
// It starts from λ0 = G(G̃ᵀG)⁻¹e (G̃ᵀλ0 = e) and projects with Π = I − G(G̃ᵀG)⁻¹G̃ᵀ, which removes the modes'
// columns (ΠG = 0) and maps onto ker G̃ᵀ (G̃ᵀΠ = 0), where it is the identity: GMRES (Saad, Iterative Methods §6.5:
// Arnoldi with modified Gram–Schmidt, Givens rotations, restarted every kRestart iterations) on Π F over ker G̃ᵀ, right
// preconditioned by Π M⁻¹; then α = −(G̃ᵀG)⁻¹G̃ᵀ(b − Fλ). With G̃ = G, Π is ProjectedCG's Euclidean projector.
#include "solve/ProjectedCG.h"

namespace rollsim {

/// The residuals reported are ‖Π(b − Fλ_k)‖ / ‖Π(b − Fλ_0)‖ (GMRES's own estimate within a cycle, the true one at
/// its end); lambda_min / lambda_max stay 0. Throws SingularMatrix (column −1) when G̃ᵀG is singular.
ProjectedCGResult projected_gmres(const InterfaceProblem& problem, const ProjectedCGOptions& options,
                                  AnalysisObserver* observer = nullptr);

}  // namespace rollsim
