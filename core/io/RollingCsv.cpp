#include "io/RollingCsv.h"

#include <sstream>

namespace rollsim {

std::string rolling_csv(const RollingResults& rolling) {
  std::ostringstream out;
  out.precision(10);
  out << "increment,travel,roll_force,roll_torque,contact_length,exit_thickness,forward_slip,spread,mean_spread,volume_"
         "change\n";
  for (size_t i = 0; i < rolling.increments.size(); ++i) {
    const RollingIncrement& r = rolling.increments[i];
    out << i + 1 << ',' << r.travel << ',' << r.roll_force << ',' << r.roll_torque << ',' << r.contact_length << ','
        << r.exit_thickness << ',' << r.forward_slip << ',' << r.spread << ',' << r.mean_spread << ','
        << r.volume_change << '\n';
  }
  return out.str();
}

std::string contact_profile_csv(const RollingResults& rolling) {
  std::ostringstream out;
  out.precision(10);
  out << "angle,x,width,pressure,shear\n";
  for (const ArcPoint& p : rolling.profile)
    out << p.angle << ',' << p.x << ',' << p.width << ',' << p.pressure << ',' << p.shear << '\n';
  return out.str();
}

}  // namespace rollsim
