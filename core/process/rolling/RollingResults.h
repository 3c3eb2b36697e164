#pragma once
// What a rolling pass reports (process/rolling/RollingMeasures computes it from the increments' fields): per increment
// the roll force, torque, contact length, exit thickness, forward slip and spread, and where the roll bit and the pass
// reached steady state. Whole-slab values: the symmetry halves are counted back in (2D: per unit width).
#include <vector>

namespace rollsim {

struct RollingIncrement {
  double travel = 0;          // roll surface travel R θ so far [length]
  double roll_force = 0;      // force of the slab on the roll along the thickness, away from the slab [force]
  double roll_torque = 0;     // torque on the roll's hub about its axis that drives it [force · length]
  double contact_length = 0;  // arc of contact (2D) [length] / contact area (3D) [length²]
  double exit_thickness = 0;  // whole slab thickness just past the exit plane (0: nothing there yet) [length]
  // slab front's advance / roll surface travel − 1 over the last tenth of a nominal contact length √(R Δh) of travel
  // (from the start before that) [-]
  double forward_slip = 0;
  double spread = 0;  // 3D: whole width past the exit (its widest point) − entry width (0 in 2D) [length]
  // 3D: the same with the section's mean width: the side face's position averaged over the thickness (0 in 2D) [length]
  double mean_spread = 0;
  double volume_change = 0;  // the slab's current volume (area in 2D) / its initial one − 1 [-]
  double mean_pressure = 0;  // roll force / contact length (2D) or area (3D): the mean pressure on the arc [stress]
  double roll_power = 0;     // torque × ω per roll (0 without a roll speed) [kW (per mm of width in 2D)]
  // with a slab temperature (a flow stress law, a heat capacity or heat conduction) [°C]:
  double slab_temperature = 0;     // the slab's mean, weighted by volume
  double surface_temperature = 0;  // the slab's top surface just past the exit plane (0 < x ≤ √(R Δh)), mean
  double roll_temperature = 0;     // the roll's surface, hottest node (its material's temperature unless it conducts)
};

/// One slab node in contact along the arc, in the rolling plane (3D: every node of the contact zone, across the
/// width): where it is and the tractions on the slab there.
struct ArcPoint {
  double angle = 0;     // from the roll's lowest point about its axis, positive toward the entry [degree]
  double x = 0;         // current position along the rolling direction (exit plane at 0) [length]
  double width = 0;     // 3D: current position across the width (symmetry plane at 0); 2D: 0 [length]
  double pressure = 0;  // normal contact pressure [stress]
  double shear = 0;     // friction traction along the roll's surface in the rolling direction, on the slab [stress]
};

struct RollingResults {
  bool thermal = false;  // the slab has a temperature: the temperature measures are reported
  std::vector<RollingIncrement> increments;
  std::vector<ArcPoint> profile;   // contact along the arc at the last increment, by angle
  int bite_increment = 0;          // first increment whose travel drew the slab in (0: the roll did not bite)
  int steady_state_increment = 0;  // first increment from which force and torque stay settled (0: not reached)
  RollingIncrement steady;         // travel-weighted mean from the steady state on (not reached: the last increment)
};

}  // namespace rollsim
