#include "bench/Quantities.h"

#include <cmath>
#include <limits>

#include "analysis/Recovery.h"

namespace rollsim::bench {

namespace {

int nearest_node(const Mesh& mesh, const std::array<double, 3>& at) {
  int best = 0;
  double d_best = std::numeric_limits<double>::infinity();
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    double d = 0;
    for (int k = 0; k < 3; ++k) d += (mesh.nodes[n][k] - at[k]) * (mesh.nodes[n][k] - at[k]);
    if (d < d_best) d_best = d, best = n;
  }
  return best;
}

}  // namespace

MeasureFn displacement_at(int body, std::array<double, 3> at, int c) {
  return [=](const Model& m, const Results& r) {
    const int n = nearest_node(m.bodies[body].mesh, at);
    return Measure{r.bodies[body].displacement[n * m.dim + c]};
  };
}

MeasureFn nodal_stress_at(int body, std::array<double, 3> at, int c) {
  return [=](const Model& m, const Results& r) {
    const int n = nearest_node(m.bodies[body].mesh, at);
    return Measure{r.bodies[body].nodal_stress[n][c]};
  };
}

MeasureFn reaction_on(int body, const std::string& set, int c, double exact) {
  return [=](const Model& m, const Results& r) {
    return Measure{set_resultant(r.bodies[body], m.dim, m.bodies[body].mesh.node_sets.at(set))[c], exact};
  };
}

MeasureFn hertz_peak_pressure(double radius, double e1, double nu1, double e2, double nu2) {
  return [=](const Model&, const Results& r) {
    if (r.contacts.empty()) return Measure{};
    const ContactResult& c = r.contacts.front();
    const double P = 2 * c.normal_force;
    const double e_star = 1.0 / ((1 - nu1 * nu1) / e1 + (1 - nu2 * nu2) / e2);
    const double a = std::sqrt(4 * P * radius / (M_PI * e_star));
    return Measure{c.max_pressure, 2 * P / (M_PI * a)};
  };
}

MeasureFn lame_inner_displacement(double a, double b, double p, double e, double nu) {
  return [=](const Model& m, const Results& r) {
    const Measure u = displacement_at(0, {a, 0, 0}, 0)(m, r);
    return Measure{u.value, (1 + nu) * p * a * a / (e * (b * b - a * a)) * ((1 - 2 * nu) * a + b * b / a)};
  };
}

}  // namespace rollsim::bench
