#include "contact/FrictionStiffness.h"

#include "contact/Friction.h"

namespace rollsim {

std::vector<StiffnessEntry> slip_direction_stiffness(const Model& model, const std::vector<PairState>& pairs) {
  std::vector<StiffnessEntry> out;
  if (model.dim != 3) return out;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (!can_slip(p)) continue;
    const PairState& s = pairs[i];
    for (size_t j = 0; j < s.points.size(); ++j) {
      const Eigen::Vector3d d = friction_direction(s, j);
      if (!s.active[j] || !s.slip[j] || !(s.slip_step[j] > 0) || d.norm() == 0.0) continue;
      const ContactPoint& c = s.points[j];
      const double k = slip_force(p, s.normal_force[j], c.weight) / s.slip_step[j];
      if (!(k > 0)) continue;
      const Eigen::Vector3d w = c.normal.cross(d);  // P = w wᵀ: the tangent plane's direction across the slip
      std::vector<int> body{p.slave_body}, node{c.slave_node};
      std::vector<double> coef{1.0};  // R̃: the slave minus the master nodes by their weights
      for (size_t m = 0; m < c.master_nodes.size(); ++m)
        body.push_back(p.master_body), node.push_back(c.master_nodes[m]), coef.push_back(-c.N[m]);
      for (size_t a = 0; a < body.size(); ++a)
        for (size_t b = 0; b < body.size(); ++b)
          for (int r = 0; r < 3; ++r)
            for (int q = 0; q < 3; ++q)
              if (const double v = k * coef[a] * coef[b] * w[r] * w[q]; v != 0.0)
                out.push_back({body[a], node[a], r, body[b], node[b], q, v});
    }
  }
  return out;
}

}  // namespace rollsim
