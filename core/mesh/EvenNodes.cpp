#include "mesh/EvenNodes.h"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "mesh/ElementQuality.h"

namespace rollsim {

namespace {
using Point = std::array<double, 3>;
using Names = std::set<std::string>;

/// The boundary of a quad mesh: its edges (those of one element only), the names each edge belongs to (the
/// surfaces holding its facet, the node sets holding both its nodes) and each node's boundary edges.
struct Boundary {
  std::vector<std::array<int, 2>> edges;
  std::vector<Names> names;
  std::map<int, std::vector<int>> at;  // boundary node -> its edges
};

std::vector<Names> node_sets_of(const Mesh& m) {
  std::vector<Names> sets(m.nodes.size());
  for (const auto& [name, nodes] : m.node_sets)
    if (name != "all")
      for (int n : nodes) sets[n].insert(name);
  return sets;
}

Boundary boundary_of(const Mesh& m, const std::vector<Names>& sets) {
  std::map<std::pair<int, int>, std::vector<Facet>> uses;
  for (int e = 0; e < m.num_elements(); ++e)
    for (int local = 0; local < 4; ++local) {
      const std::vector<int> l = facet_local_nodes(m.type, local);
      const int a = m.element(e)[l[0]], b = m.element(e)[l[1]];
      uses[{std::min(a, b), std::max(a, b)}].push_back({e, local});
    }
  std::map<std::pair<int, int>, Names> surface_names;
  for (const auto& [name, facets] : m.surfaces)
    for (const Facet& f : facets) surface_names[{f.element, f.local}].insert(name);
  Boundary bd;
  for (const auto& [ab, facets] : uses) {
    if (facets.size() != 1) continue;
    const int edge = static_cast<int>(bd.edges.size());
    bd.edges.push_back({ab.first, ab.second});
    Names names = surface_names[{facets[0].element, facets[0].local}];
    for (const std::string& s : sets[ab.first])
      if (sets[ab.second].count(s)) names.insert(s);
    bd.names.push_back(std::move(names));
    bd.at[ab.first].push_back(edge);
    bd.at[ab.second].push_back(edge);
  }
  return bd;
}

int other(const Boundary& bd, int edge, int node) {
  return bd.edges[edge][0] == node ? bd.edges[edge][1] : bd.edges[edge][0];
}

/// The boundary nodes that stay where they are (see the header).
std::set<int> features(const Mesh& m, const Boundary& bd, const std::vector<Names>& sets) {
  constexpr double kSharpTurn = 0.7071067811865476;  // cos 45°
  std::set<int> out;
  for (const auto& [node, edges] : bd.at) {
    if (edges.size() != 2 || bd.names[edges[0]] != bd.names[edges[1]]) {
      out.insert(node);
      continue;
    }
    const int prev = other(bd, edges[0], node), next = other(bd, edges[1], node);
    for (const std::string& s : sets[node])
      if (!sets[prev].count(s) && !sets[next].count(s)) out.insert(node);
    const Point &p = m.nodes[prev], &x = m.nodes[node], &q = m.nodes[next];
    const double ax = x[0] - p[0], ay = x[1] - p[1], bx = q[0] - x[0], by = q[1] - x[1];
    const double cosine = (ax * bx + ay * by) / std::sqrt((ax * ax + ay * ay) * (bx * bx + by * by));
    if (cosine < kSharpTurn) out.insert(node);
  }
  return out;
}

double distance(const Point& a, const Point& b) { return std::hypot(b[0] - a[0], b[1] - a[1]); }

/// Cumulative lengths along a chain of nodes at `x`.
std::vector<double> arc_lengths(const std::vector<int>& chain, const std::vector<Point>& x) {
  std::vector<double> s{0.0};
  for (size_t k = 1; k < chain.size(); ++k) s.push_back(s.back() + distance(x[chain[k - 1]], x[chain[k]]));
  return s;
}

/// The chain's inner nodes placed along its current polyline at their original arc-length fractions.
void spread_along(const std::vector<int>& chain, const Mesh& original, const std::vector<Point>& current,
                  std::vector<Point>& out) {
  const std::vector<double> s0 = arc_lengths(chain, original.nodes), s = arc_lengths(chain, current);
  size_t seg = 1;
  for (size_t k = 1; k + 1 < chain.size(); ++k) {
    const double at = s0[k] / s0.back() * s.back();
    while (seg + 1 < chain.size() && s[seg] < at) ++seg;
    const Point &a = current[chain[seg - 1]], &b = current[chain[seg]];
    const double t = s[seg] > s[seg - 1] ? (at - s[seg - 1]) / (s[seg] - s[seg - 1]) : 0.0;
    out[chain[k]] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), 0.0};
  }
}

/// Every stretch of boundary between two features (a loop without one starts and ends at one of its nodes).
std::vector<std::vector<int>> chains(const Boundary& bd, std::set<int> feature) {
  std::vector<std::vector<int>> out;
  std::vector<char> walked(bd.edges.size(), 0);
  auto walk_from = [&](int start) {
    for (int first : bd.at.at(start)) {
      if (walked[first]) continue;
      std::vector<int> chain{start};
      int edge = first, node = start;
      while (true) {
        walked[edge] = 1;
        node = other(bd, edge, node);
        chain.push_back(node);
        if (feature.count(node)) break;
        const std::vector<int>& two = bd.at.at(node);
        edge = two[0] == edge ? two[1] : two[0];
      }
      out.push_back(std::move(chain));
    }
  };
  for (int f : feature) walk_from(f);
  for (size_t e = 0; e < bd.edges.size(); ++e)
    if (!walked[e]) {  // a loop without a feature
      feature.insert(bd.edges[e][0]);
      walk_from(bd.edges[e][0]);
    }
  return out;
}

/// The inner nodes moved by the harmonic extension of the boundary nodes' motion from `from` to `out`, on the mesh's
/// edges weighted by their inverse length at `from` (uniform: every edge alike — the inner nodes then solve Laplace's
/// equation themselves whatever `from` holds: a harmonic map of the boundary, which evens out a shear).
void follow_inside(const Mesh& original, const std::vector<Point>& from, bool uniform,
                   const std::map<int, std::vector<int>>& on_boundary, std::vector<Point>& out) {
  const int n = original.num_nodes();
  std::vector<int> inner(n, -1);
  int count = 0;
  for (int i = 0; i < n; ++i)
    if (!on_boundary.count(i)) inner[i] = count++;
  if (count == 0) return;
  std::set<std::pair<int, int>> links;
  for (int e = 0; e < original.num_elements(); ++e)
    for (int a = 0; a < 4; ++a) {
      const int i = original.element(e)[a], j = original.element(e)[(a + 1) % 4];
      links.insert({std::min(i, j), std::max(i, j)});
    }
  std::vector<Eigen::Triplet<double>> t;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(count, 2);
  auto link = [&](int i, int j) {  // node i's equation: Σ (w_i − w_j) / |X_i − X_j| = 0
    if (inner[i] < 0) return;
    const double k = uniform ? 1.0 : 1 / distance(from[i], from[j]);
    t.emplace_back(inner[i], inner[i], k);
    if (inner[j] >= 0)
      t.emplace_back(inner[i], inner[j], -k);
    else
      for (int c = 0; c < 2; ++c) rhs(inner[i], c) += k * (out[j][c] - (uniform ? 0.0 : from[j][c]));
  };
  for (const auto& [i, j] : links) link(i, j), link(j, i);
  Eigen::SparseMatrix<double> L(count, count);
  L.setFromTriplets(t.begin(), t.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(L);
  const Eigen::MatrixX2d w = solver.solve(rhs);
  for (int i = 0; i < n; ++i)
    if (inner[i] >= 0)
      out[i] = uniform ? Point{w(inner[i], 0), w(inner[i], 1), 0.0}
                       : Point{from[i][0] + w(inner[i], 0), from[i][1] + w(inner[i], 1), 0.0};
}

/// How much worse (a share of the best candidate's worst corner sine) a spread that keeps more of the original may
/// shape its worst element and still be chosen.
constexpr double kShapeMargin = 0.1;

/// The worst corner sine of the mesh's elements with its nodes at x (≤ 0: an element folds).
double worst_sine(const Mesh& m, const std::vector<Point>& x) {
  double worst = 1;
  for (int e = 0; e < m.num_elements(); ++e) worst = std::min(worst, corner_sine(m, x, e));
  return worst;
}
/// The unit normal of the line through the nodes `face` at `x`, pointing to `inside`, and a point on it; false when
/// the face's nodes do not lie on one line (within 1e-6 of its length).
bool face_line(const std::vector<int>& face, const std::vector<Point>& x, const Point& inside, Point& on, Point& n) {
  auto farthest = [&](const Point& from) {
    int best = face[0];
    for (int f : face)
      if (distance(x[f], from) > distance(x[best], from)) best = f;
    return x[best];
  };
  on = farthest(x[face[0]]);
  const Point end = farthest(on);
  const double length = distance(on, end);
  if (length <= 0) return false;
  n = {-(end[1] - on[1]) / length, (end[0] - on[0]) / length, 0.0};
  const auto side = [&](const Point& q) { return (q[0] - on[0]) * n[0] + (q[1] - on[1]) * n[1]; };
  if (side(inside) < 0) n = {-n[0], -n[1], 0.0};
  for (int f : face)
    if (std::abs(side(x[f])) > 1e-6 * length) return false;
  return true;
}

/// Free boundary nodes that have crossed the line of a face stuck to a tool (the nodes of `faces`, each on one line)
/// fold onto it: the face's corner node moves to where the free boundary crosses back over the line, and the crossed
/// nodes with it — the folded material lies on the tool now, and the grid's corner follows the boundary's corner
/// (the spread along the chains then places them: the face's nodes along the line, the free ones down the side).
std::vector<Point> fold_onto_faces(const Boundary& bd, const std::vector<std::vector<int>>& faces,
                                   std::vector<Point> x) {
  Point centre{0, 0, 0};
  const double count = static_cast<double>(x.size());
  for (const Point& p : x) centre = {centre[0] + p[0] / count, centre[1] + p[1] / count, 0.0};
  for (const std::vector<int>& face : faces) {
    Point on, n;
    if (face.size() < 2 || !face_line(face, x, centre, on, n)) continue;
    const auto side = [&](const Point& q) { return (q[0] - on[0]) * n[0] + (q[1] - on[1]) * n[1]; };
    const std::set<int> in(face.begin(), face.end());
    for (int c : face) {
      const auto at = bd.at.find(c);
      if (at == bd.at.end()) continue;
      for (int edge : at->second) {
        int prev = c, node = other(bd, edge, c), walked = edge;
        std::vector<int> folded;
        while (!in.count(node) && side(x[node]) < 0 && bd.at.at(node).size() == 2) {
          folded.push_back(node);
          const std::vector<int>& two = bd.at.at(node);
          walked = two[0] == walked ? two[1] : two[0];
          prev = node, node = other(bd, walked, prev);
        }
        if (folded.empty() || in.count(node)) continue;
        const double d0 = side(x[folded.back()]), d1 = side(x[node]), t = d0 / (d0 - d1);
        const Point& a = x[folded.back()];
        const Point crossing{a[0] + t * (x[node][0] - a[0]), a[1] + t * (x[node][1] - a[1]), 0.0};
        x[c] = crossing;
        for (int f : folded) x[f] = crossing;
      }
    }
  }
  return x;
}
}  // namespace

std::vector<Point> even_nodes(const Mesh& original, const std::vector<Point>& current_nodes,
                              const std::vector<int>& staying, const std::vector<std::vector<int>>& faces) {
  if (original.type != ElementType::Quad4)
    throw std::invalid_argument("even_nodes: a 2D quad mesh only (this one has " +
                                std::to_string(original.nodes_per_elem()) + "-node elements)");
  const std::vector<Names> sets = node_sets_of(original);
  const Boundary bd = boundary_of(original, sets);
  const std::vector<Point> current = fold_onto_faces(bd, faces, current_nodes);
  std::vector<Point> boundary = current;
  std::set<int> feature = features(original, bd, sets);
  for (int n : staying)
    if (bd.at.count(n)) feature.insert(n);
  for (const std::vector<int>& chain : chains(bd, feature)) spread_along(chain, original, current, boundary);
  // the inner nodes by the motion since the original mesh, by the boundary's correction from where they are, or as
  // a harmonic map of the boundary: the first, in that order, whose worst element is within kShapeMargin of the best
  // shaped (the first keeps a graded spread where the motion is smooth, the second changes least, the third evens out
  // a shear — and a grading with it: a hot slab's top elements, graded for its chilled skin, became 1.5 times as
  // thick for a worst corner sine of 0.693 against the graded spread's 0.660)
  std::vector<std::vector<Point>> candidates(3, boundary);
  follow_inside(original, original.nodes, false, bd.at, candidates[0]);
  follow_inside(original, current, false, bd.at, candidates[1]);
  follow_inside(original, current, true, bd.at, candidates[2]);
  std::vector<double> shape;
  for (const std::vector<Point>& c : candidates) shape.push_back(worst_sine(original, c));
  const double best = *std::max_element(shape.begin(), shape.end());
  for (size_t c = 0; c < candidates.size(); ++c)
    if (shape[c] >= best - kShapeMargin * std::abs(best)) return candidates[c];
  return candidates.back();
}

}  // namespace rollsim
