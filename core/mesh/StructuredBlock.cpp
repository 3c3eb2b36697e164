#include "mesh/StructuredBlock.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

namespace rollsim {

namespace {
// Axis permutation: order[0] is the fastest-varying axis in the numbering (the one with fewest elements).
std::array<int, 3> numbering_order(const BlockSpec& s) {
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.begin() + s.dim, [&](int a, int b) { return s.n[a] < s.n[b]; });
  return order;
}
// The coordinate along `axis` of node i: the uniform expression unchanged when there is no grading.
double node_at(const BlockSpec& s, int axis, int i) {
  const auto a = static_cast<size_t>(axis);
  if (axis == 0 && !s.x_planes.empty()) return s.x_planes[static_cast<size_t>(i)];
  if (s.grading[a] == 1.0) return s.origin[a] + s.size[a] * i / s.n[a];
  return s.origin[a] + s.size[a] * graded_fraction(i, s.n[a], s.grading[a]);
}
}  // namespace

double graded_fraction(int i, int n, double grading) {
  if (i >= n) return 1.0;
  if (grading == 1.0) return static_cast<double>(i) / n;
  const double q = 1.0 / grading;
  return (1.0 - std::pow(q, i)) / (1.0 - std::pow(q, n));
}

Mesh make_block(const BlockSpec& s) {
  for (int a = 0; a < 3; ++a)
    if (!(std::isfinite(s.grading[static_cast<size_t>(a)]) && s.grading[static_cast<size_t>(a)] > 0.0))
      throw std::invalid_argument(std::string("BlockSpec.grading along ") + "xyz"[a] + " must be a positive number");
  if (!s.x_planes.empty() &&
      (s.x_planes.size() != static_cast<size_t>(s.n[0]) + 1 ||
       std::adjacent_find(s.x_planes.begin(), s.x_planes.end(), std::greater_equal<>()) != s.x_planes.end()))
    throw std::invalid_argument("BlockSpec.x_planes must hold nx + 1 increasing coordinates");
  Mesh m;
  m.dim = s.dim;
  m.type = s.dim == 2 ? ElementType::Quad4 : ElementType::Hex8;
  const int nz = s.dim == 3 ? s.n[2] : 0;
  const std::array<int, 3> np{s.n[0] + 1, s.n[1] + 1, nz + 1};
  const auto ord = numbering_order(s);
  // stride of each axis in the node numbering
  std::array<long, 3> stride{};
  long st = 1;
  for (int k = 0; k < 3; ++k) {
    stride[ord[k]] = st;
    st *= np[ord[k]];
  }
  auto node_id = [&](int i, int j, int k) { return static_cast<int>(i * stride[0] + j * stride[1] + k * stride[2]); };
  m.nodes.resize(static_cast<size_t>(np[0]) * np[1] * np[2]);
  for (int k = 0; k < np[2]; ++k)
    for (int j = 0; j < np[1]; ++j)
      for (int i = 0; i < np[0]; ++i) {
        m.nodes[node_id(i, j, k)] = {node_at(s, 0, i), node_at(s, 1, j), s.dim == 3 ? node_at(s, 2, k) : 0.0};
      }

  // elements, numbered with the same axis order as the nodes
  std::array<int, 3> ne{s.n[0], s.n[1], std::max(nz, 1)};
  std::array<int, 3> idx{};
  const int total = ne[0] * ne[1] * ne[2];
  auto& all = m.element_sets["all"];
  auto add_facet = [&](const char* name, int e, int local) { m.surfaces[name].push_back({e, local}); };
  for (int e = 0; e < total; ++e) {
    int rem = e;
    for (int k = 0; k < 3; ++k) {
      idx[ord[k]] = rem % ne[ord[k]];
      rem /= ne[ord[k]];
    }
    const int i = idx[0], j = idx[1], k = s.dim == 3 ? idx[2] : 0;
    if (s.dim == 2) {
      for (int v : {node_id(i, j, 0), node_id(i + 1, j, 0), node_id(i + 1, j + 1, 0), node_id(i, j + 1, 0)})
        m.connectivity.push_back(v);
      if (j == 0) add_facet("ymin", e, 0);
      if (i == s.n[0] - 1) add_facet("xmax", e, 1);
      if (j == s.n[1] - 1) add_facet("ymax", e, 2);
      if (i == 0) add_facet("xmin", e, 3);
    } else {
      for (int kk : {k, k + 1})
        for (int v : {node_id(i, j, kk), node_id(i + 1, j, kk), node_id(i + 1, j + 1, kk), node_id(i, j + 1, kk)})
          m.connectivity.push_back(v);
      if (k == 0) add_facet("zmin", e, 0);
      if (k == nz - 1) add_facet("zmax", e, 1);
      if (j == 0) add_facet("ymin", e, 2);
      if (i == s.n[0] - 1) add_facet("xmax", e, 3);
      if (j == s.n[1] - 1) add_facet("ymax", e, 4);
      if (i == 0) add_facet("xmin", e, 5);
    }
    all.push_back(e);
  }
  add_derived_node_sets(m);
  return m;
}

std::string grading_problem(double grading, int n) {
  const double spread = std::pow(std::max(grading, 1.0 / grading), n - 1);
  if (spread <= kMaxGradingSpread) return "";
  char text[160];
  std::snprintf(text, sizeof text,
                "%g over %d elements makes the largest element %.3g times the smallest (at most %g): lower the "
                "grading or the element count",
                grading, n, spread, kMaxGradingSpread);
  return text;
}

}  // namespace rollsim
