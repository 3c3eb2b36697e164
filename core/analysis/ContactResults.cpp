#include "analysis/ContactResults.h"

#include <map>

#include "contact/Friction.h"

namespace rollsim {

void contact_results(const Model& model, const std::vector<PairState>& pairs, const std::vector<ConstraintRow>& rows,
                     const std::vector<int>& kept, const Eigen::VectorXd& lambda, Results& results) {
  // force on each slave point, per pair
  std::vector<std::map<int, Eigen::Vector3d>> force(pairs.size());
  for (size_t r = 0; r < kept.size(); ++r) {
    const ConstraintRow& row = rows[kept[r]];
    auto [it, fresh] = force[row.pair].try_emplace(row.point, Eigen::Vector3d::Zero());
    const double l = lambda[static_cast<Eigen::Index>(r)];
    it->second -= l * row.dir;
  }
  results.contacts.clear();
  if (!pairs.empty())  // every body carries the fields once the model has contact: 0 off the slave surfaces
    for (size_t b = 0; b < results.bodies.size(); ++b) {
      results.bodies[b].contact_pressure = results.bodies[b].contact_slip =
          Eigen::VectorXd::Zero(model.bodies[b].mesh.num_nodes());
      results.bodies[b].contact_shear = Eigen::VectorXd::Zero(model.bodies[b].mesh.num_nodes() * model.dim);
    }
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    ContactResult cr;
    cr.name = p.name;
    cr.candidate_nodes = static_cast<int>(pairs[i].points.size());
    Eigen::Vector3d tangential = Eigen::Vector3d::Zero();
    BodyResults& slave = results.bodies[p.slave_body];
    for (size_t j = 0; j < pairs[i].points.size(); ++j)
      slave.contact_slip[pairs[i].points[j].slave_node] = pairs[i].slid[j];
    for (auto& [j, f] : force[i]) {
      const ContactPoint& c = pairs[i].points[j];
      if (can_slip(p) && pairs[i].slip[j])  // μ N (capped) against the slip, N from this λ
        f += slip_force(p, f.dot(c.normal), c.weight) * friction_direction(pairs[i], j);
      const double fn = f.dot(c.normal);
      cr.normal_force += fn;
      tangential += f - fn * c.normal;
      const double pressure = fn / c.weight;
      cr.max_pressure = std::max(cr.max_pressure, pressure);
      slave.contact_pressure[c.slave_node] = pressure;
      const Eigen::Vector3d shear = (f - fn * c.normal) / c.weight;
      for (int k = 0; k < model.dim; ++k) slave.contact_shear[c.slave_node * model.dim + k] = shear[k];
      cr.measure += c.weight;
      ++cr.active_nodes;
    }
    cr.tangential_force = tangential.norm();
    results.contacts.push_back(cr);
  }
}

void add_contact_reactions(const std::vector<std::unique_ptr<DofMap>>& dofs, const std::vector<ConstraintRow>& rows,
                           const std::vector<int>& kept, const Eigen::VectorXd& lambda,
                           const std::vector<Eigen::VectorXd>& friction, Results& results) {
  for (size_t b = 0; b < friction.size(); ++b) {
    const int dim = dofs[b]->dim();
    for (int i = 0; i < static_cast<int>(friction[b].size()); ++i)
      if (friction[b][i] != 0 && dofs[b]->equation(i / dim, i % dim) < 0)
        results.bodies[b].nodal_force[i] -= friction[b][i];
  }
  for (size_t r = 0; r < kept.size(); ++r)
    for (const ConstraintTerm& t : rows[kept[r]].terms) {
      if (dofs[t.body]->equation(t.node, t.comp) >= 0) continue;
      const int dim = dofs[t.body]->dim();
      results.bodies[t.body].nodal_force[t.node * dim + t.comp] += lambda[static_cast<Eigen::Index>(r)] * t.coef;
    }
}

}  // namespace rollsim
