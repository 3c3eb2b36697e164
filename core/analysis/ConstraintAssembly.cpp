#include "analysis/ConstraintAssembly.h"

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
