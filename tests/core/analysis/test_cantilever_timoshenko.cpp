// Convergence of a cantilever's tip reaction toward Timoshenko's solution (Timoshenko & Goodier,
// end-loaded cantilever; plane strain through E' = E/(1-nu^2), nu' = nu/(1-nu)) under refinement,
// with the observed order of convergence.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "analysis/LinearStatic.h"
#include "analysis/Recovery.h"
#include "mesh/StructuredBlock.h"
#include "solve/SolverStrategy.h"

namespace test_cantilever_timoshenko {

using namespace rollsim;

namespace {

constexpr double L = 8.0, D = 2.0, P = 1.0, E = 1000.0, NU = 0.3;

struct Exact {
  double Ep = E / (1 - NU * NU), nup = NU / (1 - NU), I = D * D * D / 12.0;
  double ux(double x, double y) const {
    return P * y / (6 * Ep * I) * ((6 * L - 3 * x) * x + (2 + nup) * (y * y - D * D / 4));
  }
  double uy(double x, double y) const {
    return -P / (6 * Ep * I) * (3 * nup * y * y * (L - x) + (4 + 5 * nup) * D * D * x / 4 + (3 * L - x) * x * x);
  }
};

/// y-reaction at the loaded end x = L when both ends carry the exact displacements.
double tip_reaction(int n_depth, Formulation f) {
  const Exact ex;
  Model m;
  m.dim = 2;
  BlockSpec s;
  s.n = {4 * n_depth, n_depth, 1};
  s.size = {L, D, 1};
  s.origin = {0, -D / 2, 0};
  Body b{"beam", make_block(s), {E, NU}, "steel", f};
  for (const char* set : {"xmin", "xmax"})
    for (int n : b.mesh.node_sets.at(set)) {
      const auto& x = b.mesh.nodes[n];
      m.displacements.push_back({0, set, {n}, {ex.ux(x[0], x[1]), ex.uy(x[0], x[1]), std::nullopt}});
    }
  m.bodies.push_back(std::move(b));
  auto solver = make_solver("direct", {});
  const Results r = run_linear_static(m, *solver);
  return set_resultant(r.bodies[0], 2, m.bodies[0].mesh.node_sets.at("xmax"))[1];
}

}  // namespace

TEST(CantileverTimoshenko, TipReactionConvergesAtSecondOrder) {
  const int levels[] = {2, 4, 8, 16, 32};
  double prev = 0;
  double order = 0;
  for (int n : levels) {
    const double err = std::abs(tip_reaction(n, Formulation::Full) + P) / P;  // exact reaction: -P
    if (prev > 0) order = std::log2(prev / err);
    std::printf("  elements through depth %2d: reaction error %.3e  observed order %.2f\n", n, err, order);
    if (prev > 0) EXPECT_LT(err, prev);
    prev = err;
  }
  EXPECT_LT(prev, 2e-3);
  EXPECT_GT(order, 1.8);
  EXPECT_LT(order, 2.3);
}

TEST(CantileverTimoshenko, BBarAlsoConverges) {
  const double coarse = std::abs(tip_reaction(4, Formulation::BBar) + P);
  const double fine = std::abs(tip_reaction(16, Formulation::BBar) + P);
  EXPECT_LT(fine, coarse / 8);
}

}  // namespace test_cantilever_timoshenko
