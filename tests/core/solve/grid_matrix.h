#pragma once
// A test matrix with the structure of a finite-element stiffness: the Q1 node graph of an n^dim grid (all
// neighbours within one cell), `dofs` per node, random couplings, SPD by diagonal dominance; optionally with some
// dofs removed (as supports remove them), so that nodes keep 1 … dofs columns.
#include <Eigen/Sparse>
#include <cstdlib>
#include <random>
#include <vector>

namespace rollsim::testing {

inline Eigen::SparseMatrix<double, Eigen::ColMajor, int> fe_grid_matrix(int n, int dim, int dofs, unsigned seed,
                                                                        int remove_every = 0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 0.0);
  const int p = n + 1, nodes = dim == 2 ? p * p : p * p * p;
  auto coord = [&](int v, int k) { return k == 0 ? v % p : k == 1 ? (v / p) % p : v / (p * p); };
  std::vector<int> index(static_cast<size_t>(nodes * dofs), -1);  // dof -> column, -1: removed
  int cols = 0;
  for (int i = 0; i < nodes * dofs; ++i)
    if (remove_every == 0 || i % remove_every != 1) index[static_cast<size_t>(i)] = cols++;
  std::vector<Eigen::Triplet<double, int>> t;
  std::vector<double> row_sum(static_cast<size_t>(cols), 0.0);
  auto add = [&](int a, int b, double x) {
    const int i = index[static_cast<size_t>(a)], j = index[static_cast<size_t>(b)];
    if (i < 0 || j < 0) return;
    t.emplace_back(i, j, x);
    t.emplace_back(j, i, x);
    row_sum[static_cast<size_t>(i)] -= x;
    row_sum[static_cast<size_t>(j)] -= x;
  };
  for (int v = 0; v < nodes; ++v)
    for (int w = v; w < nodes; ++w) {
      bool near = true;
      for (int k = 0; k < dim; ++k) near = near && std::abs(coord(v, k) - coord(w, k)) <= 1;
      if (!near) continue;
      for (int a = 0; a < dofs; ++a)
        for (int c = (v == w ? a + 1 : 0); c < dofs; ++c) add(v * dofs + a, w * dofs + c, value(rng));
    }
  for (int i = 0; i < cols; ++i) t.emplace_back(i, i, row_sum[static_cast<size_t>(i)] + 0.1);
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> A(cols, cols);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

}  // namespace rollsim::testing
