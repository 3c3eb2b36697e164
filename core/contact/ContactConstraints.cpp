#include "contact/ContactConstraints.h"

#include <cmath>
#include <map>
#include <stdexcept>

#include <Eigen/Geometry>

namespace rollsim {

namespace {
/// A point new to the pair, with a fresh friction state: sticking where it is (u = 0: at its undeformed relative
/// position).
void add_point(PairState& s, const ContactPoint& c, bool active) {
  s.points.push_back(c);
  s.active.push_back(active);
  s.anchor.push_back(c.separation);
  s.slip.push_back(0);
  s.friction_dir.push_back(Eigen::Vector3d::Zero());
  s.normal_force.push_back(0.0);
  s.switches.push_back(0);
  s.contact_switches.push_back(0);
  s.slid.push_back(0.0);
  s.trial_slip.push_back(0.0);
  s.start_direction.push_back(Eigen::Vector3d::Zero());
}

Mesh displaced(const Mesh& m, const Eigen::VectorXd& u) {
  Mesh d = m;
  for (size_t n = 0; n < d.nodes.size(); ++n)
    for (int k = 0; k < m.dim; ++k) d.nodes[n][k] += u[static_cast<Eigen::Index>(n) * m.dim + k];
  return d;
}

/// A turning master surface is one of revolution (ContactPair::master_turns): its true surface lies outside the
/// facet, along the facet's normal, by the distance from the projection to the circle of the radius interpolated from
/// the facet's nodes — the sagitta, up to L²/8R on a facet of length L. Without it a point carried along a fixed
/// roll's facets would ride over every node's corner. Taken on the undeformed master (a correction of its facets'
/// shape, not of its deformation): the offset a row holds is the one its point is found with again where the step
/// ends, as the master deforms under it.
void round_facet(const Mesh& master, const ContactPair& p, ContactPoint& c) {
  if (!p.master_turns) return;
  const Eigen::Vector3d centre(p.master_turns->center.data()), axis(p.master_turns->axis.data());
  auto across = [&](const Eigen::Vector3d& v) -> Eigen::Vector3d { return v - v.dot(axis) * axis; };
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double radius = 0;
  for (size_t k = 0; k < c.master_nodes.size(); ++k) {
    const auto& X = master.nodes[c.master_nodes[k]];
    const Eigen::Vector3d x(X[0], X[1], X[2]);
    point += c.N[k] * x;
    radius += c.N[k] * across(x - centre).norm();
  }
  // |d + b n| = radius along the normal n from the projection, d its offset from the axis: b² + 2 b n·d + |d|² − r²
  const Eigen::Vector3d d = across(point - centre), n = across(c.normal);
  const double a = n.squaredNorm(), half = n.dot(d), rest = d.squaredNorm() - radius * radius;
  c.offset = a > 0 ? (-half + std::sqrt(std::max(0.0, half * half - a * rest))) / a : 0.0;
  c.gap -= c.offset;
}

/// How far past a master surface a point may lie and still count as on it, neither penetrating nor put off: round-off
/// (1e-9 of the search distance), or on a turning master's true surface 1e-4 of it (2.7 µm on the 3D sample). There an
/// ALE window's placement (the circle of the radius interpolated from the deformed roll's nodes, straight above the
/// node) and the contact (the deformed facet plus the undeformed facet's sagitta along its normal) agree to second
/// order only, 3e-5 mm apart on a 28-column 3D window: held to round-off, the arc's last column went off the roll
/// after every step and back on in its iterations, a column past the exit plane placed onto the roll entered where
/// each step began and left at once (tensile), and one at the arc's end, stuck and tensile, left, penetrated by 1 µm
/// and came back.
double on_surface(const ContactPair& p) { return (p.master_turns ? 1e-4 : 1e-9) * p.search_distance; }

/// X_s − Σ N_k X_k in the undeformed positions.
Eigen::Vector3d reference_separation(const Mesh& slave, const Mesh& master, const ContactPoint& c) {
  Eigen::Vector3d s(slave.nodes[c.slave_node][0], slave.nodes[c.slave_node][1], slave.nodes[c.slave_node][2]);
  for (size_t k = 0; k < c.master_nodes.size(); ++k) {
    const auto& X = master.nodes[c.master_nodes[k]];
    s -= c.N[k] * Eigen::Vector3d(X[0], X[1], X[2]);
  }
  return s;
}

/// Point j of `from` copied into `to` with its state.
void carry(const PairState& from, size_t j, ContactPoint c, PairState& to) {
  to.points.push_back(std::move(c));
  to.active.push_back(from.active[j]);
  to.anchor.push_back(from.anchor[j]);
  to.slip.push_back(from.slip[j]);
  to.friction_dir.push_back(from.friction_dir[j]);
  to.normal_force.push_back(from.normal_force[j]);
  to.switches.push_back(from.switches[j]);
  to.contact_switches.push_back(from.contact_switches[j]);
  to.slid.push_back(from.slid[j]);
  to.trial_slip.push_back(from.trial_slip[j]);
  to.start_direction.push_back(from.start_direction[j]);
}
}  // namespace

std::vector<PairState> search_contacts(const Model& model) {
  std::vector<PairState> states;
  for (const ContactPair& p : model.contacts) {
    const Mesh& slave = model.bodies[p.slave_body].mesh;
    const Mesh& master = model.bodies[p.master_body].mesh;
    const std::vector<ContactPoint> found =
        find_contact_points(slave, slave.surfaces.at(p.slave_surface), master, master.surfaces.at(p.master_surface),
                            p.search_distance, p.box_search ? FacetCandidates::Boxes : FacetCandidates::All);
    if (found.empty())
      throw std::runtime_error("contact pair '" + p.name + "': no node of surface '" + p.slave_surface + "' of body '" +
                               model.bodies[p.slave_body].name + "' lies over surface '" + p.master_surface +
                               "' of body '" + model.bodies[p.master_body].name + "' within the search distance " +
                               std::to_string(p.search_distance) + ": the surfaces never meet");
    PairState s;
    for (ContactPoint c : found) {
      round_facet(master, p, c);
      add_point(s, c, p.kind == ContactKind::Tied || c.gap <= 1e-9 * p.search_distance);
    }
    states.push_back(std::move(s));
  }
  return states;
}

Eigen::Vector3d relative_position(const ContactPair& p, const ContactPoint& c, const std::vector<Eigen::VectorXd>& u,
                                  int dim) {
  Eigen::Vector3d r = c.separation;
  for (int k = 0; k < dim; ++k) {
    r[k] += u[p.slave_body][c.slave_node * dim + k];
    for (size_t m = 0; m < c.master_nodes.size(); ++m) r[k] -= c.N[m] * u[p.master_body][c.master_nodes[m] * dim + k];
  }
  return r;
}

void follow_contacts(const Model& model, const std::vector<Eigen::VectorXd>& u, std::vector<PairState>& pairs,
                     ContactPair::Sliding when, const std::vector<Eigen::VectorXd>* frames_at) {
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (p.sliding != when) continue;
    const Mesh& slave = model.bodies[p.slave_body].mesh;
    const Mesh& master = model.bodies[p.master_body].mesh;
    const Mesh master_now = displaced(master, u[p.master_body]);
    const Mesh master_frames = frames_at ? displaced(master, (*frames_at)[p.master_body]) : Mesh{};
    std::map<int, size_t> was;
    for (size_t j = 0; j < pairs[i].points.size(); ++j) was[pairs[i].points[j].slave_node] = j;
    PairState now;
    const double touch = 1e-9 * p.search_distance;
    for (ContactPoint& c : find_contact_points(displaced(slave, u[p.slave_body]), slave.surfaces.at(p.slave_surface),
                                               master_now, master.surfaces.at(p.master_surface), p.search_distance,
                                               p.box_search ? FacetCandidates::Boxes : FacetCandidates::All)) {
      c.separation = reference_separation(slave, master, c);
      round_facet(master, p, c);
      const auto it = was.find(c.slave_node);
      if (it == was.end()) {
        add_point(now, c, c.gap <= touch);
        now.anchor.back() = relative_position(p, c, u, model.dim);
        continue;
      }
      const size_t j = it->second;
      const bool stuck = frictional(p.kind) && pairs[i].active[j] && !pairs[i].slip[j];
      if (stuck && p.master_turns) {  // the material it sticks to is not the mesh's: projected anew, the same place
        const Eigen::Vector3d shift =
            relative_position(p, c, u, model.dim) - relative_position(p, pairs[i].points[j], u, model.dim);
        carry(pairs[i], j, std::move(c), now);
        now.anchor.back() += shift;
        continue;
      }
      if (stuck) {  // keeps its master point; the facet's frame turns
        ContactPoint kept = pairs[i].points[j];
        facet_frame(frames_at ? master_frames : master_now, kept.master_nodes, kept.N, kept);
        kept.gap = kept.normal.dot(relative_position(p, kept, u, model.dim)) - kept.offset;
        carry(pairs[i], j, std::move(kept), now);
        continue;
      }
      const bool penetrates = c.gap < -on_surface(p);
      carry(pairs[i], j, std::move(c), now);
      now.active.back() = now.active.back() || penetrates;
    }
    now.master_turn = pairs[i].master_turn;
    pairs[i] = std::move(now);
  }
}

void refind_contacts(const Model& model, const std::vector<Eigen::VectorXd>& u, int body,
                     std::vector<PairState>& pairs) {
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (p.slave_body != body) continue;
    const Mesh& slave = model.bodies[p.slave_body].mesh;
    const Mesh& master = model.bodies[p.master_body].mesh;
    const Mesh master_now = displaced(master, u[p.master_body]);
    std::map<int, size_t> was;
    for (size_t j = 0; j < pairs[i].points.size(); ++j) was[pairs[i].points[j].slave_node] = j;
    PairState now;
    // a point new to a turning master's true surface touches within a rounding (the window's placement and the
    // contact interpolate its radius at points apart); one that touched stays within on_surface
    const double touch = (p.master_turns ? 1e-6 : 1e-9) * p.search_distance;
    for (ContactPoint& c : find_contact_points(displaced(slave, u[p.slave_body]), slave.surfaces.at(p.slave_surface),
                                               master_now, master.surfaces.at(p.master_surface), p.search_distance,
                                               p.box_search ? FacetCandidates::Boxes : FacetCandidates::All)) {
      c.separation = reference_separation(slave, master, c);
      round_facet(master, p, c);
      if (const auto it = was.find(c.slave_node); it != was.end()) {
        carry(pairs[i], it->second, c, now);
        if (c.gap > on_surface(p)) now.active.back() = 0;  // put off the master: free until it touches
      } else
        add_point(now, c, c.gap <= touch);
      now.anchor.back() = relative_position(p, c, u, model.dim);
    }
    now.master_turn = pairs[i].master_turn;
    pairs[i] = std::move(now);
  }
}

namespace {
Eigen::AngleAxisd step_rotation(const ContactPair& p, const PairState& s) {
  const auto& a = p.master_turns->axis;
  return Eigen::AngleAxisd(s.master_turn, Eigen::Vector3d(a[0], a[1], a[2]));
}

Eigen::Vector3d position(const Mesh& m, const Eigen::VectorXd& u, int node) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int k = 0; k < m.dim; ++k) x[k] = m.nodes[node][k] + u[node * m.dim + k];
  return x;
}
}  // namespace

Eigen::Vector3d surface_travel(const Model& model, const ContactPair& p, const PairState& s, const ContactPoint& c,
                               const std::vector<Eigen::VectorXd>& u) {
  if (!p.master_turns || s.master_turn == 0) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d x = position(model.bodies[p.slave_body].mesh, u[p.slave_body], c.slave_node) -
                            Eigen::Vector3d(p.master_turns->center.data());
  return step_rotation(p, s) * x - x;
}

namespace {
/// The pair's slave nodes projected where the master's turning material carries them over the step (u: its start),
/// by slave node, each with its reference separation and the master's true surface (round_facet).
std::map<int, ContactPoint> carried_projections(const Model& model, const ContactPair& p, const PairState& s,
                                                const std::vector<Eigen::VectorXd>& u) {
  const Mesh& slave = model.bodies[p.slave_body].mesh;
  const Mesh& master = model.bodies[p.master_body].mesh;
  Mesh carried = displaced(slave, u[p.slave_body]);
  const Eigen::Vector3d centre(p.master_turns->center.data());
  for (auto& x : carried.nodes) {
    const Eigen::Vector3d y = step_rotation(p, s) * (Eigen::Vector3d(x[0], x[1], x[2]) - centre) + centre;
    for (int k = 0; k < slave.dim; ++k) x[k] = y[k];
  }
  std::map<int, ContactPoint> out;
  for (ContactPoint& c :
       find_contact_points(carried, slave.surfaces.at(p.slave_surface), displaced(master, u[p.master_body]),
                           master.surfaces.at(p.master_surface), p.search_distance,
                           p.box_search ? FacetCandidates::Boxes : FacetCandidates::All)) {
    c.separation = reference_separation(slave, master, c);
    round_facet(master, p, c);
    c.gap = c.normal.dot(relative_position(p, c, u, model.dim)) - c.offset;
    out[c.slave_node] = std::move(c);
  }
  return out;
}
}  // namespace

void turn_master_surfaces(const Model& model, const std::vector<Eigen::VectorXd>& u, double span,
                          std::vector<PairState>& pairs) {
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (!p.master_turns) continue;
    PairState& s = pairs[i];
    s.master_turn = span * p.master_turns->angle;
    // each point projected where the material carries it over the step: its rows hold it to the master's true
    // surface there, and a point that sticks — or enters during the step — ends on the projection it started from
    // (no search again)
    const std::map<int, ContactPoint> ahead = carried_projections(model, p, s, u);
    for (size_t j = 0; j < s.points.size(); ++j) {
      if (const auto it = ahead.find(s.points[j].slave_node); it != ahead.end()) {
        const double weight = s.points[j].weight;
        s.points[j] = it->second;
        s.points[j].weight = weight;
      }
      if (s.active[j] && !s.slip[j])
        s.anchor[j] = relative_position(p, s.points[j], u, model.dim) + surface_travel(model, p, s, s.points[j], u);
    }
  }
}

int projections_moved(const Model& model, const std::vector<Eigen::VectorXd>& u, const std::vector<PairState>& pairs) {
  return projection_drift(model, u, pairs).moved;
}

ProjectionDrift projection_drift(const Model& model, const std::vector<Eigen::VectorXd>& u,
                                 const std::vector<PairState>& pairs) {
  std::vector<PairState> now = pairs;
  follow_contacts(model, u, now, ContactPair::Sliding::Step);
  ProjectionDrift d;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (p.sliding != ContactPair::Sliding::Step) continue;
    std::map<int, double> gap;
    for (size_t j = 0; j < now[i].points.size(); ++j) gap[now[i].points[j].slave_node] = now[i].points[j].gap;
    const double limit = 1e-8 * p.search_distance;
    for (size_t j = 0; j < pairs[i].points.size(); ++j) {
      if (!pairs[i].active[j]) continue;
      const auto it = gap.find(pairs[i].points[j].slave_node);
      const double off = it == gap.end() ? 0.0 : std::abs(it->second);
      if (it != gap.end() && off <= limit) continue;
      ++d.moved;
      if (off >= d.largest) d.largest = off, d.limit = limit;
    }
  }
  return d;
}

namespace {
/// coef_s u_s − Σ N_k u_k projected on `dir` (a unit axis for tied rows, the normal or a tangent for the others).
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

/// The rows of one active point: tied, one per axis; otherwise the normal row, and while the point sticks, one
/// row per tangent holding its relative position at the anchor.
void point_rows(const ContactPair& p, const PairState& s, size_t j, int dim, int pair,
                std::vector<ConstraintRow>& out) {
  const ContactPoint& c = s.points[j];
  auto add = [&](ConstraintRow row, int comp) {
    row.pair = pair, row.point = static_cast<int>(j), row.comp = comp;
    out.push_back(std::move(row));
  };
  if (p.kind == ContactKind::Tied) {
    for (int k = 0; k < dim; ++k) add(relative_motion(p, c, Eigen::Vector3d::Unit(k), dim), k);
    return;
  }
  ConstraintRow normal = relative_motion(p, c, c.normal, dim);
  normal.rhs = c.offset - c.normal.dot(c.separation);  // the gap of the configuration the point was found in
  add(std::move(normal), -1);
  if (!frictional(p.kind) || s.slip[j]) return;
  for (int k = 0; k + 1 < dim; ++k) {
    ConstraintRow t = relative_motion(p, c, c.tangent[k], dim);
    t.rhs = c.tangent[k].dot(s.anchor[j] - c.separation);
    add(std::move(t), k);
  }
}
}  // namespace

std::vector<ConstraintRow> contact_rows(const Model& model, const std::vector<PairState>& pairs) {
  std::vector<ConstraintRow> rows;
  for (size_t i = 0; i < pairs.size(); ++i)
    for (size_t j = 0; j < pairs[i].points.size(); ++j)
      if (pairs[i].active[j]) point_rows(model.contacts[i], pairs[i], j, model.dim, static_cast<int>(i), rows);
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
    if (model.contacts[row.pair].kind != ContactKind::Tied && row.comp < 0 &&
        lambda[static_cast<Eigen::Index>(r)] > tensile && pairs[row.pair].contact_switches[row.point] < 2)
      next[row.pair][row.point] = 0;
  }
  // entering: an inactive point whose gap after deformation is negative beyond on_surface; it sticks where it is
  for (size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& p = model.contacts[i];
    if (p.kind == ContactKind::Tied) continue;
    for (size_t j = 0; j < pairs[i].points.size(); ++j) {
      if (pairs[i].active[j]) continue;
      const ContactPoint& c = pairs[i].points[j];
      const Eigen::Vector3d r = relative_position(p, c, u, model.dim);
      if (c.normal.dot(r) - c.offset >= -on_surface(p)) continue;
      next[i][j] = 1;
      pairs[i].anchor[j] = r;
      pairs[i].slip[j] = 0;
    }
    for (size_t j = 0; j < next[i].size(); ++j)
      if (next[i][j] != pairs[i].active[j]) ++changed, ++pairs[i].contact_switches[j];
    pairs[i].active = next[i];
  }
  return changed;
}

}  // namespace rollsim
