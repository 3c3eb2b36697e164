#pragma once
// rolling.csv: one row per completed increment of a rolling pass (travel, roll force, torque, contact length or area,
// exit thickness, forward slip, spread), in the process's units (mm, N; 2D per unit width).
#include <string>

#include "analysis/RollingResults.h"

namespace rollsim {

std::string rolling_csv(const RollingResults& rolling);

/// contact_profile.csv: the slab's contact nodes at the last increment, entry first: angle from the roll's lowest
/// point [degree], x and (3D) width position [mm], pressure and shear along the roll's surface toward the exit [MPa].
std::string contact_profile_csv(const RollingResults& rolling);

}  // namespace rollsim
