#include "contact/ContactConstraints.h"

#include <map>
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
Mesh displaced(const Mesh& m, const Eigen::VectorXd& u) {
  Mesh d = m;
  for (size_t n = 0; n < d.nodes.size(); ++n)
    for (int k = 0; k < m.dim; ++k) d.nodes[n][k] += u[static_cast<Eigen::Index>(n) * m.dim + k];
  return d;
}

/// X_s − Σ N_k X_k in the undeformed positions.
Eigen::Vector3d reference_separation(const Mesh& slave, const Mesh& master, const ContactPoint& c) {
  Eigen::Vector3d s(slave.nodes[c.slave_node][0], slave.nodes[c.slave_node][1], slave.nodes[c.slave_node][2]);
  for (size_t k = 0; k < c.master_nodes.size(); ++k) {
    const auto& X = master.nodes[c.master_nodes[k]];
    s -= c.N[k] * Eigen::Vector3d(X[0], X[1], X[2]);
  }
  return s;
}
}  // namespace

void follow_contacts(const Model& model, const std::vector<Eigen::VectorXd>& u, std::vector<PairState>& pairs) {
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (!p.large_sliding) continue;
    const Mesh& slave = model.bodies[p.slave_body].mesh;
    const Mesh& master = model.bodies[p.master_body].mesh;
    std::map<int, char> was;
    for (size_t j = 0; j < pairs[i].points.size(); ++j) was[pairs[i].points[j].slave_node] = pairs[i].active[j];
    PairState now;
    now.points = find_contact_points(displaced(slave, u[p.slave_body]), slave.surfaces.at(p.slave_surface),
                                     displaced(master, u[p.master_body]), master.surfaces.at(p.master_surface),
                                     p.search_distance);
    const double touch = 1e-9 * p.search_distance;
    for (ContactPoint& c : now.points) {
      c.separation = reference_separation(slave, master, c);
      const auto it = was.find(c.slave_node);
      now.active.push_back(it != was.end() ? (it->second || c.gap < -touch) : c.gap <= touch);
    }
    pairs[i] = std::move(now);
  }
}

namespace {
/// coef_s u_s − Σ N_k u_k projected on `dir` (a unit axis for tied rows, the normal for frictionless ones).
ConstraintRow relative_motion(const ContactPair& p, const ContactPoint& c, const Eigen::Vector3d& dir, int dim) {
  ConstraintRow row;
  row.dir = dir;
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
        row.rhs = -c.normal.dot(c.separation);  // the gap of the configuration the point was found in
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
      double g = c.normal.dot(c.separation);
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
