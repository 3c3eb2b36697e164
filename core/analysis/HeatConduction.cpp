#include "analysis/HeatConduction.h"

#include <cmath>
#include <cstdio>

#include "analysis/AnalysisError.h"
#include "base/Stopwatch.h"
#include "contact/Friction.h"
#include "fem/Assembler.h"
#include "fem/ElementLoop.h"
#include "fem/Loads.h"
#include "material/Material.h"
#include "solve/SparseCompare.h"

namespace rollsim {

namespace {
using Triplets = std::vector<Eigen::Triplet<double>>;

/// Calls f.template operator()<D>() with the model's dimension.
template <class F>
void with_dimension(int dim, F&& f) {
  if (dim == 2)
    f.template operator()<2>();
  else
    f.template operator()<3>();
}

/// Element e's node positions moved by u (every dof of its body).
template <int D>
typename SolidElement<D>::Coords moved_coords(const Mesh& m, int e, const Eigen::VectorXd& u) {
  auto x = element_coords<D>(m, e);
  const int* conn = m.element(e);
  for (int a = 0; a < SolidElement<D>::NN; ++a)
    for (int i = 0; i < D; ++i) x(i, a) += u[static_cast<Eigen::Index>(conn[a]) * D + i];
  return x;
}

/// Each integration point's mass per unit reference volume over the original density's, J_p of its initial state
/// (Material::plastic_volume): a remeshed run's later segments start on references under elastic strain. Empty when
/// every point's is 1 (no initial state, or none that moved its reference).
std::vector<double> point_masses(const Body& body, const Material& material) {
  const int width = material.state_size();
  if (body.initial_state.empty() || width == 0) return {};
  std::vector<double> mass(body.initial_state.size() / static_cast<size_t>(width));
  bool any = false;
  for (size_t p = 0; p < mass.size(); ++p) {
    mass[p] = material.plastic_volume(body.initial_state.data() + p * width);
    any = any || mass[p] != 1.0;
  }
  return any ? mass : std::vector<double>{};
}
}  // namespace

HeatConduction::HeatConduction(const Model& model)
    : model_(model), bodies_(model.bodies.size()), T_(model.bodies.size()) {
  for (size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (!body.material.conducts()) continue;
    BodyHeat& h = bodies_[b];
    h.offset = static_cast<int>(rows_);
    rows_ += body.mesh.num_nodes();
    T_[b] = Eigen::VectorXd::Constant(body.mesh.num_nodes(), body.material.temperature);
    if (!body.initial_temperature.empty())
      T_[b] = Eigen::Map<const Eigen::VectorXd>(body.initial_temperature.data(), body.mesh.num_nodes());
    h.share = Eigen::VectorXd::Zero(body.mesh.num_nodes());
    const auto material = make_material(body.material);
    const std::vector<double> mass = point_masses(body, *material);
    with_dimension(model.dim, [&]<int D>() {
      using El = SolidElement<D>;
      std::array<typename El::Gradients, El::NGP> dN;
      std::array<double, El::NGP> dv;
      typename El::Gradients centre;
      for (int e = 0; e < body.mesh.num_elements(); ++e) {
        const auto x = element_coords<D>(body.mesh, e);
        El::gradients(x, dN, dv, centre);
        if (!mass.empty())  // a rebased reference's points: their volume holds J_p times the original's mass
          for (int p = 0; p < El::NGP; ++p) dv[p] *= mass[static_cast<size_t>(e) * El::NGP + p];
        if (mass.empty()) {
          const auto share = El::shape_integrals(x);
          for (int a = 0; a < El::NN; ++a) h.share[body.mesh.element(e)[a]] += share[a];
        } else {
          for (int p = 0; p < El::NGP; ++p)
            for (int a = 0; a < El::NN; ++a) h.share[body.mesh.element(e)[a]] += El::gauss_shape()(p, a) * dv[p];
        }
        h.volume.insert(h.volume.end(), dv.begin(), dv.end());
      }
    });
    h.capacity = body.material.heat_capacity * h.share;
    if (body.material.thermal() && material->temperature_rise_index() >= 0) {
      h.stride = material->state_size();
      h.rise = material->temperature_rise_index();
      h.written = initial_point_rises(body);  // what the points start from (IntegrationState::initial)
      if (h.written.empty()) h.written.assign(h.volume.size(), 0.0);
    }
  }
}

void HeatConduction::update_table(size_t b) {
  const ThermalTable& table = model_.bodies[b].material.thermal_table;
  if (table.empty()) return;
  BodyHeat& h = bodies_[b];
  const Eigen::VectorXd& T = T_[b];
  h.lowest = std::min(h.lowest, T.minCoeff());
  h.highest = std::max(h.highest, T.maxCoeff());
  if (table.gives_heat_capacity())
    for (Eigen::Index n = 0; n < T.size(); ++n) h.capacity[n] = table.heat_capacity_at(T[n]) * h.share[n];
}

std::vector<std::string> HeatConduction::warnings() const {
  std::vector<std::string> out;
  const auto celsius = [](double T) {
    char s[32];
    std::snprintf(s, sizeof s, "%.4g °C", T);
    return std::string(s);
  };
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const ThermalTable& table = model_.bodies[b].material.thermal_table;
    const BodyHeat& h = bodies_[b];
    if (table.empty() || h.lowest > h.highest || (table.covers(h.lowest) && table.covers(h.highest))) continue;
    out.push_back("body '" + model_.bodies[b].name + "' (material '" + model_.bodies[b].material_name +
                  "'): its temperatures reached " + celsius(h.lowest) + " to " + celsius(h.highest) +
                  ", beyond its thermal_table's " + celsius(table.temperature.front()) + " to " +
                  celsius(table.temperature.back()) + ": its properties there were held at the table's end values");
  }
  return out;
}

void HeatConduction::add_conduction(size_t b, const Eigen::VectorXd& u, double dt, Triplets& t) const {
  const Body& body = model_.bodies[b];
  const ThermalTable& table = body.material.thermal_table;
  const bool varies = table.gives_conductivity();
  const Eigen::VectorXd& Tn = T_[b];
  const int offset = bodies_[b].offset;
  with_dimension(model_.dim, [&]<int D>() {
    using El = SolidElement<D>;
    std::array<typename El::Gradients, El::NGP> dN;
    std::array<double, El::NGP> dv;
    typename El::Gradients centre;
    for (int e = 0; e < body.mesh.num_elements(); ++e) {
      if (!El::gradients(moved_coords<D>(body.mesh, e, u), dN, dv, centre))
        throw AnalysisError("the heat step: element " + std::to_string(e) + " of body '" + body.name + "' is inverted");
      const int* conn = body.mesh.element(e);
      double k = body.material.conductivity;
      if (varies) {  // k(T) at the element's mean nodal temperature of the step's start
        double mean = 0;
        for (int a = 0; a < El::NN; ++a) mean += Tn[conn[a]];
        k = table.conductivity_at(mean / El::NN);
      }
      Eigen::Matrix<double, El::NN, El::NN> Ke = Eigen::Matrix<double, El::NN, El::NN>::Zero();
      for (int p = 0; p < El::NGP; ++p) Ke.noalias() += (k * dt * dv[p]) * dN[p].transpose() * dN[p];
      for (int a = 0; a < El::NN; ++a)
        for (int c = 0; c < El::NN; ++c) t.emplace_back(offset + conn[a], offset + conn[c], Ke(a, c));
    }
  });
}

void HeatConduction::add_contacts(const HeatStepInput& in, Triplets& t, Eigen::VectorXd& rhs,
                                  std::vector<std::vector<char>>& touching) {
  for (size_t i = 0; i < model_.contacts.size(); ++i) {
    const ContactPair& p = model_.contacts[i];
    const PairState& s = (*in.pairs)[i];
    const int os = bodies_[static_cast<size_t>(p.slave_body)].offset;
    const int om = bodies_[static_cast<size_t>(p.master_body)].offset;
    const std::vector<double> none;
    const std::vector<double>& before = in.slid_before && i < in.slid_before->size() ? (*in.slid_before)[i] : none;
    for (size_t j = 0; j < s.points.size(); ++j) {
      if (!s.active[j]) continue;
      const ContactPoint& c = s.points[j];
      // friction work over the step: the slipping point's force times its slip, shared between the bodies
      if (!s.slip.empty() && s.slip[j] && can_slip(p)) {
        const double slipped = s.slid[j] - (j < before.size() ? before[j] : 0.0);
        const double work = slip_force(p, s.normal_force[j], c.weight) * std::max(slipped, 0.0);
        if (os >= 0) rhs[os + c.slave_node] += p.friction_heat_to_slave * work;
        if (om >= 0)
          for (size_t k = 0; k < c.master_nodes.size(); ++k)
            rhs[om + c.master_nodes[k]] += (1 - p.friction_heat_to_slave) * work * c.N[k];
      }
      if (p.conductance <= 0 || os < 0 || om < 0) continue;
      touching[static_cast<size_t>(p.slave_body)][static_cast<size_t>(c.slave_node)] = 1;
      for (int m : c.master_nodes) touching[static_cast<size_t>(p.master_body)][static_cast<size_t>(m)] = 1;
      // h_c A (T_s − Σ N_k T_k)² / 2: the link's energy, its matrix g v vᵀ with v = (1, −N_1, −N_2, …)
      const double g = in.dt * p.conductance * c.weight;
      std::vector<std::pair<int, double>> v{{os + c.slave_node, 1.0}};
      for (size_t k = 0; k < c.master_nodes.size(); ++k) v.emplace_back(om + c.master_nodes[k], -c.N[k]);
      for (const auto& [r, vr] : v)
        for (const auto& [q, vq] : v) t.emplace_back(r, q, g * vr * vq);
    }
  }
}

void HeatConduction::add_air(const HeatStepInput& in, const std::vector<std::vector<char>>& touching,
                             Eigen::VectorXd& diagonal, Eigen::VectorXd& rhs) {
  const double ambient = model_.heat.ambient, ta = ambient + kKelvin;
  for (const AirCooling& a : model_.heat.air) {
    const size_t b = static_cast<size_t>(a.body);
    if (bodies_[b].offset < 0) continue;
    const Mesh& mesh = model_.bodies[b].mesh;
    const Eigen::VectorXd area = surface_node_areas(mesh, mesh.surfaces.at(a.surface), &(*in.displacement)[b]);
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      if (area[n] == 0 || touching[b][static_cast<size_t>(n)]) continue;
      const double tn = T_[b][n] + kKelvin;  // radiation linearised at the step's start
      const double h = a.convection + a.emissivity * kStefanBoltzmann * (tn * tn + ta * ta) * (tn + ta);
      const double g = in.dt * h * area[n];
      diagonal[bodies_[b].offset + n] += g;
      rhs[bodies_[b].offset + n] += g * ambient;
    }
  }
}

void HeatConduction::add_plastic_heat(size_t b, const std::vector<double>& state, Eigen::VectorXd& rhs) {
  const BodyHeat& h = bodies_[b];
  if (h.rise < 0 || state.empty()) return;
  const Body& body = model_.bodies[b];
  with_dimension(model_.dim, [&]<int D>() {
    using El = SolidElement<D>;
    const auto& N = El::gauss_shape();
    for (int e = 0; e < body.mesh.num_elements(); ++e)
      for (int p = 0; p < El::NGP; ++p) {
        const size_t point = static_cast<size_t>(e) * El::NGP + p;
        // the rise is β ∫ τ_y dα / ρc with the material's constant ρc (J2Plasticity's heating factor), so times that
        // same constant it is the plastic work's heat β ∫ τ_y dα, whatever ρc(T) a thermal_table gives conduction
        const double q =
            body.material.heat_capacity * (state[point * h.stride + h.rise] - h.written[point]) * h.volume[point];
        for (int a = 0; a < El::NN; ++a) rhs[h.offset + body.mesh.element(e)[a]] += N(p, a) * q;
      }
  });
}

void HeatConduction::write_points(size_t b, std::vector<double>& state) {
  BodyHeat& h = bodies_[b];
  if (h.rise < 0 || state.empty()) return;
  const Body& body = model_.bodies[b];
  h.written = point_values(body.mesh, T_[b].data());
  for (size_t point = 0; point < h.written.size(); ++point)
    state[point * h.stride + h.rise] = h.written[point] -= body.material.temperature;
}

Eigen::VectorXd HeatConduction::solve(const SparseMatrix& A, const Eigen::VectorXd& rhs) {
  if (!factor_ || !same_pattern(A, pattern_)) {
    factor_ = make_factorization("cholmod");
    factor_->analyze(A);
    pattern_ = A;
  }
  factor_->factorize(A);
  ++factorizations_;
  return factor_->solve(rhs);
}

void HeatConduction::step(const HeatStepInput& in, std::vector<std::vector<double>>& states) {
  if (rows_ == 0) return;
  Stopwatch clock;
  Triplets t;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows_), diagonal = Eigen::VectorXd::Zero(rows_);
  std::vector<std::vector<char>> touching(model_.bodies.size());
  for (size_t b = 0; b < bodies_.size(); ++b) {
    if (bodies_[b].offset < 0) continue;
    touching[b].assign(static_cast<size_t>(model_.bodies[b].mesh.num_nodes()), 0);
    update_table(b);
    add_conduction(b, (*in.displacement)[b], in.dt, t);
    add_plastic_heat(b, states[b], rhs);
    const auto C = bodies_[b].capacity.array();
    diagonal.segment(bodies_[b].offset, C.size()) += C.matrix();
    rhs.segment(bodies_[b].offset, C.size()) += (C * T_[b].array()).matrix();
  }
  add_contacts(in, t, rhs, touching);
  add_air(in, touching, diagonal, rhs);
  for (long r = 0; r < rows_; ++r) t.emplace_back(r, r, diagonal[r]);
  SparseMatrix A(rows_, rows_);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::VectorXd T;
  try {
    T = solve(A, rhs);
  } catch (const std::runtime_error& e) {
    throw AnalysisError(std::string("the heat step's system: ") + e.what());
  }
  if (!T.allFinite()) throw AnalysisError("the heat step gave a temperature that is not finite");
  for (size_t b = 0; b < bodies_.size(); ++b) {
    if (bodies_[b].offset < 0) continue;
    const Eigen::VectorXd next = T.segment(bodies_[b].offset, T_[b].size());
    T_[b] = next;
    write_points(b, states[b]);
    update_table(b);  // the range the step ended in (the capacity is rebuilt again at the next step's start)
  }
  seconds_ += clock.seconds();
}

}  // namespace rollsim
