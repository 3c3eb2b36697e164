#pragma once
// The closed forms a rolling pass is checked against (docs/VALIDATION.md), computed from the pass's geometry and
// the slab's flow stress: Sims (1954) for roll force, torque and forward slip with sticking friction, the friction-
// hill estimate of a homogeneously compressed slab with sticking friction, Hitchcock's flattened roll radius
// (1935) and, in 3D, Wusatowski's spread (1955). Plane strain, whole slab thicknesses h0 → h1 (two rolls), per unit
// width; 3D: times the slab's width.
#include <string>

#include "process/rolling/RollingPass.h"

namespace rollsim {

struct RollingTheory {
  double bite_angle = 0;              // α, cos α = 1 − Δh / 2R [rad]
  double contact_length = 0;          // projected arc L = √(R Δh) [length]
  double neutral_angle = 0;           // Sims's φ_n [rad]
  double sims_force = 0;              // roll force 2k L Q_p [force (per unit width in 2D)]
  double sims_torque = 0;             // torque per roll 2k R² (α/2 − φ_n) [force · length (per unit width in 2D)]
  double sims_forward_slip = 0;       // h_n / h1 − 1, h_n = h1 + R φ_n² [-]
  double friction_hill_force = 0;     // 2k L (1 + L / (4 h̄)), h̄ = (h0 + h1) / 2 [force (per unit width in 2D)]
  double hitchcock_radius_ratio = 1;  // R′/R = 1 + 16 (1 − ν²) F_Sims / (π E Δh) (elastic roll; 1 for a rigid one)
  // Wusatowski: b1 = b0 (h0/h1)^W, W = 10^(−1.269 (b0/h0) (h0/2R)^0.556), his factors for steel, speed, friction and
  // roll material taken as 1; spread b1 − b0 [length] (3D; 0 in plane strain)
  double wusatowski_spread = 0;
};

/// The closed forms of `pass` (its geometry, the slab's flow stress, the roll's elasticity).
RollingTheory rolling_theory(const RollingPass& pass);

/// The roll's surface travel after which the slab's rear end enters the roll gap (x = −L): its material, L_slab − L
/// from there, enters at h1 (1 + Sims's forward slip) / h0 times the roll's surface speed (continuity).
double travel_through(const RollingPass& pass);

/// Whether the roll can draw the slab in (the bite condition μ ≥ tan α): "" when it can (sticking friction always
/// can), else the refusal with the numbers — μ, tan α, α, and the largest draft this μ bites, 2R (1 − cos(atan μ)).
std::string bite_refusal(const RollingPass& pass);

}  // namespace rollsim
