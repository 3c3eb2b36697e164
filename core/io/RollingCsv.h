#pragma once
// rolling.csv: one row per completed increment of a rolling pass (travel, roll force, torque, contact length or area,
// exit thickness, forward slip, spread), in the process's units (mm, N; 2D per unit width).
#include <string>

#include "analysis/RollingResults.h"

namespace rollsim {

std::string rolling_csv(const RollingResults& rolling);

}  // namespace rollsim
