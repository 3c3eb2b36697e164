#include "fem/StateTransfer.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>

#include "fem/SolidElement.h"
#include "material/Material.h"

namespace rollsim {

namespace {
using El = SolidElement<2>;
constexpr int kSigns[2][4] = {{-1, 1, 1, -1}, {-1, -1, 1, 1}};

Eigen::Vector4d bilinear(double xi, double eta) {
  Eigen::Vector4d N;
  for (int a = 0; a < 4; ++a) N[a] = 0.25 * (1 + kSigns[0][a] * xi) * (1 + kSigns[1][a] * eta);
  return N;
}

El::Coords coords(const Mesh& m, const std::vector<Point3>& x, int e) {
  El::Coords c;
  for (int a = 0; a < 4; ++a) c.col(a) << x[m.element(e)[a]][0], x[m.element(e)[a]][1];
  return c;
}

void require_quads(const Mesh& m) {
  if (m.type != ElementType::Quad4) throw std::invalid_argument("state transfer: 2D quad meshes only");
}

/// The weights of an element's four Gauss points at (ξ, η): the bilinear interpolation through them (at ±1/√3), (ξ, η)
/// held within their square — all in [0, 1], summing to 1.
Eigen::Vector4d gauss_weights(double xi, double eta) {
  const double g = std::sqrt(3.0);
  return bilinear(std::clamp(xi * g, -1.0, 1.0), std::clamp(eta * g, -1.0, 1.0));
}

/// The values at `place` interpolated from nodal values (`width` per node).
void interpolate(const Mesh& m, const std::vector<double>& nodal, int width, const MeshPlace& place, double* out) {
  const Eigen::Vector4d N = bilinear(place.xi, place.eta);
  for (int c = 0; c < width; ++c) {
    out[c] = 0;
    for (int a = 0; a < 4; ++a) out[c] += N[a] * nodal[static_cast<size_t>(m.element(place.element)[a]) * width + c];
  }
}

/// Values of `from` (nodal, `width` each) at the points `at`, each searched from the element `near[i]`.
std::vector<double> sample(const Mesh& from, const std::vector<Point3>& x, const std::vector<double>& nodal, int width,
                           const std::vector<Point3>& at, const std::vector<int>& near) {
  const PointLocator locator(from, x);
  std::vector<double> out(at.size() * width);
  for (size_t i = 0; i < at.size(); ++i)
    interpolate(from, nodal, width, locator.locate(at[i], near[i]), out.data() + i * width);
  return out;
}

int clamp_element(int e, const Mesh& m) { return std::clamp(e, 0, m.num_elements() - 1); }
}  // namespace

PointLocator::PointLocator(const Mesh& mesh, const std::vector<Point3>& x) : mesh_(mesh), x_(x) {
  const int nn = mesh.nodes_per_elem();
  std::vector<std::vector<int>> of_node(mesh.num_nodes());
  for (int e = 0; e < mesh.num_elements(); ++e)
    for (int a = 0; a < nn; ++a) of_node[mesh.element(e)[a]].push_back(e);
  neighbours_.resize(mesh.num_elements());
  for (int e = 0; e < mesh.num_elements(); ++e) {
    for (int a = 0; a < nn; ++a)
      for (int f : of_node[mesh.element(e)[a]])
        if (f != e) neighbours_[e].push_back(f);
    std::sort(neighbours_[e].begin(), neighbours_[e].end());
    neighbours_[e].erase(std::unique(neighbours_[e].begin(), neighbours_[e].end()), neighbours_[e].end());
  }
}

namespace {
/// Local coordinates of p in element e (nodes at x) by Newton on the isoparametric map, clamped to the element; the
/// distance left.
template <int D>
double local_in(const Mesh& m, const std::vector<Point3>& x, int e, const Point3& p, double* xi) {
  using E = SolidElement<D>;
  typename E::Coords c;
  for (int a = 0; a < E::NN; ++a)
    for (int k = 0; k < D; ++k) c(k, a) = x[m.element(e)[a]][k];
  Eigen::Matrix<double, D, 1> target;
  for (int k = 0; k < D; ++k) target[k] = p[k];
  Eigen::Matrix<double, E::NN, 1> N;
  Eigen::Matrix<double, D, E::NN> dN;
  for (int k = 0; k < 3; ++k) xi[k] = 0;
  for (int it = 0; it < 30; ++it) {
    E::shape_at(xi, N, dN);
    const Eigen::Matrix<double, D, 1> r = c * N - target;
    const Eigen::Matrix<double, D, D> J = c * dN.transpose();  // J(k, i) = dx_k / dξ_i
    const Eigen::Matrix<double, D, 1> d = J.fullPivLu().solve(r);
    if (!d.allFinite()) break;
    for (int k = 0; k < D; ++k) xi[k] = std::clamp(xi[k] - d[k], -2.0, 2.0);
    if (d.norm() < 1e-13) break;
  }
  for (int k = 0; k < D; ++k) xi[k] = std::clamp(xi[k], -1.0, 1.0);
  E::shape_at(xi, N, dN);
  return (c * N - target).norm();
}
}  // namespace

double PointLocator::local(int e, const Point3& p, double* xi) const {
  return mesh_.dim == 2 ? local_in<2>(mesh_, x_, e, p, xi) : local_in<3>(mesh_, x_, e, p, xi);
}

MeshPlace PointLocator::locate(const Point3& p, int near) const {
  std::vector<char> seen(mesh_.num_elements(), 0);
  std::deque<int> queue{clamp_element(near, mesh_)};
  seen[queue.front()] = 1;
  MeshPlace best;
  double best_distance = std::numeric_limits<double>::infinity();
  while (!queue.empty()) {
    const int e = queue.front();
    queue.pop_front();
    double xi[3];
    const double d = local(e, p, xi);
    if (d < best_distance) best_distance = d, best = {e, xi[0], xi[1], xi[2]};
    const Point3& lo = x_[mesh_.element(e)[0]];
    const Point3& hi = x_[mesh_.element(e)[mesh_.dim == 2 ? 2 : 6]];
    const double size = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    if (d <= 1e-9 * size) return best;
    for (int f : neighbours_[e])
      if (!seen[f]) seen[f] = 1, queue.push_back(f);
  }
  return best;
}

std::vector<Point3> displaced_nodes(const Mesh& mesh, const Eigen::VectorXd& u) {
  std::vector<Point3> x = mesh.nodes;
  for (int n = 0; n < mesh.num_nodes(); ++n)
    for (int c = 0; c < mesh.dim; ++c) x[n][c] += u[static_cast<Eigen::Index>(n) * mesh.dim + c];
  return x;
}

namespace {
template <int D>
std::vector<double> current_state_in(const Body& body, const Eigen::VectorXd& u, std::vector<double> state, int width) {
  using E = SolidElement<D>;
  const Mesh& m = body.mesh;
  const auto material = make_material(body.material);
  for (int e = 0; e < m.num_elements(); ++e) {
    typename E::Coords x;
    for (int a = 0; a < E::NN; ++a)
      for (int k = 0; k < D; ++k) x(k, a) = m.nodes[m.element(e)[a]][k];
    std::array<typename E::Gradients, E::NGP> dN;
    std::array<double, E::NGP> dv;
    typename E::Gradients centre;
    E::gradients(x, dN, dv, centre);
    auto gradient = [&](const typename E::Gradients& g) {
      Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
      for (int a = 0; a < E::NN; ++a)
        for (int i = 0; i < D; ++i)
          for (int k = 0; k < D; ++k) F(i, k) += u[static_cast<Eigen::Index>(m.element(e)[a]) * D + i] * g(k, a);
      return F;
    };
    const double Jc = gradient(centre).determinant();
    for (int p = 0; p < E::NGP; ++p) {
      Eigen::Matrix3d F = gradient(dN[p]);
      if (body.formulation == Formulation::BBar)  // F̄ = (J_0 / J)^{1/D} F: the centre's volume change
        F.template topLeftCorner<D, D>() *= std::pow(Jc / F.determinant(), 1.0 / D);
      material->rebase_state(F, state.data() + (static_cast<size_t>(e) * E::NGP + p) * width);
    }
  }
  return state;
}
}  // namespace

std::vector<double> current_state(const Body& body, const Eigen::VectorXd& u, std::vector<double> state) {
  const int width = make_material(body.material)->state_size();
  if (width == 0) return state;
  return body.mesh.dim == 2 ? current_state_in<2>(body, u, std::move(state), width)
                            : current_state_in<3>(body, u, std::move(state), width);
}

namespace {
template <int D>
std::vector<Point3> integration_points_in(const Mesh& mesh, const std::vector<Point3>& x) {
  using E = SolidElement<D>;
  std::vector<Point3> at;
  const auto& N = E::gauss_shape();
  for (int e = 0; e < mesh.num_elements(); ++e)
    for (int p = 0; p < E::NGP; ++p) {
      Point3 q{0, 0, 0};
      for (int a = 0; a < E::NN; ++a)
        for (int c = 0; c < D; ++c) q[c] += N(p, a) * x[static_cast<size_t>(mesh.element(e)[a])][c];
      at.push_back(q);
    }
  return at;
}
}  // namespace

std::vector<Point3> integration_points(const Mesh& mesh) { return integration_points(mesh, mesh.nodes); }

std::vector<Point3> integration_points(const Mesh& mesh, const std::vector<Point3>& x) {
  return mesh.dim == 2 ? integration_points_in<2>(mesh, x) : integration_points_in<3>(mesh, x);
}

std::vector<double> transfer_points(const Mesh& from, const std::vector<Point3>& x, const std::vector<double>& values,
                                    int width, const Mesh& to) {
  require_quads(to);
  const std::vector<Point3> at = integration_points(to);
  std::vector<int> near;  // the same numbers: a remesh keeps the elements
  for (size_t i = 0; i < at.size(); ++i) near.push_back(clamp_element(static_cast<int>(i) / El::NGP, from));
  const PointLocator locator(from, x);
  std::vector<double> out(at.size() * width);
  for (size_t i = 0; i < at.size(); ++i) {
    const MeshPlace place = locator.locate(at[i], near[i]);
    const Eigen::Vector4d w = gauss_weights(place.xi, place.eta);
    for (int c = 0; c < width; ++c)
      for (int p = 0; p < El::NGP; ++p)
        out[i * width + c] += w[p] * values[(static_cast<size_t>(place.element) * El::NGP + p) * width + c];
  }
  return out;
}

namespace {
/// A point of an element's reference square and its quadrature weight.
struct LocalPoint {
  double xi, eta, weight;
};

/// Gauss–Legendre's 4 × 4 points on each quarter of the reference square: a transfer's defect integrated over a new
/// element (the old field is bilinear on pieces of it: its kinks cost 16 points over the whole square 7e-3 of a steep
/// layer's deficit, these 64 under 1e-3).
const std::vector<LocalPoint>& quarter_points() {
  static const std::vector<LocalPoint> points = [] {
    constexpr double g[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
    constexpr double w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};
    std::vector<LocalPoint> out;
    for (const double cx : {-0.5, 0.5})
      for (const double cy : {-0.5, 0.5})
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 4; ++j) out.push_back({cx + 0.5 * g[i], cy + 0.5 * g[j], 0.25 * w[i] * w[j]});
    return out;
  }();
  return points;
}

/// ∫ N_n (old − new) dV and ∫ N_n dV over `to`'s elements, per node of `to`: the old field (`values` at the nodes of
/// `from`, placed at `x`) against the new one (`carried` at `to`'s nodes).
std::pair<std::vector<double>, std::vector<double>> lost_per_node(const Mesh& from, const std::vector<Point3>& x,
                                                                  const std::vector<double>& values, const Mesh& to,
                                                                  const std::vector<double>& carried) {
  const PointLocator locator(from, x);
  std::vector<double> lost(to.num_nodes(), 0.0), mass(to.num_nodes(), 0.0);
  for (int e = 0; e < to.num_elements(); ++e) {
    const El::Coords c = coords(to, to.nodes, e);
    for (const LocalPoint& q : quarter_points()) {
      const double xi[2] = {q.xi, q.eta};
      Eigen::Vector4d N;
      Eigen::Matrix<double, 2, 4> dN;
      El::shape_at(xi, N, dN);
      const double dv = q.weight * (c * dN.transpose()).determinant();
      const Eigen::Vector2d p = c * N;
      double old_value = 0, new_value = 0;
      interpolate(from, values, 1, locator.locate({p[0], p[1], 0.0}, clamp_element(e, from)), &old_value);
      for (int a = 0; a < 4; ++a) new_value += N[a] * carried[to.element(e)[a]];
      for (int a = 0; a < 4; ++a) {
        lost[to.element(e)[a]] += N[a] * (old_value - new_value) * dv;
        mass[to.element(e)[a]] += N[a] * dv;
      }
    }
  }
  return {lost, mass};
}

/// Nodal values held within [lo, hi] keeping Σ mass_n v_n (a repair of a conservative remap): what a node has beyond
/// a bound goes to the nodes of its elements that have room, in proportion to their room (a thin chilled skin under a
/// node moved deeper warms the surface nodes over it rather than heat a node past the hottest value), sweep after
/// sweep while any is left.
void hold_within(const Mesh& m, const std::vector<double>& mass, double lo, double hi, std::vector<double>& v) {
  std::vector<std::vector<int>> around(v.size());
  for (int e = 0; e < m.num_elements(); ++e)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (a != b) around[m.element(e)[a]].push_back(m.element(e)[b]);
  for (auto& list : around) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  for (int sweep = 0; sweep < 8; ++sweep) {
    bool moved = false;
    for (size_t n = 0; n < v.size(); ++n) {
      const double over = v[n] - std::clamp(v[n], lo, hi);
      if (over == 0.0 || !(mass[n] > 0)) continue;
      const double sign = over > 0 ? 1.0 : -1.0;
      const auto gap = [&](int k) { return std::max(0.0, over > 0 ? hi - v[k] : v[k] - lo); };
      double room = 0;  // what the neighbours can take, mass × their distance to the bound
      for (int k : around[n]) room += mass[k] * gap(k);
      const double excess = std::abs(over) * mass[n];
      const double share = room > 0 ? std::min(1.0, excess / room) : 0.0;
      for (int k : around[n]) v[k] += sign * share * gap(k);
      v[n] = (over > 0 ? hi : lo) + sign * (excess - share * room) / mass[n];
      moved = true;
    }
    if (!moved) break;
  }
}
}  // namespace

std::vector<double> transfer_nodes(const Mesh& from, const std::vector<Point3>& x, const std::vector<double>& values,
                                   const Mesh& to) {
  require_quads(to);
  std::vector<int> of_node(to.num_nodes(), 0);
  for (int e = 0; e < to.num_elements(); ++e)
    for (int a = 0; a < 4; ++a) of_node[to.element(e)[a]] = e;
  for (int& e : of_node) e = clamp_element(e, from);
  std::vector<double> out = sample(from, x, values, 1, to.nodes, of_node);
  // interpolated at nodes that moved across a steep layer (a chilled skin), the field loses its kinks, and with them
  // part of its integral (the rolling pass's slab lost 1.3 K of its mean in one remesh): the lumped projection of what
  // was lost is given back, where it was lost
  const auto [lost, mass] = lost_per_node(from, x, values, to, out);
  for (size_t n = 0; n < out.size(); ++n)
    if (mass[n] > 0) out[n] += lost[n] / mass[n];
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  hold_within(to, mass, *lo, *hi, out);
  return out;
}

double integral(const Mesh& mesh, const std::vector<Point3>& x, const std::vector<double>& values, int width,
                int component) {
  double sum = 0;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    std::array<El::Gradients, El::NGP> dN;
    std::array<double, El::NGP> dv;
    El::Gradients centre;
    El::gradients(coords(mesh, x, e), dN, dv, centre);
    for (int p = 0; p < El::NGP; ++p) sum += dv[p] * values[(static_cast<size_t>(e) * El::NGP + p) * width + component];
  }
  return sum;
}

}  // namespace rollsim
