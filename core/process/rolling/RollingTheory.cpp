#include "process/rolling/RollingTheory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rollsim {

RollingTheory rolling_theory(const RollingPass& pass) {
  RollingTheory t;
  const double R = pass.radius, h0 = pass.entry_thickness, h1 = pass.exit_thickness, draft = h0 - h1;
  const double r = draft / h0, k2 = 2 * pass.flow_stress / std::sqrt(3.0);  // plane-strain flow stress 2k
  const double width = pass.width_axis >= 0 ? pass.width : 1.0;
  t.bite_angle = std::acos(1 - draft / (2 * R));
  t.contact_length = std::sqrt(R * draft);
  // Sims: the neutral angle, then Q_p (Roberts, Cold Rolling of Steel, 1978, eqs. for sticking friction)
  const double a = std::sqrt((1 - r) / r), b = std::sqrt(r / (1 - r)), s = std::sqrt(R / h1);
  t.neutral_angle = std::sqrt(h1 / R) * std::tan(M_PI / 8 * std::sqrt(h1 / R) * std::log(1 - r) + 0.5 * std::atan(b));
  const double hn = h1 + R * t.neutral_angle * t.neutral_angle;
  const double Qp =
      M_PI / 2 * a * std::atan(b) - M_PI / 4 - a * s * std::log(hn / h1) + 0.5 * a * s * std::log(1 / (1 - r));
  t.sims_force = k2 * t.contact_length * Qp * width;
  t.sims_torque = k2 * R * R * (t.bite_angle / 2 - t.neutral_angle) * width;
  t.sims_forward_slip = hn / h1 - 1;
  t.friction_hill_force = k2 * t.contact_length * (1 + t.contact_length / (2 * (h0 + h1))) * width;
  if (pass.width_axis >= 0) {
    const double W = std::pow(10.0, -1.269 * (width / h0) * std::pow(h0 / (2 * R), 0.556));
    t.wusatowski_spread = width * (std::pow(h0 / h1, W) - 1);
  }
  if (pass.roll_E > 0)
    t.hitchcock_radius_ratio =
        1 + 16 * (1 - pass.roll_nu * pass.roll_nu) * (t.sims_force / width) / (M_PI * pass.roll_E * draft);
  return t;
}

double travel_through(const RollingPass& pass) {
  const RollingTheory t = rolling_theory(pass);
  const double entry_speed = pass.exit_thickness * (1 + t.sims_forward_slip) / pass.entry_thickness;
  return std::max(0.0, pass.slab_length - t.contact_length) / entry_speed;
}

std::string bite_refusal(const RollingPass& pass) {
  if (pass.friction < 0) return "";
  const double alpha = rolling_theory(pass).bite_angle, tan_alpha = std::tan(alpha);
  if (pass.friction >= tan_alpha) return "";
  const double R = pass.radius, draft = pass.entry_thickness - pass.exit_thickness;
  const double largest = 2 * R * (1 - std::cos(std::atan(pass.friction)));
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "the roll cannot draw the slab in — friction coefficient %.3g is below tan α = %.3f (bite "
                "angle α = %.2f°: cos α = 1 − Δh / 2R with draft Δh = %.4g mm, R = %.4g mm); raise the friction to "
                "%.3f or more, or take a draft of at most %.3g mm",
                pass.friction, tan_alpha, alpha * 180 / M_PI, draft, R, tan_alpha, largest);
  return buf;
}

}  // namespace rollsim
