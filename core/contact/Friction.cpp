#include "contact/Friction.h"

#include <algorithm>
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
        s.slip_step[j] = 0;
        ++s.switches[j], ++changed;
        if (f.norm() / limit < least.ratio) least = {j, f.norm() / limit};
        continue;
      }
      // slipping: the friction force opposes the slip over the step (backward Euler); a slip along the force means
      // the point sticks where the step began. A point at the limit with next to no slip can chatter (stick, over
      // μN, slip, along...): it gets one way back per step, then slips with the force against its slip — until its
      // slip turns along the force once more, which freezes its direction for the rest of the step.
      const Eigen::Vector3d start = relative_position(p, c, u_start, model.dim);
      const Eigen::Vector3d v = tangential_part(relative_position(p, c, u, model.dim) - start, c.normal);
      s.slip_step[j] = 0;
      // a slip below the resolution has no direction (its turn −v_t/|v_t| would be round-off's): on the cone with
      // next to no slip, any direction is Coulomb's, and the last one stays
      if (v.norm() <= kSlipResolution * p.search_distance || s.switches[j] == kFrozenDirection) continue;
      if (v.dot(s.friction_dir[j]) > 0 && s.switches[j] < 2) {
        s.slip[j] = 0, s.anchor[j] = start;
        ++s.switches[j], ++changed;
      } else if (v.dot(s.friction_dir[j]) > 0 && s.switches[j] < kReleasedDirection) {
        // it came back to slip and now slips along its force again: no slip against it holds this point (it
        // would stick, but sticking needs more than μN). Turned over, μN would throw it to and fro with growing
        // slips (3D rolling pass, docs/BENCHMARKS-ROLLING.md), so its direction stays for the rest of the step.
        s.switches[j] = kFrozenDirection;
      } else {
        s.friction_dir[j] = -v.normalized(), s.slip_step[j] = v.norm();
      }
    }
    if (p.holds_slave && least.ratio < std::numeric_limits<double>::max() && !any_sticks(s)) {
      s.slip[least.point] = 0;  // keeps holding the body: all points slipping would leave it free
      --s.switches[least.point], --changed;
    }
  }
  return changed;
}

int release_frozen(const Model& model, const std::vector<Eigen::VectorXd>& u,
                   const std::vector<Eigen::VectorXd>& u_start, std::vector<PairState>& pairs) {
  int released = 0;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    PairState& s = pairs[i];
    for (size_t j = 0; j < s.points.size(); ++j) {
      if (!s.active[j] || !s.slip[j] || s.switches[j] != kFrozenDirection) continue;
      const ContactPoint& c = s.points[j];
      const Eigen::Vector3d v = tangential_part(
          relative_position(p, c, u, model.dim) - relative_position(p, c, u_start, model.dim), c.normal);
      if (v.norm() <= kSlipResolution * p.search_distance) continue;  // next to no slip: any direction on the cone
      if (-v.normalized().dot(friction_direction(s, j)) >= 1 - kDirectionTolerance) continue;
      s.friction_dir[j] = -v.normalized(), s.slip_step[j] = v.norm();
      s.switches[j] = kReleasedDirection;
      ++released;
    }
  }
  return released;
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
      const Eigen::Vector3d v = relative_position(p, c, u, model.dim) - relative_position(p, c, u_start, model.dim);
      s.slid[j] += tangential_part(v, c.normal).norm();
    }
  }
}

void new_step(std::vector<PairState>& pairs) {
  for (PairState& s : pairs) {
    std::fill(s.switches.begin(), s.switches.end(), 0);
    std::fill(s.contact_switches.begin(), s.contact_switches.end(), 0);
    std::fill(s.slip_step.begin(), s.slip_step.end(), 0.0);  // the direction is the last step's
  }
}

}  // namespace rollsim
