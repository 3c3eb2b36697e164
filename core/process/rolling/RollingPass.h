#pragma once
// A rolling pass as the model knows it (built from the project's `process`): which bodies are the slab and the roll,
// which prescribed motion turns the roll, and the nominal pass geometry the rolling quantities are measured against.
#include <string>
#include <utility>
#include <vector>

#include "mesh/RadiusProfile.h"

namespace rollsim {

struct RollingPass {
  int slab = 0, roll = 1;                          // body indices
  int hub = 0;                                     // index in Model::displacements of the hub's rigid rotation
  int thickness_axis = 1;                          // y in 2D, z in 3D (the slab's mid-plane at 0)
  int width_axis = -1;                             // y in 3D (width symmetry plane at 0), −1 in 2D
  bool half_width = false;                         // 3D: the model holds half the width (y ≥ 0)
  double radius = 0;                               // roll radius R [length]
  double entry_thickness = 0, exit_thickness = 0;  // nominal h0 and h1 of the whole slab [length]
  double width = 0;                                // whole slab width b0 (3D) [length]
  double slab_length = 0;                          // the slab's length before the pass [length]
  // process.formulation ale: the slab's mesh a window held around the roll gap, from x = −ale_entry to ale_exit (the
  // exit plane at x = 0), its material flowing through (RollingAle, RollingAle3d); false: Lagrangian, the slab rolled
  // through
  bool ale = false;
  double ale_entry = 0, ale_exit = 0;  // [length]
  int ale_columns = 0;                 // the uniform window's elements along x (process.slab_nx)
  double ale_grading = 1;              // the zones' columns growing by this ratio away from the arc (1: uniform)
  bool stop_at_steady = false;         // the run ends once force and torque are steady (steady_state_from)
  double rpm = 0;                      // roll speed [1/min] (0: not given)
  double travel = 0;                   // roll surface travel R θ at load factor 1 [length]
  // the slab's σ_0, or with a flow stress law its mean over the pass: over ε from 0 to (2/√3) ln(h0/h1) at the mean
  // rate ε ωR / √(R Δh) (Δh = h0 − h1) and the slab's temperature [stress]
  double flow_stress = 0;
  std::string flow_law;              // the slab's flow stress law ("": σ_0 and linear hardening)
  double temperature = 0;            // the slab's temperature with a law [°C]
  double mean_strain_rate = 0;       // the rate its mean flow stress is taken at [1/s]
  double roll_E = 0, roll_nu = 0.3;  // the roll's elasticity (E 0: a rigid roll) [stress, -]
  bool roll_fixed = false;           // the roll's mesh stays, its surface's material turns (process.roll_mesh: fixed)
  double friction = -1;  // Coulomb's μ of the roll–slab contact (frictionless: 0); −1: sticking (always bites) [-]
  RadiusProfile profile;  // 3D: the radius's change (≤ 0) by distance from the barrel's centre [length]
  // a schedule's passes (process.passes) as its facts list them, each {draft, roll}; empty: a single pass
  std::vector<std::pair<std::string, std::string>> schedule;
};

}  // namespace rollsim
