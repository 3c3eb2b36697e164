#include "mesh/ElementQuality.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace rollsim {

namespace {
using Point = std::array<double, 3>;

Point edge(const Point& from, const Point& to) { return {to[0] - from[0], to[1] - from[1], to[2] - from[2]}; }

double triple(const Point& a, const Point& b, const Point& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/// The corner Jacobian at local corner `i` of the element's points `x` (Q4 or H8, VTK order).
double corner_jacobian(const std::vector<Point>& x, int i) {
  if (x.size() == 4) {
    const Point a = edge(x[i], x[(i + 1) % 4]), b = edge(x[i], x[(i + 3) % 4]);
    return a[0] * b[1] - a[1] * b[0];
  }
  const int base = i < 4 ? 0 : 4, k = i - base, other = i < 4 ? i + 4 : i - 4;
  const Point a = edge(x[i], x[base + (k + 1) % 4]), b = edge(x[i], x[base + (k + 3) % 4]), c = edge(x[i], x[other]);
  return triple(a, b, c);
}
}  // namespace

double corner_jacobian_ratio(const Mesh& mesh, const double* u, int e) {
  const int n = mesh.nodes_per_elem(), dim = mesh.dim;
  const int* nodes = mesh.element(e);
  std::vector<Point> ref(n), def(n);
  for (int a = 0; a < n; ++a) {
    ref[a] = def[a] = mesh.nodes[nodes[a]];
    for (int c = 0; c < dim; ++c) def[a][c] += u[nodes[a] * dim + c];
  }
  double worst = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const double r = corner_jacobian(ref, i);
    if (r != 0) worst = std::min(worst, corner_jacobian(def, i) / r);
  }
  return worst == std::numeric_limits<double>::infinity() ? 1.0 : worst;  // no corner of positive size: degenerate
}

double corner_sine(const Mesh& mesh, const std::vector<Point>& x, int e) {
  const int n = mesh.nodes_per_elem();
  std::vector<Point> at(n);
  for (int a = 0; a < n; ++a) at[a] = x[mesh.element(e)[a]];
  auto length = [](const Point& p) { return std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]); };
  double worst = 1;
  for (int i = 0; i < n; ++i) {
    double edges =
        length(edge(at[i], at[(i % 4 + 1) % 4 + i / 4 * 4])) * length(edge(at[i], at[(i % 4 + 3) % 4 + i / 4 * 4]));
    if (n == 8) edges *= length(edge(at[i], at[i < 4 ? i + 4 : i - 4]));
    if (edges > 0) worst = std::min(worst, corner_jacobian(at, i) / edges);
  }
  return worst;
}

}  // namespace rollsim
