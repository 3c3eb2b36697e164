#include "analysis/ConstraintAssembly.h"

#include <cmath>
#include <map>

namespace rollsim {

BodyConstraints body_constraints(const std::vector<ConstraintRow>& rows,
                                 const std::vector<std::unique_ptr<DofMap>>& dofs, double load_factor) {
  std::vector<std::vector<Eigen::Triplet<double, int>>> t(dofs.size());
  std::vector<double> d;
  BodyConstraints out;
  for (size_t r = 0; r < rows.size(); ++r) {
    double rhs = rows[r].rhs;
    int first = -1;  // the body of the first free term
    for (const ConstraintTerm& term : rows[r].terms) {
      const DofMap& map = *dofs[term.body];
      const int eq = map.equation(term.node, term.comp);
      if (eq < 0) {
        rhs -= term.coef * map.prescribed(term.node, term.comp, load_factor);
      } else {
        if (first < 0) first = term.body;
        t[term.body].emplace_back(static_cast<int>(d.size()), eq, term.coef);
      }
    }
    if (first < 0) continue;  // only prescribed dofs: nothing entered the blocks
    d.push_back(rhs);
    out.kept.push_back(static_cast<int>(r));
    out.slave_body.push_back(first);
  }
  const int m = static_cast<int>(d.size());
  out.d = Eigen::Map<Eigen::VectorXd>(d.data(), m);
  for (size_t b = 0; b < dofs.size(); ++b) {
    out.C.emplace_back(m, dofs[b]->num_free());
    out.C.back().setFromTriplets(t[b].begin(), t[b].end());
  }
  return out;
}

namespace {
/// A master node's weight below which a projection puts it there by round-off: a slave node on a symmetry plane
/// projects onto the master's edge in that plane, and the Newton solve for its facet coordinates leaves weights of
/// 1e-7–1e-6 on the edge across (the 3D pass; a threshold of 1e-9 kept such a row, free terms 9e-7 of its largest,
/// and the step's system was singular: a correction of 254 mm).
constexpr double kProjectionNoise = 1e-4;

/// The axis (0, 1, 2) along which every node of `row` that carries weight has its component prescribed; −1: none.
int supported_axis(const ConstraintRow& row, const std::vector<std::unique_ptr<DofMap>>& dofs) {
  std::map<std::pair<int, int>, double> weight;  // (body, node) → its largest coefficient
  double largest = 0;
  for (const ConstraintTerm& t : row.terms) {
    double& w = weight[{t.body, t.node}];
    w = std::max(w, std::abs(t.coef));
    largest = std::max(largest, w);
  }
  for (int axis = 0; axis < 3; ++axis) {
    bool held = true;
    for (const auto& [node, w] : weight)
      if (w > kProjectionNoise * largest && dofs[node.first]->equation(node.second, axis) >= 0) held = false;
    if (held) return axis;
  }
  return -1;
}

/// a · x + b · y, term by term (a row's terms may repeat a dof: the blocks sum them).
ConstraintRow combined(double a, const ConstraintRow& x, double b, const ConstraintRow& y) {
  ConstraintRow out = x;
  for (ConstraintTerm& t : out.terms) t.coef *= a;
  for (ConstraintTerm t : y.terms) out.terms.push_back({t.body, t.node, t.comp, b * t.coef});
  out.rhs = a * x.rhs + b * y.rhs;
  return out;
}
}  // namespace

void hold_supported_tangents(std::vector<ConstraintRow>& rows, const std::vector<std::unique_ptr<DofMap>>& dofs) {
  std::vector<ConstraintRow> out;
  for (size_t r = 0; r < rows.size(); ++r) {
    out.push_back(rows[r]);
    // a sticking point: its normal row, then its two tangential ones (contact/ContactConstraints point_rows)
    auto of_point = [&](size_t k) { return rows[k].pair == rows[r].pair && rows[k].point == rows[r].point; };
    if (r + 2 >= rows.size() || rows[r].comp != -1 || rows[r + 1].comp != 0 || rows[r + 2].comp != 1 ||
        !of_point(r + 1) || !of_point(r + 2))
      continue;
    const int axis = supported_axis(rows[r + 1], dofs);
    if (axis < 0) continue;  // nothing held
    const Eigen::Vector3d q = rows[r].dir.cross(Eigen::Vector3d::Unit(axis));
    if (q.norm() < 0.5) continue;  // held along the normal: both tangents are free
    const Eigen::Vector3d q1 = q.normalized();
    ConstraintRow t = combined(q1.dot(rows[r + 1].dir), rows[r + 1], q1.dot(rows[r + 2].dir), rows[r + 2]);
    t.dir = q1, t.comp = kSupportedTangent;
    out.push_back(std::move(t));
    r += 2;
  }
  rows = std::move(out);
}

void add_coupling(const std::vector<ConstraintRow>& extra, const std::vector<std::unique_ptr<DofMap>>& dofs,
                  BodyConstraints& c) {
  c.coupling.clear();
  std::vector<std::vector<Eigen::Triplet<double, int>>> t(dofs.size());
  bool any = false;
  for (size_t r = 0; r < c.kept.size(); ++r)
    for (const ConstraintTerm& term : extra[static_cast<size_t>(c.kept[r])].terms) {
      const int eq = dofs[term.body]->equation(term.node, term.comp);
      if (eq < 0) continue;
      t[term.body].emplace_back(static_cast<int>(r), eq, term.coef);
      any = true;
    }
  if (!any) return;
  for (size_t b = 0; b < dofs.size(); ++b) {
    c.coupling.emplace_back(static_cast<long>(c.kept.size()), dofs[b]->num_free());
    c.coupling.back().setFromTriplets(t[b].begin(), t[b].end());
  }
}

}  // namespace rollsim
