#include "analysis/Recovery.h"

#include "fem/ElementLoop.h"
#include "fem/FiniteStrainElement.h"
#include "fem/Loads.h"

namespace rollsim {

namespace {
template <int D>
void recover_elements(const Body& body, const std::vector<double>& state, BodyResults& r) {
  using El = SolidElement<D>;
  const Mesh& m = body.mesh;
  const int ne = m.num_elements();
  r.element_stress.assign(static_cast<size_t>(ne), {});
  r.nodal_stress.assign(static_cast<size_t>(m.num_nodes()), {});
  std::vector<int> count(static_cast<size_t>(m.num_nodes()), 0);
  typename El::Dofs ue, fe;
  std::array<typename El::Stress6, El::NGP> gp;
  const auto material = make_material(body.material);
  const int ns = material->state_size(), alpha = material->equivalent_plastic_strain_index();
  const int rise = body.material.thermal() ? material->temperature_rise_index() : -1;
  const size_t per_element = static_cast<size_t>(El::NGP * ns);
  const bool stateful = ns > 0 && state.size() == per_element * static_cast<size_t>(ne);
  if (stateful && alpha >= 0) r.plastic_strain.assign(static_cast<size_t>(ne), 0.0);
  if (stateful && rise >= 0) r.temperature.assign(static_cast<size_t>(ne), body.material.temperature);
  for (int e = 0; e < ne; ++e) {
    const int* conn = m.element(e);
    for (int a = 0; a < El::NN; ++a)
      for (int i = 0; i < D; ++i) ue(a * D + i) = r.displacement[conn[a] * D + i];
    const auto x = element_coords<D>(m, e);
    const double* committed = stateful ? state.data() + per_element * e : nullptr;
    if (body.kinematics == Kinematics::Finite) {  // Cauchy stresses of the current configuration
      std::vector<double> initial(per_element, 0.0), trial(per_element);
      FiniteStrainElement<D>::tangent_and_force(x, *material, body.formulation, ue,
                                                committed ? committed : initial.data(), trial.data(), nullptr, fe, &gp);
    } else {
      El::stresses_and_force(x, *material, body.formulation, ue, gp, fe, committed);
    }
    if (!r.plastic_strain.empty())
      for (int p = 0; p < El::NGP; ++p) r.plastic_strain[e] += committed[p * ns + alpha] / El::NGP;
    if (!r.temperature.empty())
      for (int p = 0; p < El::NGP; ++p) r.temperature[e] += committed[p * ns + rise] / El::NGP;
    for (int a = 0; a < El::NN; ++a)
      for (int i = 0; i < D; ++i) r.nodal_force[conn[a] * D + i] += fe(a * D + i);
    for (int c = 0; c < 6; ++c) {
      std::array<double, El::NGP> v;
      double mean = 0.0;
      for (int p = 0; p < El::NGP; ++p) mean += (v[p] = gp[p][c]) / El::NGP;
      r.element_stress[e][c] = mean;
      for (int a = 0; a < El::NN; ++a) r.nodal_stress[conn[a]][c] += El::extrapolate_to_node(v, a);
    }
    for (int a = 0; a < El::NN; ++a) ++count[conn[a]];
  }
  for (size_t n = 0; n < count.size(); ++n)
    if (count[n])
      for (double& s : r.nodal_stress[n]) s /= count[n];
}
}  // namespace

BodyResults recover(const Model& model, int b, Eigen::VectorXd displacement, double load_factor,
                    const std::vector<double>& state) {
  const Body& body = model.bodies[b];
  BodyResults r;
  r.displacement = std::move(displacement);
  r.nodal_force = -external_nodal_load(model, b);
  if (const auto follower = follower_pressures(model, b); !follower.empty())
    r.nodal_force -= follower_nodal_load(body.mesh, follower, r.displacement);
  if (load_factor != 1.0) r.nodal_force *= load_factor;
  if (body.mesh.dim == 2)
    recover_elements<2>(body, state, r);
  else
    recover_elements<3>(body, state, r);
  r.subdomain.assign(static_cast<size_t>(body.mesh.num_elements()), 0);
  return r;
}

std::array<double, 3> set_resultant(const BodyResults& r, int dim, const std::vector<int>& nodes) {
  std::array<double, 3> s{0.0, 0.0, 0.0};
  for (int n : nodes)
    for (int c = 0; c < dim; ++c) s[c] += r.nodal_force[n * dim + c];
  return s;
}

void set_nodal_temperature(const Mesh& mesh, const Eigen::VectorXd& T, BodyResults& r) {
  r.nodal_temperature = T;
  r.temperature.assign(static_cast<size_t>(mesh.num_elements()), 0.0);
  const int nn = mesh.nodes_per_elem();
  for (int e = 0; e < mesh.num_elements(); ++e) {
    for (int a = 0; a < nn; ++a) r.temperature[static_cast<size_t>(e)] += T[mesh.element(e)[a]];
    r.temperature[static_cast<size_t>(e)] /= nn;
  }
}

}  // namespace rollsim
