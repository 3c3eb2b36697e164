#include "contact/ContactStiffness.h"

namespace rollsim {

namespace {
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

Eigen::Vector2d position(const Model& model, int body, int node, const std::vector<Eigen::VectorXd>& u) {
  const auto& X = model.bodies[body].mesh.nodes[node];
  return {X[0] + u[body][2 * node], X[1] + u[body][2 * node + 1]};
}

/// [v_s; −(1 − ξ) v; −ξ v] over (slave, a, b): a row's coefficients along v.
Vector6 spread(const Eigen::Vector2d& v, double xi) {
  Vector6 out;
  out << v, -(1 - xi) * v, -xi * v;
  return out;
}

/// λ ∂C/∂u of one 2D row (header: the formulas), symmetric, over (slave, a, b).
Matrix6 segment_term(const ContactPair& p, const PairState& s, const ConstraintRow& row, double lambda,
                     const Model& model, const std::vector<Eigen::VectorXd>& u) {
  const ContactPoint& c = s.points[row.point];
  const Eigen::Vector2d a = position(model, p.master_body, c.master_nodes[0], u);
  const Eigen::Vector2d b = position(model, p.master_body, c.master_nodes[1], u);
  const Eigen::Vector2d x = position(model, p.slave_body, c.slave_node, u);
  const double l = (b - a).norm(), xi = c.N[1];
  const Eigen::Vector2d t = (b - a) / l, n(t.y(), -t.x());
  Vector6 N0;
  N0 << 0, 0, -n, n;
  const Vector6 D = spread(t, xi);
  const bool stuck = frictional(p.kind) && !s.slip[row.point];
  if (row.comp < 0 && !stuck && xi > 0 && xi < 1) {  // sliding: the Hessian of the gap
    const double g = n.dot(x - (1 - xi) * a - xi * b);
    return -lambda / l * (D * N0.transpose() + N0 * D.transpose()) - lambda * g / (l * l) * N0 * N0.transpose();
  }
  const Matrix6 M = row.comp < 0 ? Matrix6(-D * N0.transpose()) : Matrix6(spread(n, xi) * N0.transpose());
  return 0.5 * lambda / l * (M + M.transpose());
}
}  // namespace

std::vector<StiffnessEntry> contact_geometric_stiffness(const Model& model, const std::vector<PairState>& pairs,
                                                        const std::vector<ConstraintRow>& rows,
                                                        const std::vector<int>& kept, const Eigen::VectorXd& lambda,
                                                        const std::vector<Eigen::VectorXd>& u) {
  std::vector<StiffnessEntry> out;
  if (model.dim != 2) return out;
  for (size_t i = 0; i < kept.size(); ++i) {
    const ConstraintRow& row = rows[kept[i]];
    const ContactPair& p = model.contacts[row.pair];
    if (p.kind == ContactKind::Tied || p.sliding != ContactPair::Sliding::Iteration) continue;
    const PairState& s = pairs[row.pair];
    const Matrix6 K = segment_term(p, s, row, lambda[static_cast<Eigen::Index>(i)], model, u);
    const ContactPoint& c = s.points[row.point];
    const int body[3] = {p.slave_body, p.master_body, p.master_body};
    const int node[3] = {c.slave_node, c.master_nodes[0], c.master_nodes[1]};
    for (int r = 0; r < 6; ++r)
      for (int q = 0; q < 6; ++q)
        if (K(r, q) != 0) out.push_back({body[r / 2], node[r / 2], r % 2, body[q / 2], node[q / 2], q % 2, K(r, q)});
  }
  return out;
}

}  // namespace rollsim
