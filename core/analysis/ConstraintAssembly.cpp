#include "analysis/ConstraintAssembly.h"

namespace rollsim {

void set_constraints(const std::vector<ConstraintRow>& rows, const std::vector<std::unique_ptr<DofMap>>& dofs,
                     BlockSystem& sys, std::vector<int>* kept) {
  std::vector<std::vector<Eigen::Triplet<double, int>>> t(sys.groups.size());
  std::vector<double> d;
  if (kept) kept->clear();
  for (size_t r = 0; r < rows.size(); ++r) {
    double rhs = rows[r].rhs;
    bool free = false;
    for (const ConstraintTerm& term : rows[r].terms) {
      const DofMap& map = *dofs[term.body];
      const int eq = map.equation(term.node, term.comp);
      if (eq < 0) {
        rhs -= term.coef * map.prescribed(term.node, term.comp);
      } else {
        free = true;
        t[term.body].emplace_back(static_cast<int>(d.size()), eq, term.coef);
      }
    }
    if (!free) continue;  // only prescribed dofs: nothing entered the groups
    d.push_back(rhs);
    if (kept) kept->push_back(static_cast<int>(r));
  }
  const int m = static_cast<int>(d.size());
  sys.d = Eigen::Map<Eigen::VectorXd>(d.data(), m);
  for (size_t g = 0; g < sys.groups.size(); ++g) {
    Group& grp = sys.groups[g];
    grp.C.resize(m, grp.K.rows());
    grp.C.setFromTriplets(t[g].begin(), t[g].end());
  }
}

}  // namespace rollsim
