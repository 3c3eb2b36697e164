// `direct` on constraint rows that depend on each other (four stick rows holding three roll dofs, as on the 3D pass's
// symmetry plane, with the round-off terms a tangent leaves on the slave's free dofs): the bordered matrix is singular,
// an LU of it gave λ of 1e17 and a correction that was no solution. It must give the solution `mixed` gives (whose
// interface CG tolerates dependent rows) and mixed's least-norm λ; rows that contradict each other are reported.
// `mixed` with the `dense` interface solver, which forms F (singular with such rows), must give the same.
#include <gtest/gtest.h>

#include "solve/SolverStrategy.h"

namespace test_global_direct_dependent_rows {

using namespace rollsim;

namespace {
/// "roll": three dofs on springs, loaded; "slab": two dofs; four rows on the roll's dofs alone (but for round-off
/// terms on the slab's second dof), one normal row joining both with a gap.
BlockSystem dependent_rows(double round_off) {
  Eigen::MatrixXd Kr(3, 3), Ks(2, 2);
  Kr << 3, -1, 0, -1, 3, -1, 0, -1, 3;
  Ks << 2, -1, -1, 2;
  Eigen::MatrixXd Cr(5, 3), Cs = Eigen::MatrixXd::Zero(5, 2);
  Cr << -0.005, -0.995, 0, -0.67, -0.33, 0, 0, -0.66, -0.34, 0, 0, -1, -1, 0, 0;
  Cs(0, 1) = round_off, Cs(1, 1) = 0.07 * round_off;
  Cs(4, 0) = 1;
  BlockSystem sys;
  Group roll, slab;
  roll.name = "roll", slab.name = "slab";
  roll.K = Kr.sparseView(), slab.K = Ks.sparseView();
  roll.f = Eigen::Vector3d(1, -2, 0.5), slab.f = Eigen::Vector2d(0.3, 1);
  roll.C = Cr.sparseView(), slab.C = Cs.sparseView();
  roll.R.resize(3, 0), slab.R.resize(2, 0);
  sys.groups = {roll, slab};
  sys.d = Eigen::VectorXd::Zero(5);
  sys.d[4] = 0.1;
  return sys;
}

/// `direct`, and `mixed` with its interface formed and factored (`dense`, which keeps the independent rows as
/// `direct` does), give the solution of `mixed` with its interface CG
void expect_mixed_solution(const BlockSystem& sys) {
  SolverOptions o;
  o.cg_tolerance = 1e-13;
  const BlockSolution mixed = make_solver("mixed", o)->solve(sys);
  ASSERT_TRUE(mixed.status.ok());
  SolverOptions dense;
  dense.interface_solver = InterfaceSolver::Dense;
  for (const auto& [name, s] : {std::pair{"direct", make_solver("direct", {})->solve(sys)},
                                std::pair{"mixed, dense", make_solver("mixed", dense)->solve(sys)}}) {
    SCOPED_TRACE(name);
    ASSERT_TRUE(s.status.ok()) << s.status.message;
    for (size_t g = 0; g < 2; ++g) EXPECT_LT((s.u[g] - mixed.u[g]).norm(), 1e-10) << sys.groups[g].name;
    EXPECT_LT((s.lambda - mixed.lambda).norm(), 1e-9 * mixed.lambda.norm());
  }
}
}  // namespace

TEST(GlobalDirectDependentRows, GivesMixedsSolutionWithRoundOffTermsInTheRows) {
  expect_mixed_solution(dependent_rows(7e-18));
}

TEST(GlobalDirectDependentRows, GivesMixedsSolutionWithExactlyDependentRows) {
  expect_mixed_solution(dependent_rows(0.0));
}

TEST(GlobalDirectDependentRows, RowsThatContradictEachOtherAreReported) {
  BlockSystem sys = dependent_rows(0.0);
  sys.d[3] = 0.2;  // row 3 is a combination of rows 0–2 (right-hand sides 0): it cannot hold too
  try {
    make_solver("direct", {})->solve(sys);
    FAIL() << "contradicting rows solved";
  } catch (const SingularMatrix& e) {  // a row and by how much it misses, against what
    EXPECT_NE(std::string(e.what()).find("depends on other rows and contradicts them by "), std::string::npos)
        << e.what();
  }
}

TEST(GlobalDirectDependentRows, ANewtonCorrectionsRowsMayDisagreeByTheAccuracyOfTheirTerms) {
  // a late Newton correction (d ~ 1e-9) whose dependent row misses by 1e-12: nothing against d, but the d of a Newton
  // system is d_total − C u of terms ~1 (d_reference), and against those it is 1e-12 — the accuracy they have
  BlockSystem sys = dependent_rows(0.0);
  for (Group& g : sys.groups) g.f *= 1e-9;  // the out-of-balance forces of a nearly converged iterate
  sys.d[4] = 1e-9;
  sys.d[3] = 1e-12;
  EXPECT_THROW(make_solver("direct", {})->solve(sys), SingularMatrix) << "against d alone it contradicts";
  sys.d_reference = 1.0;
  const BlockSolution s = make_solver("direct", {})->solve(sys);
  ASSERT_TRUE(s.status.ok()) << s.status.message;
  BlockSystem consistent = sys;
  consistent.d[3] = 0;
  const BlockSolution c = make_solver("direct", {})->solve(consistent);
  for (size_t g = 0; g < 2; ++g)  // the miss moves the solution by its order times the rows' 1 / 0.005, no more
    EXPECT_LT((s.u[g] - c.u[g]).lpNorm<Eigen::Infinity>(), 200 * 1e-12 * 1.5) << sys.groups[g].name;
  sys.d[3] = 1e-3;  // a miss of the order of its terms is still a contradiction
  EXPECT_THROW(make_solver("direct", {})->solve(sys), SingularMatrix);
}

}  // namespace test_global_direct_dependent_rows
