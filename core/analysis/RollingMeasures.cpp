#include "analysis/RollingMeasures.h"

#include "analysis/RollingTheory.h"

#include <algorithm>
#include <cmath>

namespace rollsim {

namespace {

Eigen::Vector3d current(const Mesh& mesh, const Eigen::VectorXd& u, int node) {
  Eigen::Vector3d x(mesh.nodes[node][0], mesh.nodes[node][1], mesh.nodes[node][2]);
  for (int k = 0; k < mesh.dim; ++k) x[k] += u[node * mesh.dim + k];
  return x;
}

/// The roll's axis: the centre of its hub's rotation.
Eigen::Vector3d roll_axis_point(const Model& model, const RollingPass& pass) {
  const auto& c = model.displacements[static_cast<size_t>(pass.hub)].rotation->center;
  return {c[0], c[1], c[2]};
}

/// The hub's reaction on the roll: roll force (minus its thickness component) and driving torque about the axis.
void hub_reaction(const Model& model, const RollingPass& pass, const BodyResults& roll, RollingIncrement& out) {
  const DisplacementBC& hub = model.displacements[static_cast<size_t>(pass.hub)];
  const Mesh& mesh = model.bodies[static_cast<size_t>(pass.roll)].mesh;
  const Eigen::Vector3d c = roll_axis_point(model, pass);
  const Eigen::Vector3d axis(hub.rotation->axis[0], hub.rotation->axis[1], hub.rotation->axis[2]);
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), torque = Eigen::Vector3d::Zero();
  for (int n : hub.nodes) {
    Eigen::Vector3d f = Eigen::Vector3d::Zero();
    for (int k = 0; k < mesh.dim; ++k) f[k] = roll.nodal_force[n * mesh.dim + k];
    force += f;
    torque += (current(mesh, roll.displacement, n) - c).cross(f);
  }
  out.roll_force = -force[pass.thickness_axis];
  out.roll_torque = torque.dot(axis);
}

/// Exit thickness and spread from the slab's nodes just past the exit plane (0 < x ≤ one nominal contact length).
void exit_geometry(const RollingPass& pass, const Mesh& slab, const BodyResults& r, double window,
                   RollingIncrement& out) {
  double top = 0, side = 0;
  for (int n = 0; n < slab.num_nodes(); ++n) {
    const Eigen::Vector3d x = current(slab, r.displacement, n);
    if (x[0] <= 0 || x[0] > window) continue;
    top = std::max(top, x[pass.thickness_axis]);
    if (pass.width_axis >= 0) side = std::max(side, x[pass.width_axis]);
  }
  out.exit_thickness = 2 * top;
  if (pass.width_axis >= 0 && side > 0) out.spread = 2 * side - pass.width;
}

double mean_advance(const Mesh& slab, const std::vector<int>& nodes, const Eigen::VectorXd& u) {
  double s = 0;
  for (int n : nodes) s += u[n * slab.dim];
  return nodes.empty() ? 0.0 : s / static_cast<double>(nodes.size());
}

RollingIncrement mean(const std::vector<RollingIncrement>& h, size_t from) {
  RollingIncrement m;
  const double n = static_cast<double>(h.size() - from);
  for (size_t i = from; i < h.size(); ++i) {
    m.travel = h[i].travel;
    m.roll_force += h[i].roll_force / n;
    m.roll_torque += h[i].roll_torque / n;
    m.contact_length += h[i].contact_length / n;
    m.exit_thickness += h[i].exit_thickness / n;
    m.forward_slip += h[i].forward_slip / n;
    m.spread += h[i].spread / n;
  }
  return m;
}

/// The slab's contact nodes at the state `r`, by decreasing angle (entry first).
std::vector<ArcPoint> arc_profile(const Model& model, const RollingPass& pass, const BodyResults& r) {
  const Mesh& slab = model.bodies[static_cast<size_t>(pass.slab)].mesh;
  const Eigen::Vector3d c = roll_axis_point(model, pass);
  const int t = pass.thickness_axis, dim = slab.dim;
  std::vector<ArcPoint> out;
  for (int n = 0; n < slab.num_nodes(); ++n) {
    if (n >= r.contact_pressure.size() || r.contact_pressure[n] <= 0) continue;
    const Eigen::Vector3d x = current(slab, r.displacement, n);
    const double phi = std::atan2(-(x[0] - c[0]), -(x[t] - c[t]));
    Eigen::Vector3d tangent = Eigen::Vector3d::Zero();  // along the surface toward the exit
    tangent[0] = std::cos(phi), tangent[t] = -std::sin(phi);
    double shear = 0;
    for (int k = 0; k < dim; ++k) shear += r.contact_shear[n * dim + k] * tangent[k];
    out.push_back(
        {phi * 180 / M_PI, x[0], pass.width_axis >= 0 ? x[pass.width_axis] : 0.0, r.contact_pressure[n], shear});
  }
  std::sort(out.begin(), out.end(), [](const ArcPoint& a, const ArcPoint& b) { return a.angle > b.angle; });
  return out;
}

}  // namespace

int steady_state_from(const std::vector<RollingIncrement>& h, double window) {
  for (size_t i = 0; i < h.size(); ++i) {
    if (h[i].travel < window) continue;
    bool settled = true;
    for (size_t j = i + 1; j-- > 0 && h[j].travel >= h[i].travel - window;)
      settled = settled &&
                std::abs(h[j].roll_force - h[i].roll_force) <= kSteadyTolerance * std::abs(h[i].roll_force) &&
                std::abs(h[j].roll_torque - h[i].roll_torque) <= kSteadyTolerance * std::abs(h[i].roll_torque);
    if (settled) return static_cast<int>(i) + 1;
  }
  return 0;
}

RollingResults measure_rolling(const Model& model, const Results& results) {
  const RollingPass& pass = *model.rolling;
  const Mesh& slab = model.bodies[static_cast<size_t>(pass.slab)].mesh;
  const double symmetry = model.dim == 3 ? 2.0 : 1.0;          // 3D models half the width
  const double contact = rolling_theory(pass).contact_length;  // √(R Δh)
  RollingResults out;
  double rear_before = 0, travel_before = 0;
  std::vector<std::pair<double, double>> fronts{{0.0, 0.0}};  // (travel, front advance) from the start
  for (const IncrementResults& inc : results.increments) {
    if (inc.bodies.size() != model.bodies.size()) continue;
    RollingIncrement r;
    r.travel = inc.load_factor * pass.travel;
    hub_reaction(model, pass, inc.bodies[static_cast<size_t>(pass.roll)], r);
    r.roll_force *= symmetry;
    r.roll_torque *= symmetry;
    for (const ContactResult& c : inc.contacts) r.contact_length += symmetry * c.measure;
    exit_geometry(pass, slab, inc.bodies[static_cast<size_t>(pass.slab)], contact, r);
    const Eigen::VectorXd& u = inc.bodies[static_cast<size_t>(pass.slab)].displacement;
    const double front = mean_advance(slab, slab.node_sets.at("xmax"), u);
    const double rear = mean_advance(slab, slab.node_sets.at("xmin"), u);
    const double dt = r.travel - travel_before;
    // over the last tenth of a contact length of travel (from the start before that): a cut-back step's own advance
    // is mostly the round-off of a tiny travel
    size_t j = 0;
    while (j + 1 < fronts.size() && fronts[j + 1].first <= r.travel - 0.1 * contact) ++j;
    const double span = r.travel - fronts[j].first;
    r.forward_slip = span > 0 ? (front - fronts[j].second) / span - 1 : 0.0;
    fronts.emplace_back(r.travel, front);
    // the roll bites once the rear end follows: it moves in by half of what the roll's travel would draw in
    if (!out.bite_increment && dt > 0 && rear - rear_before >= 0.5 * dt * pass.exit_thickness / pass.entry_thickness)
      out.bite_increment = static_cast<int>(out.increments.size()) + 1;
    rear_before = rear, travel_before = r.travel;
    out.increments.push_back(r);
  }
  if (out.increments.empty()) return out;
  for (auto it = results.increments.rbegin(); it != results.increments.rend(); ++it)
    if (it->bodies.size() == model.bodies.size()) {
      out.profile = arc_profile(model, pass, it->bodies[static_cast<size_t>(pass.slab)]);
      break;
    }
  out.steady_state_increment = steady_state_from(out.increments, contact);
  out.steady = mean(out.increments, out.steady_state_increment ? static_cast<size_t>(out.steady_state_increment - 1)
                                                               : out.increments.size() - 1);
  return out;
}

}  // namespace rollsim
