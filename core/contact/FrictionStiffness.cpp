#include "contact/FrictionStiffness.h"

#include "contact/Friction.h"

namespace rollsim {

SlipDirectionRows slip_direction_rows(const Model& model, const std::vector<PairState>& pairs) {
  SlipDirectionRows out;
  if (model.dim != 3) return out;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (!can_slip(p)) continue;
    const PairState& s = pairs[i];
    for (size_t j = 0; j < s.points.size(); ++j) {
      const Eigen::Vector3d d = friction_direction(s, j);
      if (!s.active[j] || !s.slip[j] || !(s.trial_slip[j] > 0) || d.norm() == 0.0) continue;
      const ContactPoint& c = s.points[j];
      const double k = slip_force(p, s.normal_force[j], c.weight) / s.trial_slip[j];
      if (!(k > 0)) continue;
      const Eigen::Vector3d w = c.normal.cross(d);  // P = w wᵀ: the tangent plane's direction across the slip
      ConstraintRow row;                            // wᵀR̃: the slave minus the master nodes by their weights
      row.pair = static_cast<int>(i), row.point = static_cast<int>(j), row.dir = w;
      for (int r = 0; r < 3; ++r) {
        if (w[r] == 0.0) continue;
        row.terms.push_back({p.slave_body, c.slave_node, r, w[r]});
        for (size_t m = 0; m < c.master_nodes.size(); ++m)
          row.terms.push_back({p.master_body, c.master_nodes[m], r, -c.N[m] * w[r]});
      }
      out.rows.push_back(std::move(row));
      out.stiffness.push_back(k);
    }
  }
  return out;
}

std::vector<StiffnessEntry> slip_direction_stiffness(const Model& model, const std::vector<PairState>& pairs) {
  std::vector<StiffnessEntry> out;
  const SlipDirectionRows r = slip_direction_rows(model, pairs);
  for (size_t i = 0; i < r.rows.size(); ++i)
    for (const ConstraintTerm& a : r.rows[i].terms)
      for (const ConstraintTerm& b : r.rows[i].terms)
        if (const double v = r.stiffness[i] * a.coef * b.coef; v != 0.0)
          out.push_back({a.body, a.node, a.comp, b.body, b.node, b.comp, v});
  return out;
}

}  // namespace rollsim
