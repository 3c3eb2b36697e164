#include "mesh/OGrid.h"

namespace rollsim::detail {

std::vector<OGridQuad> quarter_quads(const OGridQuarter& quarter) {
  std::vector<OGridQuad> q;
  const int n = quarter.n;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      q.push_back({{quarter.core(i, j), quarter.core(i + 1, j), quarter.core(i + 1, j + 1), quarter.core(i, j + 1)},
                   j == 0 ? 2 : -1,
                   i == 0 ? 5 : -1,
                   -1});
  for (int k = 0; k < quarter.m; ++k)  // outward (k) then round (s): e_r × e_θ = +z
    for (int s = 0; s < 2 * n; ++s)
      q.push_back({{quarter.ring(k, s), quarter.ring(k + 1, s), quarter.ring(k + 1, s + 1), quarter.ring(k, s + 1)},
                   s == 0 ? 2 : -1,
                   s == 2 * n - 1 ? 4 : -1,
                   k == quarter.m - 1 ? 3 : -1});
  return q;
}

}  // namespace rollsim::detail
