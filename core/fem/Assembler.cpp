#include "fem/Assembler.h"

#include <algorithm>

#include "fem/ElementLoop.h"

namespace rollsim {

void element_equations(const Mesh& mesh, const DofMap& dofs, int e, int* eq) {
  const int* conn = mesh.element(e);
  const int d = mesh.dim;
  for (int a = 0; a < mesh.nodes_per_elem(); ++a)
    for (int c = 0; c < d; ++c) eq[a * d + c] = dofs.equation(conn[a], c);
}

Assembler::Assembler(const Body& body, const DofMap& dofs) : body_(body), dofs_(dofs) {
  const Mesh& m = body.mesh;
  const int nd = m.nodes_per_elem() * m.dim;
  const int n = dofs.num_free();
  // column lists of the pattern, built once
  std::vector<std::vector<int>> cols(static_cast<size_t>(n));
  std::vector<int> eq(static_cast<size_t>(nd));
  for (int e = 0; e < m.num_elements(); ++e) {
    element_equations(m, dofs, e, eq.data());
    for (int j : eq)
      if (j >= 0)
        for (int i : eq)
          if (i >= 0) cols[j].push_back(i);
  }
  std::vector<int> outer(static_cast<size_t>(n) + 1, 0);
  for (int j = 0; j < n; ++j) {
    auto& c = cols[j];
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    outer[j + 1] = outer[j] + static_cast<int>(c.size());
  }
  pattern_.resize(n, n);
  pattern_.resizeNonZeros(outer[n]);
  std::copy(outer.begin(), outer.end(), pattern_.outerIndexPtr());
  for (int j = 0; j < n; ++j) std::copy(cols[j].begin(), cols[j].end(), pattern_.innerIndexPtr() + outer[j]);
  std::fill(pattern_.valuePtr(), pattern_.valuePtr() + outer[n], 0.0);
  // scatter map: slot of each element-matrix entry in the value array
  slot_.resize(static_cast<size_t>(m.num_elements()) * nd * nd);
  for (int e = 0; e < m.num_elements(); ++e) {
    element_equations(m, dofs, e, eq.data());
    int* s = slot_.data() + static_cast<size_t>(e) * nd * nd;
    for (int jj = 0; jj < nd; ++jj)
      for (int ii = 0; ii < nd; ++ii) {
        const int i = eq[ii], j = eq[jj];
        if (i < 0 || j < 0) {
          s[jj * nd + ii] = -1;
          continue;
        }
        const int* begin = pattern_.innerIndexPtr() + outer[j];
        const int* end = pattern_.innerIndexPtr() + outer[j + 1];
        s[jj * nd + ii] = static_cast<int>(std::lower_bound(begin, end, i) - pattern_.innerIndexPtr());
      }
  }
}

void Assembler::assemble(SparseMatrix& K, Eigen::VectorXd& fD) const {
  const Mesh& m = body_.mesh;
  const int nd = m.nodes_per_elem() * m.dim;
  K = pattern_;
  fD = Eigen::VectorXd::Zero(dofs_.num_free());
  double* val = K.valuePtr();
  std::vector<int> eq(static_cast<size_t>(nd));
  for_each_element_stiffness(body_, [&](int e, const double* Ke) {
    element_equations(m, dofs_, e, eq.data());
    const int* s = slot_.data() + static_cast<size_t>(e) * nd * nd;
    const int* conn = m.element(e);
    for (int jj = 0; jj < nd; ++jj) {
      if (eq[jj] < 0) {  // prescribed column: move K_fp u_p to the right-hand side
        const double up = dofs_.prescribed(conn[jj / m.dim], jj % m.dim);
        if (up != 0.0)
          for (int ii = 0; ii < nd; ++ii)
            if (eq[ii] >= 0) fD[eq[ii]] -= Ke[jj * nd + ii] * up;
        continue;
      }
      for (int ii = 0; ii < nd; ++ii)
        if (s[jj * nd + ii] >= 0) val[s[jj * nd + ii]] += Ke[jj * nd + ii];
    }
  });
}

}  // namespace rollsim
