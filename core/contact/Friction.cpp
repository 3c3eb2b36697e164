#include "contact/Friction.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rollsim {

namespace {
/// The multipliers of each active point: normal (comp −1) and tangential (comp k) of the kept rows.
struct PointMultipliers {
  double normal = 0;
  Eigen::Vector3d tangential_force = Eigen::Vector3d::Zero();  // −Σ λ_k t_k: the force of the stick rows on the slave
};

std::vector<std::vector<PointMultipliers>> by_point(const std::vector<PairState>& pairs,
                                                    const std::vector<ConstraintRow>& rows,
                                                    const Eigen::VectorXd& lambda) {
  std::vector<std::vector<PointMultipliers>> m(pairs.size());
  for (size_t i = 0; i < pairs.size(); ++i) m[i].resize(pairs[i].points.size());
  for (size_t r = 0; r < rows.size(); ++r) {
    PointMultipliers& p = m[rows[r].pair][rows[r].point];
    const double l = lambda[static_cast<Eigen::Index>(r)];
    if (rows[r].comp < 0)
      p.normal = l;
    else
      p.tangential_force -= l * rows[r].dir;
  }
  return m;
}

Eigen::Vector3d tangential_part(const Eigen::Vector3d& v, const Eigen::Vector3d& n) { return v - v.dot(n) * n; }

/// A point that went from stick to slip, and by how much its tangential force passed its limit (force / limit).
struct Overload {
  size_t point = 0;
  double ratio = std::numeric_limits<double>::max();
};

/// The least trial slip a slipping point's direction stiffness is taken at, as a fraction of its elastic slip.
constexpr double kTrialFloor = 1e-3;

bool any_sticks(const PairState& s) {
  for (size_t j = 0; j < s.points.size(); ++j)
    if (s.active[j] && !s.slip[j]) return true;
  return false;
}

}  // namespace

int update_friction(const Model& model, const std::vector<ConstraintRow>& rows, const Eigen::VectorXd& lambda,
                    const std::vector<Eigen::VectorXd>& u, const std::vector<Eigen::VectorXd>& u_start,
                    std::vector<PairState>& pairs) {
  const auto m = by_point(pairs, rows, lambda);
  int changed = 0;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (!frictional(p.kind)) continue;
    PairState& s = pairs[i];
    Overload least;  // the point that went from stick to slip with the smallest overload
    for (size_t j = 0; j < s.points.size(); ++j) {
      if (!s.active[j]) continue;
      const ContactPoint& c = s.points[j];
      s.normal_force[j] = std::max(0.0, -m[i][j].normal);
      if (!can_slip(p)) continue;
      const double limit = slip_force(p, s.normal_force[j], c.weight);
      if (!s.slip[j]) {
        const Eigen::Vector3d f = m[i][j].tangential_force;
        if (f.norm() <= limit * (1 + 1e-9) || f.norm() == 0.0) continue;
        s.slip[j] = 1, s.friction_dir[j] = f.normalized();  // the return onto the cone keeps the direction
        s.start_direction[j] = s.friction_dir[j], s.trial_slip[j] = 0;
        ++s.switches[j], ++changed;
        if (f.norm() / limit < least.ratio) least = {j, f.norm() / limit};
        continue;
      }
      // slipping: the friction force points along the trial force δ d₀ − v_t (Friction.h). A trial force inside the
      // cone sticks the point where the step began — once per step: a point at the limit with next to no slip could
      // go round stick, over μN, slip, inside... at every iteration; the second time it slips on.
      // where it would be had it stuck: its place at the step's start, moved with a turning master's material
      const Eigen::Vector3d start =
          relative_position(p, c, u_start, model.dim) + surface_travel(model, p, s, c, u_start);
      const Eigen::Vector3d v = tangential_part(relative_position(p, c, u, model.dim) - start, c.normal);
      const double delta = elastic_slip(p, c, model.dim);
      const Eigen::Vector3d trial = tangential_part(delta * s.start_direction[j], c.normal) - v;
      if (trial.norm() < delta && s.switches[j] < 2) {
        s.slip[j] = 0, s.anchor[j] = start;
        ++s.switches[j], ++changed;
      } else if (trial.norm() > 0) {
        // the direction's stiffness F / |trial| (FrictionStiffness) bounded where a point that slipped on keeps a
        // trial force inside the cone
        s.friction_dir[j] = trial.normalized(), s.trial_slip[j] = std::max(trial.norm(), kTrialFloor * delta);
      }
    }
    if (p.holds_slave && least.ratio < std::numeric_limits<double>::max() && !any_sticks(s)) {
      s.slip[least.point] = 0;  // keeps holding the body: all points slipping would leave it free
      --s.switches[least.point], --changed;
    }
  }
  return changed;
}

double elastic_slip(const ContactPair& p, const ContactPoint& c, int dim) {
  return p.slip_tolerance * (dim == 3 ? std::sqrt(c.weight) : c.weight);
}

bool can_slip(const ContactPair& p) {
  return p.kind == ContactKind::Coulomb || (p.kind == ContactKind::Sticking && p.shear_limit > 0);
}

double slip_force(const ContactPair& p, double normal_force, double weight) {
  double limit = p.kind == ContactKind::Coulomb ? p.friction * normal_force : std::numeric_limits<double>::max();
  if (p.shear_limit > 0) limit = std::min(limit, p.shear_limit * weight);
  return limit;
}

Eigen::Vector3d friction_direction(const PairState& s, size_t j) {
  const Eigen::Vector3d d = tangential_part(s.friction_dir[j], s.points[j].normal);
  return d.norm() > 0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::Zero();
}

bool slip_moves_with_normal(const ContactPair& p, const PairState& s, size_t j) {
  if (p.kind != ContactKind::Coulomb || !s.active[j] || !s.slip[j]) return false;
  if (p.shear_limit > 0 && p.friction * s.normal_force[j] > p.shear_limit * s.points[j].weight) return false;
  return friction_direction(s, j).norm() > 0;
}

std::vector<ConstraintRow> slip_coupling(const Model& model, const std::vector<PairState>& pairs,
                                         const std::vector<ConstraintRow>& rows) {
  std::vector<ConstraintRow> out(rows.size());
  for (size_t r = 0; r < rows.size(); ++r) {
    const ContactPair& p = model.contacts[rows[r].pair];
    const PairState& s = pairs[rows[r].pair];
    const auto j = static_cast<size_t>(rows[r].point);
    if (rows[r].comp >= 0 || !slip_moves_with_normal(p, s, j)) continue;
    const ContactPoint& c = s.points[j];
    const Eigen::Vector3d d = p.friction * friction_direction(s, j);
    for (int k = 0; k < model.dim; ++k) {
      out[r].terms.push_back({p.slave_body, c.slave_node, k, d[k]});
      for (size_t n = 0; n < c.master_nodes.size(); ++n)
        out[r].terms.push_back({p.master_body, c.master_nodes[n], k, -c.N[n] * d[k]});
    }
  }
  return out;
}

std::vector<Eigen::VectorXd> friction_loads(const Model& model, const std::vector<PairState>& pairs,
                                            FrictionLoads which) {
  bool any = false;
  for (const ContactPair& p : model.contacts) any = any || can_slip(p);
  if (!any) return {};
  const int dim = model.dim;
  std::vector<Eigen::VectorXd> f;
  for (const Body& b : model.bodies)
    f.push_back(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(b.mesh.num_nodes()) * dim));
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (!can_slip(p)) continue;
    const PairState& s = pairs[i];
    for (size_t j = 0; j < s.points.size(); ++j) {
      if (!s.active[j] || !s.slip[j]) continue;
      if (which == FrictionLoads::Capped && slip_moves_with_normal(p, s, j)) continue;
      const ContactPoint& c = s.points[j];
      const Eigen::Vector3d F = slip_force(p, s.normal_force[j], c.weight) * friction_direction(s, j);
      for (int k = 0; k < dim; ++k) {
        f[p.slave_body][c.slave_node * dim + k] += F[k];
        for (size_t n = 0; n < c.master_nodes.size(); ++n)
          f[p.master_body][c.master_nodes[n] * dim + k] -= c.N[n] * F[k];
      }
    }
  }
  return f;
}

void accumulate_slip(const Model& model, const std::vector<Eigen::VectorXd>& u,
                     const std::vector<Eigen::VectorXd>& u_start, std::vector<PairState>& pairs) {
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (p.kind == ContactKind::Tied) continue;
    PairState& s = pairs[i];
    for (size_t j = 0; j < s.points.size(); ++j) {
      if (!s.active[j]) continue;
      const ContactPoint& c = s.points[j];
      const Eigen::Vector3d v = relative_position(p, c, u, model.dim) - relative_position(p, c, u_start, model.dim) -
                                surface_travel(model, p, s, c, u_start);
      s.slid[j] += tangential_part(v, c.normal).norm();
    }
  }
}

void new_step(std::vector<PairState>& pairs) {
  for (PairState& s : pairs) {
    std::fill(s.switches.begin(), s.switches.end(), 0);
    std::fill(s.contact_switches.begin(), s.contact_switches.end(), 0);
    std::fill(s.trial_slip.begin(), s.trial_slip.end(), 0.0);  // the direction is the last step's
    for (size_t j = 0; j < s.points.size(); ++j)
      s.start_direction[j] = s.slip[j] ? friction_direction(s, j) : Eigen::Vector3d::Zero();
  }
}

}  // namespace rollsim
