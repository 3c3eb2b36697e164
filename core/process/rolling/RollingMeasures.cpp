#include "process/rolling/RollingMeasures.h"

#include "process/rolling/RollingTheory.h"

#include "fem/SolidElement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace rollsim {

const std::vector<RollingMeasure>& rolling_measures() {
  using R = RollingIncrement;
  static const std::vector<RollingMeasure> table = {
      {{"travel", "roll travel", "mm"}, "mm", &R::travel},
      {{"roll_force", "roll force", "N/mm (per unit width)"}, "N", &R::roll_force},
      {{"roll_torque", "torque per roll", "N·mm/mm (per unit width)"}, "N·mm", &R::roll_torque},
      {{"contact_length", "contact length", "mm"}, "mm²", &R::contact_length},
      {{"exit_thickness", "exit thickness", "mm"}, "mm", &R::exit_thickness},
      {{"forward_slip", "forward slip", "-"}, "-", &R::forward_slip},
      {{"spread", "spread at the widest point", "mm"}, "mm", &R::spread},
      {{"mean_spread", "spread of the mean width", "mm"}, "mm", &R::mean_spread},
      {{"volume_change", "slab volume change", "-"}, "-", &R::volume_change},
      {{"mean_pressure", "mean roll pressure", "MPa"}, "MPa", &R::mean_pressure},
      {{"roll_power", "roll power per roll", "kW/mm (per unit width)"}, "kW", &R::roll_power},
      {{"slab_temperature", "slab mean temperature", "°C"}, "°C", &R::slab_temperature, true},
      {{"surface_temperature", "slab surface temperature past the exit", "°C"}, "°C", &R::surface_temperature, true},
      {{"roll_temperature", "roll surface temperature, hottest", "°C"}, "°C", &R::roll_temperature, true},
  };
  return table;
}

Measure RollingMeasure::in(int dim) const {
  Measure m = plane;
  if (dim == 3) m.unit = solid_unit;
  if (dim == 3 && m.name == "contact_length") m.name = "contact_area", m.label = "contact area";  // in mm², not mm
  return m;
}

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

/// The mean width past the exit plane, less the entry width: each column of the slab's side face (its nodes of one
/// reference x, the face y = b0/2) whose nodes are all past the exit plane (0 < x ≤ window) gives its position
/// averaged over the thickness (trapezoid rule over the current heights); the columns' mean, doubled (the width is
/// symmetric about y = 0). 0 when no column is there yet.
double mean_spread(const RollingPass& pass, const Mesh& slab, const BodyResults& r, double window) {
  std::map<double, std::vector<Eigen::Vector3d>> columns;  // reference x → current positions of the side's nodes
  for (int n : slab.node_sets.at("ymax"))
    columns[slab.nodes[static_cast<size_t>(n)][0]].push_back(current(slab, r.displacement, n));
  const int up = pass.thickness_axis, across = pass.width_axis;
  double sum = 0;
  int counted = 0;
  for (auto& [x0, c] : columns) {
    const auto outside = [&](const Eigen::Vector3d& x) { return x[0] <= 0 || x[0] > window; };
    if (c.size() < 2 || std::any_of(c.begin(), c.end(), outside)) continue;
    std::sort(c.begin(), c.end(), [&](const auto& a, const auto& b) { return a[up] < b[up]; });
    double area = 0;
    for (size_t i = 0; i + 1 < c.size(); ++i)
      area += 0.5 * (c[i][across] + c[i + 1][across]) * (c[i + 1][up] - c[i][up]);
    sum += area / (c.back()[up] - c.front()[up]), ++counted;
  }
  return counted ? 2 * sum / counted - pass.width : 0.0;
}

/// The slab's and the roll's temperatures: the slab's volume mean (nodal values weighted by ∫ N dV), its top
/// surface's mean past the exit plane (0 < x ≤ window) and the roll surface's hottest node. False: no temperature.
bool temperatures(const Model& model, const RollingPass& pass, const IncrementResults& inc,
                  const Eigen::VectorXd& share, double window, RollingIncrement& out) {
  const Mesh& slab = model.bodies[static_cast<size_t>(pass.slab)].mesh;
  const BodyResults& s = inc.bodies[static_cast<size_t>(pass.slab)];
  const Eigen::VectorXd T = node_temperatures(slab, s);
  if (T.size() == 0) return false;
  out.slab_temperature = share.dot(T) / share.sum();
  double sum = 0;
  int count = 0;
  for (int n : slab.node_sets.at(pass.thickness_axis == 1 ? "ymax" : "zmax")) {
    const double x = current(slab, s.displacement, n)[0];
    if (x > 0 && x <= window) sum += T[n], ++count;
  }
  out.surface_temperature = count ? sum / count : 0.0;
  const Body& roll = model.bodies[static_cast<size_t>(pass.roll)];
  const Eigen::VectorXd R = node_temperatures(roll.mesh, inc.bodies[static_cast<size_t>(pass.roll)]);
  out.roll_temperature = roll.material.temperature;
  if (R.size() > 0) {
    out.roll_temperature = -std::numeric_limits<double>::infinity();
    for (int n : roll.mesh.node_sets.at("outer")) out.roll_temperature = std::max(out.roll_temperature, R[n]);
  }
  return true;
}

double mean_advance(const Mesh& slab, const std::vector<int>& nodes, const Eigen::VectorXd& u) {
  double s = 0;
  for (int n : nodes) s += u[n * slab.dim];
  return nodes.empty() ? 0.0 : s / static_cast<double>(nodes.size());
}

/// A Lagrangian slab's front and rear faces: how far their nodes have moved along x since the start. A remesh's
/// segment (analysis/Remeshing) starts its displacement anew on the shape it was remeshed at — where the faces' nodes
/// were spread along them again —, so each segment's advance goes on from where the one before ended.
class FaceAdvance {
 public:
  /// Front and rear of `inc` on its model `at`.
  std::pair<double, double> operator()(const Model& at, const Mesh& slab, const Eigen::VectorXd& u) {
    if (&at != segment_) segment_ = &at, front0_ = front_, rear0_ = rear_;
    front_ = front0_ + mean_advance(slab, slab.node_sets.at("xmax"), u);
    rear_ = rear0_ + mean_advance(slab, slab.node_sets.at("xmin"), u);
    return {front_, rear_};
  }

 private:
  const Model* segment_ = nullptr;
  double front0_ = 0, rear0_ = 0, front_ = 0, rear_ = 0;
};

}  // namespace

double rear_end(const Mesh& slab, const Eigen::VectorXd& u) {
  const std::vector<int>& rear = slab.node_sets.at("xmin");
  double x = 0;
  for (int n : rear) x += current(slab, u, n)[0];
  return rear.empty() ? 0.0 : x / static_cast<double>(rear.size());
}

RollingIncrement window_mean(const std::vector<RollingIncrement>& h, double from, double to) {
  RollingIncrement m;
  double weight = 0, before = 0;
  for (const RollingIncrement& r : h) {
    const double w = r.travel - before;  // each increment counts for the travel it covered
    before = r.travel;
    if (r.travel <= from || r.travel > to) continue;
    m.travel = r.travel;
    for (const RollingMeasure& measure : rolling_measures())
      if (measure.field != &RollingIncrement::travel) m.*measure.field += w * r.*measure.field;
    weight += w;
  }
  if (weight <= 0) return m;
  for (const RollingMeasure& measure : rolling_measures())
    if (measure.field != &RollingIncrement::travel) m.*measure.field /= weight;
  return m;
}

namespace {
/// The slab's volume (area in 2D) with its nodes displaced by u: the sum of det J × weight of each element (the
/// 2-point Gauss rule is exact for the bilinear / trilinear map's det J).
template <int D>
double volume(const Mesh& mesh, const Eigen::VectorXd& u) {
  using E = SolidElement<D>;
  double v = 0;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    typename E::Coords x;
    for (int a = 0; a < E::NN; ++a) {
      const int n = mesh.element(e)[a];
      for (int k = 0; k < D; ++k) x(k, a) = mesh.nodes[static_cast<size_t>(n)][static_cast<size_t>(k)] + u[n * D + k];
    }
    std::array<typename E::Gradients, E::NGP> dN;
    std::array<double, E::NGP> dv;
    typename E::Gradients centre;
    E::gradients(x, dN, dv, centre);
    for (double w : dv) v += w;
  }
  return v;
}

double volume(const Mesh& mesh, const Eigen::VectorXd& u) {
  return mesh.dim == 2 ? volume<2>(mesh, u) : volume<3>(mesh, u);
}

/// ∫ N_a dV of every node of the mesh as meshed (D: its dimension).
template <int D>
Eigen::VectorXd node_volumes_of(const Mesh& mesh) {
  using E = SolidElement<D>;
  Eigen::VectorXd share = Eigen::VectorXd::Zero(mesh.num_nodes());
  for (int e = 0; e < mesh.num_elements(); ++e) {
    typename E::Coords x;
    for (int a = 0; a < E::NN; ++a)
      for (int k = 0; k < D; ++k) x(k, a) = mesh.nodes[static_cast<size_t>(mesh.element(e)[a])][static_cast<size_t>(k)];
    const auto s = E::shape_integrals(x);
    for (int a = 0; a < E::NN; ++a) share[mesh.element(e)[a]] += s[a];
  }
  return share;
}

/// The volume a face of the slab (its elements' facets whose nodes all lie in the set) sweeps along x in the step u:
/// each facet's current measure (length in 2D, area in 3D: the face spreads in width) times its nodes' mean advance.
double face_flux(const Mesh& slab, const std::vector<int>& face, const Eigen::VectorXd& u) {
  std::vector<char> in(static_cast<size_t>(slab.num_nodes()), 0);
  for (int n : face) in[static_cast<size_t>(n)] = 1;
  const int facets = slab.dim == 2 ? 4 : 6;
  double flux = 0;
  for (int e = 0; e < slab.num_elements(); ++e)
    for (int f = 0; f < facets; ++f) {
      std::vector<int> nodes;
      for (int l : facet_local_nodes(slab.type, f)) nodes.push_back(slab.element(e)[l]);
      if (!std::all_of(nodes.begin(), nodes.end(), [&](int n) { return in[static_cast<size_t>(n)]; })) continue;
      std::vector<Eigen::Vector3d> x;
      double advance = 0;
      for (int n : nodes)
        x.push_back(current(slab, u, n)), advance += u[n * slab.dim] / static_cast<double>(nodes.size());
      const double measure = nodes.size() == 2 ? (x[1] - x[0]).norm() : 0.5 * (x[2] - x[0]).cross(x[3] - x[1]).norm();
      flux += measure * advance;
    }
  return flux;
}

/// An ALE step's volume out through the exit face over its volume in through the entry face, − 1 (0 once steady).
double flux_balance(const Mesh& slab, const Eigen::VectorXd& u) {
  const double in = face_flux(slab, slab.node_sets.at("xmin"), u);
  return in > 0 ? face_flux(slab, slab.node_sets.at("xmax"), u) / in - 1 : 0.0;
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

Eigen::VectorXd node_volumes(const Mesh& mesh) {
  return mesh.dim == 2 ? node_volumes_of<2>(mesh) : node_volumes_of<3>(mesh);
}

Eigen::VectorXd node_temperatures(const Mesh& mesh, const BodyResults& r) {
  if (r.nodal_temperature.size() == mesh.num_nodes()) return r.nodal_temperature;
  if (r.temperature.size() != static_cast<size_t>(mesh.num_elements())) return {};
  Eigen::VectorXd T = Eigen::VectorXd::Zero(mesh.num_nodes()), count = T;
  for (int e = 0; e < mesh.num_elements(); ++e)
    for (int a = 0; a < mesh.nodes_per_elem(); ++a)
      T[mesh.element(e)[a]] += r.temperature[static_cast<size_t>(e)], count[mesh.element(e)[a]] += 1;
  return T.cwiseQuotient(count.cwiseMax(1.0));
}

double earliest_steady_travel(const RollingPass& pass) {
  const double windows = 2 * kSteadyWindow * rolling_theory(pass).contact_length;
  return shape_steady(pass) ? std::max(windows, pass.ale_entry + pass.ale_exit) : windows;
}

int steady_state_from(const std::vector<RollingIncrement>& h, double window, bool shape, double flushed) {
  const auto near = [](double a, double b) { return std::abs(a - b) <= kSteadyTolerance * std::abs(a); };
  const auto spread_near = [](double a, double b) {
    return std::abs(a - b) <= kSteadyTolerance * std::abs(a) + kSteadySpread;
  };
  // the spread's means agree and every value of the last window lies within the band about its mean: two windows on
  // either side of an overshoot have equal means (the 14 × 8 × 4 window's spread peaked at 132 mm and the means
  // agreed at 156 mm, 15 % above where it settled)
  const auto settled = [&](size_t i, const RollingIncrement& last, const RollingIncrement& before) {
    if (!shape) return true;
    if (!spread_near(last.mean_spread, before.mean_spread)) return false;
    for (size_t k = 0; k <= i; ++k)
      if (h[k].travel > h[i].travel - window && !spread_near(last.mean_spread, h[k].mean_spread)) return false;
    return true;
  };
  for (size_t i = 0; i < h.size(); ++i) {
    const double t = h[i].travel;
    if (t < 2 * window || (shape && t < flushed)) continue;
    const RollingIncrement last = window_mean(h, t - window, t), before = window_mean(h, t - 2 * window, t - window);
    if (near(last.roll_force, before.roll_force) && near(last.roll_torque, before.roll_torque) &&
        settled(i, last, before))
      return static_cast<int>(i) + 1;
  }
  return 0;
}

RollingIncrement exit_shape(const RollingPass& pass, const Model& model, const IncrementResults& inc) {
  const Mesh& slab = model_of(inc, model).bodies[static_cast<size_t>(pass.slab)].mesh;
  const BodyResults& r = inc.bodies[static_cast<size_t>(pass.slab)];
  const double contact = rolling_theory(pass).contact_length;
  RollingIncrement out;
  exit_geometry(pass, slab, r, contact, out);
  if (pass.width_axis >= 0) out.mean_spread = mean_spread(pass, slab, r, contact);
  return out;
}

RollingIncrement roll_load(const RollingPass& pass, const Model& model, const IncrementResults& inc) {
  const double symmetry = pass.half_width ? 2.0 : 1.0;
  RollingIncrement r;
  r.travel = inc.load_factor * pass.travel;
  hub_reaction(model_of(inc, model), pass, inc.bodies[static_cast<size_t>(pass.roll)], r);
  r.roll_force *= symmetry;
  r.roll_torque *= symmetry;
  r.roll_power = r.roll_torque * pass.rpm * 2 * M_PI / 60 * 1e-6;  // N·mm · 1/s = 1e-6 kW
  return r;
}

RollingResults measure_rolling(const RollingPass& pass, const Model& model, const Results& results) {
  const double symmetry = pass.half_width ? 2.0 : 1.0;
  const double contact = rolling_theory(pass).contact_length;  // √(R Δh)
  const Mesh& slab0 = model.bodies[static_cast<size_t>(pass.slab)].mesh;
  const double volume0 = volume(slab0, Eigen::VectorXd::Zero(slab0.num_nodes() * slab0.dim));
  RollingResults out;
  double rear_before = 0, travel_before = 0;
  FaceAdvance advance;
  std::vector<std::pair<double, double>> fronts{{0.0, 0.0}};  // (travel, front advance) from the start
  for (const IncrementResults& inc : results.increments) {
    if (inc.bodies.size() != model.bodies.size()) continue;
    const Model& at = model_of(inc, model);  // an ALE step's: its window as the step began
    const Mesh& slab = at.bodies[static_cast<size_t>(pass.slab)].mesh;
    RollingIncrement r = roll_load(pass, model, inc);
    for (const ContactResult& c : inc.contacts) r.contact_length += symmetry * c.measure;
    const RollingIncrement shape = exit_shape(pass, model, inc);
    r.exit_thickness = shape.exit_thickness, r.spread = shape.spread, r.mean_spread = shape.mean_spread;
    const Eigen::VectorXd& u = inc.bodies[static_cast<size_t>(pass.slab)].displacement;
    const auto [front, rear] = pass.ale ? std::pair{mean_advance(slab, slab.node_sets.at("xmax"), u),
                                                    mean_advance(slab, slab.node_sets.at("xmin"), u)}
                                        : advance(at, slab, u);
    const double dt = r.travel - travel_before;
    // the roll bites once the rear end follows: it moves in by half of what the roll's travel would draw in (an ALE
    // window's entry face: in the step)
    const bool drawn_in =
        dt > 0 && (pass.ale ? rear : rear - rear_before) >= 0.5 * dt * pass.exit_thickness / pass.entry_thickness;
    if (!out.bite_increment && drawn_in) out.bite_increment = static_cast<int>(out.increments.size()) + 1;
    if (pass.ale) {  // the step's own advance of the exit and entry faces (an ALE step starts from its window)
      r.forward_slip = dt > 0 ? front / dt - 1 : 0.0;
      r.volume_change = flux_balance(slab, u);
    } else {
      // over the last tenth of a contact length of travel (from the start before that): a cut-back step's own
      // advance is mostly the round-off of a tiny travel
      size_t j = 0;
      while (j + 1 < fronts.size() && fronts[j + 1].first <= r.travel - 0.1 * contact) ++j;
      const double span = r.travel - fronts[j].first;
      r.forward_slip = span > 0 ? (front - fronts[j].second) / span - 1 : 0.0;
      fronts.emplace_back(r.travel, front);
      r.volume_change = volume(slab, u) / volume0 - 1;
    }
    r.mean_pressure = r.contact_length > 0 ? r.roll_force / r.contact_length : 0.0;  // p̄ = F / (L b)
    out.thermal = temperatures(at, pass, inc, node_volumes(slab), contact, r) || out.thermal;
    rear_before = rear, travel_before = r.travel;
    out.increments.push_back(r);
  }
  if (out.increments.empty()) return out;
  for (auto it = results.increments.rbegin(); it != results.increments.rend(); ++it)
    if (it->bodies.size() == model.bodies.size()) {
      out.profile = arc_profile(model_of(*it, model), pass, it->bodies[static_cast<size_t>(pass.slab)]);
      break;
    }
  const double window = kSteadyWindow * contact;
  const bool shape = pass.ale && pass.width_axis >= 0;
  out.steady_state_increment = steady_state_from(out.increments, window, shape, pass.ale_entry + pass.ale_exit);
  const double last = out.increments.back().travel;
  const double from = out.steady_state_increment
                          ? out.increments[static_cast<size_t>(out.steady_state_increment - 1)].travel - window
                          : (out.increments.size() > 1 ? out.increments[out.increments.size() - 2].travel : 0.0);
  out.steady = window_mean(out.increments, from, last);
  return out;
}

}  // namespace rollsim
