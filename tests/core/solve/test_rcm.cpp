// Tests of the reverse Cuthill-McKee ordering and the skyline profile measure.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "solve/ReverseCuthillMcKee.h"

namespace rollsim::test_rcm {
namespace {

using Triplets = std::vector<Eigen::Triplet<double, int>>;

SparseMatrix from_triplets(int n, const Triplets& t) {
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

/// 5-point Laplacian on an nx-by-ny grid, node x + nx*y, with both triangles stored; `offset` shifts the numbering.
void add_grid(Triplets& t, int nx, int ny, int offset = 0) {
  for (int y = 0; y < ny; ++y)
    for (int x = 0; x < nx; ++x) {
      const int v = offset + x + nx * y;
      t.emplace_back(v, v, 4.0);
      if (x + 1 < nx) t.emplace_back(v, v + 1, -1.0), t.emplace_back(v + 1, v, -1.0);
      if (y + 1 < ny) t.emplace_back(v, v + nx, -1.0), t.emplace_back(v + nx, v, -1.0);
    }
}

/// Random relabelling v -> map[v] of 0..n-1.
std::vector<int> random_map(int n, unsigned seed) {
  std::vector<int> map(static_cast<size_t>(n));
  std::iota(map.begin(), map.end(), 0);
  std::shuffle(map.begin(), map.end(), std::mt19937(seed));
  return map;
}

/// The matrix with row/col v renumbered map[v].
SparseMatrix relabelled(const SparseMatrix& A, const std::vector<int>& map) {
  Triplets t;
  for (int c = 0; c < A.cols(); ++c)
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) t.emplace_back(map[it.row()], map[c], it.value());
  return from_triplets(static_cast<int>(A.rows()), t);
}

SparseMatrix scrambled(const SparseMatrix& A, unsigned seed) {
  return relabelled(A, random_map(static_cast<int>(A.rows()), seed));
}

std::vector<int> identity(int n) {
  std::vector<int> p(static_cast<size_t>(n));
  std::iota(p.begin(), p.end(), 0);
  return p;
}

bool is_permutation_of_n(const std::vector<int>& p, int n) {
  std::vector<int> s = p;
  std::sort(s.begin(), s.end());
  return s == identity(n);
}

TEST(RcmTest, ScrambledGridGetsValidPermutationAndMuchSmallerProfile) {
  Triplets t;
  add_grid(t, 30, 20);
  const SparseMatrix natural = from_triplets(600, t);
  const SparseMatrix A = scrambled(natural, 42);
  const std::vector<int> perm = reverse_cuthill_mckee(A);
  ASSERT_TRUE(is_permutation_of_n(perm, 600));
  const long before = profile_size(A, identity(600));
  const long after = profile_size(A, perm);
  EXPECT_GT(before, 10 * after) << "scrambled profile " << before << ", RCM profile " << after;
  // RCM should do at least as well as the natural numbering (bandwidth 30) of the grid itself.
  EXPECT_LE(after, profile_size(natural, identity(600)));
}

TEST(RcmTest, ScrambledPathIsRecoveredWithBandwidthOne) {
  Triplets t;
  const int n = 200;
  for (int v = 0; v < n; ++v) {
    t.emplace_back(v, v, 2.0);
    if (v + 1 < n) t.emplace_back(v, v + 1, -1.0), t.emplace_back(v + 1, v, -1.0);
  }
  const SparseMatrix A = scrambled(from_triplets(n, t), 7);
  const std::vector<int> perm = reverse_cuthill_mckee(A);
  ASSERT_TRUE(is_permutation_of_n(perm, n));
  EXPECT_EQ(profile_size(A, perm), 2L * n - 1);  // the pseudo-peripheral search finds an end of the path
}

TEST(RcmTest, TrailingRowsStayLastInOrder) {
  Triplets t;
  add_grid(t, 12, 9);
  const int m = 108, trailing = 5;
  std::mt19937 rng(3);
  for (int r = 0; r < trailing; ++r)
    for (int k = 0; k < 3; ++k) {
      const int v = static_cast<int>(rng() % m);
      t.emplace_back(m + r, v, 1.0), t.emplace_back(v, m + r, 1.0);
    }
  const SparseMatrix B = from_triplets(m + trailing, t);
  const std::vector<int> perm = reverse_cuthill_mckee(B, trailing);
  ASSERT_TRUE(is_permutation_of_n(perm, m + trailing));
  for (int r = 0; r < trailing; ++r) EXPECT_EQ(perm[m + r], m + r);
  EXPECT_THROW(reverse_cuthill_mckee(B, m + trailing + 1), std::invalid_argument);
}

TEST(RcmTest, DisconnectedComponentsAreEachContiguous) {
  Triplets t;
  add_grid(t, 7, 5, 0);         // nodes 0..34
  add_grid(t, 4, 6, 35);        // nodes 35..58
  t.emplace_back(59, 59, 1.0);  // an isolated node
  add_grid(t, 3, 3, 60);        // nodes 60..68
  const std::vector<int> map = random_map(69, 11);
  const SparseMatrix A = relabelled(from_triplets(69, t), map);
  const std::vector<int> perm = reverse_cuthill_mckee(A);
  ASSERT_TRUE(is_permutation_of_n(perm, 69));
  std::vector<int> component(69);  // component of each scrambled index
  for (int v = 0; v < 69; ++v) component[map[v]] = v < 35 ? 0 : v < 59 ? 1 : v == 59 ? 2 : 3;
  std::vector<int> blocks;
  for (int k = 0; k < 69; ++k)
    if (k == 0 || component[perm[k]] != component[perm[k - 1]]) blocks.push_back(component[perm[k]]);
  EXPECT_EQ(blocks.size(), 4u) << "each component must occupy one contiguous block";
  // No column of the permuted matrix reaches into another component: the profile is the sum of the parts'.
  const std::vector<int> first = skyline_first_rows(A, perm);
  for (int k = 1; k < 69; ++k) {
    if (component[perm[k]] != component[perm[k - 1]]) {
      EXPECT_EQ(first[k], k) << "position " << k;
    }
  }
}

TEST(RcmTest, ProfileOfSmallMatrixByHand) {
  // Upper triangle non-zeros: (0,0) (1,1) (0,2) (2,2) (1,3) (3,3): heights 1, 1, 3, 3.
  Triplets t{{0, 0, 1}, {1, 1, 1}, {2, 2, 1}, {3, 3, 1}, {0, 2, 1}, {2, 0, 1}, {1, 3, 1}, {3, 1, 1}};
  const SparseMatrix A = from_triplets(4, t);
  EXPECT_EQ(profile_size(A, identity(4)), 8);
  EXPECT_EQ(skyline_first_rows(A, identity(4)), (std::vector<int>{0, 1, 0, 1}));
  // Swapping 1 and 2 makes both couplings adjacent: heights 1, 2, 1, 2.
  EXPECT_EQ(profile_size(A, {0, 2, 1, 3}), 6);
  EXPECT_THROW(profile_size(A, {0, 0, 1, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace rollsim::test_rcm
