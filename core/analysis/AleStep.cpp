#include "analysis/AleStep.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/AnalysisError.h"
#include "fem/SolidElement.h"
#include "material/Material.h"

namespace rollsim {

namespace {
/// A continuous field through the point values: each element's point values extrapolated to its corners, averaged at
/// the nodes (`width` per node).
template <int D>
std::vector<double> recovered(const Mesh& m, const std::vector<double>& values, int width) {
  using E = SolidElement<D>;
  std::vector<double> R(static_cast<size_t>(m.num_nodes()) * width, 0.0), count(m.num_nodes(), 0.0);
  for (int e = 0; e < m.num_elements(); ++e) {
    for (int a = 0; a < E::NN; ++a) count[m.element(e)[a]] += 1;
    for (int c = 0; c < width; ++c) {
      std::array<double, E::NGP> gp;
      for (int p = 0; p < E::NGP; ++p) gp[p] = values[(static_cast<size_t>(e) * E::NGP + p) * width + c];
      for (int a = 0; a < E::NN; ++a)
        R[static_cast<size_t>(m.element(e)[a]) * width + c] += E::extrapolate_to_node(gp, a);
    }
  }
  for (size_t n = 0; n < count.size(); ++n)
    for (int c = 0; c < width; ++c) R[n * width + c] /= count[n];
  return R;
}

/// Component c of the nodal field R at the point of element e whose shape functions are N.
template <int D>
double at(const Mesh& m, const std::vector<double>& R, int width, int e,
          const Eigen::Matrix<double, SolidElement<D>::NN, 1>& N, int c) {
  double v = 0;
  for (int a = 0; a < SolidElement<D>::NN; ++a) v += N[a] * R[static_cast<size_t>(m.element(e)[a]) * width + c];
  return v;
}

/// How far across element e (its nodes at `x`) a point moving by d has gone: |d| over the element's extent along d,
/// at most 1.
double crossed(const Mesh& m, const std::vector<Point3>& x, int e, const Point3& d) {
  const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (length == 0) return 0;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int a = 0; a < m.nodes_per_elem(); ++a) {
    const Point3& p = x[static_cast<size_t>(m.element(e)[a])];
    const double t = (p[0] * d[0] + p[1] * d[1] + p[2] * d[2]) / length;
    lo = std::min(lo, t), hi = std::max(hi, t);
  }
  return std::min(1.0, length / (hi - lo));
}

/// Per element: whether a node of it lies on the inflow face (its range of values then includes the virgin state).
std::vector<char> at_inflow(const Mesh& m, const std::vector<int>& face) {
  std::vector<char> on(static_cast<size_t>(m.num_nodes()), 0), out(static_cast<size_t>(m.num_elements()), 0);
  for (int n : face) on[static_cast<size_t>(n)] = 1;
  for (int e = 0; e < m.num_elements(); ++e)
    for (int a = 0; a < m.nodes_per_elem(); ++a) out[static_cast<size_t>(e)] |= on[m.element(e)[a]];
  return out;
}

template <int D>
std::vector<double> advected(const Mesh& from, const std::vector<Point3>& x, const std::vector<double>& values,
                             int width, const Mesh& to, const MeshMotion& motion) {
  using E = SolidElement<D>;
  std::vector<double> R = recovered<D>(from, values, width);
  const std::vector<int> face = motion.inflow_face();
  for (int n : face)  // the inflow boundary holds the virgin state, not the first elements' values extrapolated
    std::fill_n(R.begin() + static_cast<long>(n) * width, width, 0.0);
  const std::vector<char> inflow_element = at_inflow(from, face);
  const std::vector<Point3> points = integration_points(to);
  const PointLocator locator(from, x);
  const std::vector<Point3> went = integration_points(from, x);  // where each old point's material is now
  std::vector<double> out(values.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const auto value = out.begin() + static_cast<long>(i * width);
    if (motion.inflow(points[i], x)) {
      std::fill(value, value + width, 0.0);
      continue;
    }
    const int e = static_cast<int>(i) / E::NGP;  // the point's own element, whose point i was at `values`' i
    const MeshPlace place = locator.locate(points[i], e);
    const double xi[3] = {place.xi, place.eta, place.zeta};
    Eigen::Matrix<double, E::NN, 1> here;
    Eigen::Matrix<double, D, E::NN> dN;
    E::shape_at(xi, here, dN);
    const Eigen::Matrix<double, E::NN, 1> own = E::gauss_shape().row(static_cast<long>(i) % E::NGP).transpose();
    const Point3 d{went[i][0] - points[i][0], went[i][1] - points[i][1], went[i][2] - points[i][2]};
    const double kept = 1.0 - crossed(from, x, e, d);  // of the point's own part, what stays in its element
    for (int c = 0; c < width; ++c) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (int k : {place.element, e}) {
        for (int q = 0; q < E::NGP; ++q) {
          const double v = values[(static_cast<size_t>(k) * E::NGP + q) * width + c];
          lo = std::min(lo, v), hi = std::max(hi, v);
        }
        if (inflow_element[static_cast<size_t>(k)]) lo = std::min(lo, 0.0), hi = std::max(hi, 0.0);
      }
      const double own_part = values[i * width + c] - at<D>(from, R, width, e, own, c);
      value[c] = std::clamp(at<D>(from, R, width, place.element, here, c) + kept * own_part, lo, hi);
    }
  }
  return out;
}
}  // namespace

std::vector<double> advected_points(const Mesh& from, const std::vector<Point3>& x, const std::vector<double>& values,
                                    int width, const Mesh& to, const MeshMotion& motion) {
  return from.dim == 2 ? advected<2>(from, x, values, width, to, motion)
                       : advected<3>(from, x, values, width, to, motion);
}

AleRemap ale_remap(const Body& body, const Eigen::VectorXd& u, const std::vector<double>& committed,
                   const std::vector<MeshMotion::Positions>& current, const std::vector<char>& touching,
                   const MeshMotion& motion) {
  const std::vector<Point3>& x = current[static_cast<size_t>(motion.body())];
  Mesh placed = body.mesh;
  placed.nodes = motion.placed(current, touching);
  try {
    check_element_orientation(placed);
  } catch (const std::runtime_error& e) {
    throw AnalysisError("the mesh of body '" + body.name + "' put back in place would fold an element (" + e.what() +
                        ")");
  }
  AleRemap r;
  const int width = make_material(body.material)->state_size();
  if (width > 0) r.state = advected_points(body.mesh, x, current_state(body, u, committed), width, placed, motion);
  r.nodes = std::move(placed.nodes);
  return r;
}

}  // namespace rollsim
