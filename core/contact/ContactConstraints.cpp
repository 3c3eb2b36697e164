#include "contact/ContactConstraints.h"

#include <stdexcept>

namespace rollsim {

std::vector<PairState> search_contacts(const Model& model) {
  std::vector<PairState> states;
  for (const ContactPair& p : model.contacts) {
    const Mesh& slave = model.bodies[p.slave_body].mesh;
    const Mesh& master = model.bodies[p.master_body].mesh;
    PairState s;
    s.points = find_contact_points(slave, slave.surfaces.at(p.slave_surface), master,
                                   master.surfaces.at(p.master_surface), p.search_distance);
    if (s.points.empty())
      throw std::runtime_error("contact pair '" + p.name + "': no node of surface '" + p.slave_surface + "' of body '" +
                               model.bodies[p.slave_body].name + "' lies over surface '" + p.master_surface +
                               "' of body '" + model.bodies[p.master_body].name + "' within the search distance " +
                               std::to_string(p.search_distance) + ": the surfaces never meet");
    for (const ContactPoint& c : s.points)
      s.active.push_back(p.kind == ContactKind::Tied || c.gap <= 1e-9 * p.search_distance);
    states.push_back(std::move(s));
  }
  return states;
}

namespace {
/// coef_s u_s − Σ N_k u_k projected on `dir` (a unit axis for tied rows, the normal for frictionless ones).
ConstraintRow relative_motion(const ContactPair& p, const ContactPoint& c, const Eigen::Vector3d& dir, int dim) {
  ConstraintRow row;
  for (int k = 0; k < dim; ++k) {
    if (dir[k] == 0) continue;
    row.terms.push_back({p.slave_body, c.slave_node, k, dir[k]});
    for (size_t m = 0; m < c.master_nodes.size(); ++m)
      row.terms.push_back({p.master_body, c.master_nodes[m], k, -c.N[m] * dir[k]});
  }
  return row;
}
}  // namespace

std::vector<ConstraintRow> contact_rows(const Model& model, const std::vector<PairState>& pairs) {
  std::vector<ConstraintRow> rows;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    for (size_t j = 0; j < pairs[i].points.size(); ++j) {
      if (!pairs[i].active[j]) continue;
      const ContactPoint& c = pairs[i].points[j];
      if (p.kind == ContactKind::Tied) {
        for (int k = 0; k < model.dim; ++k) {
          ConstraintRow row = relative_motion(p, c, Eigen::Vector3d::Unit(k), model.dim);
          row.pair = static_cast<int>(i), row.point = static_cast<int>(j), row.comp = k;
          rows.push_back(std::move(row));
        }
      } else {
        ConstraintRow row = relative_motion(p, c, c.normal, model.dim);
        row.rhs = -c.gap;
        row.pair = static_cast<int>(i), row.point = static_cast<int>(j);
        rows.push_back(std::move(row));
      }
    }
  }
  return rows;
}

int update_active_set(const Model& model, const std::vector<ConstraintRow>& rows, const Eigen::VectorXd& lambda,
                      const std::vector<Eigen::VectorXd>& u, std::vector<PairState>& pairs, double tolerance) {
  int changed = 0;
  const double tensile = tolerance * (lambda.size() ? lambda.cwiseAbs().maxCoeff() : 0.0);
  std::vector<std::vector<char>> next(pairs.size());
  for (size_t i = 0; i < pairs.size(); ++i) next[i] = pairs[i].active;
  // leaving: the normal row's multiplier is tensile (force on the slave −λ n pulls it towards the master)
  for (size_t r = 0; r < rows.size(); ++r) {
    const ConstraintRow& row = rows[r];
    if (model.contacts[row.pair].kind == ContactKind::Frictionless && lambda[static_cast<Eigen::Index>(r)] > tensile)
      next[row.pair][row.point] = 0;
  }
  // entering: an inactive point whose gap after deformation is negative (beyond round-off)
  const int dim = model.dim;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (p.kind != ContactKind::Frictionless) continue;
    for (size_t j = 0; j < pairs[i].points.size(); ++j) {
      if (pairs[i].active[j]) continue;
      const ContactPoint& c = pairs[i].points[j];
      double g = c.gap;
      for (int k = 0; k < dim; ++k) {
        double um = 0;
        for (size_t m = 0; m < c.master_nodes.size(); ++m) um += c.N[m] * u[p.master_body][c.master_nodes[m] * dim + k];
        g += c.normal[k] * (u[p.slave_body][c.slave_node * dim + k] - um);
      }
      if (g < -1e-9 * p.search_distance) next[i][j] = 1;
    }
    for (size_t j = 0; j < next[i].size(); ++j) changed += next[i][j] != pairs[i].active[j];
    pairs[i].active = next[i];
  }
  return changed;
}

}  // namespace rollsim
