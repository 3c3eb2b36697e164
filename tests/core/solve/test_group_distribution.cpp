// MixedStrategy spread over processes (solve/GroupDistribution), without MPI: P threads stand for P ranks, each with
// its own strategy and its own copy of the system, joined by a distribution whose sum is a barrier over shared slots
// (added in rank order: every thread gets the same bits, as the MPI one's reduce and broadcast). A chain of unit
// springs torn into four groups (the first held, three floating) under a unit end force: every spring carries 1, so
// u = node number. Spread over 2 threads the strategy gives the one-process answer, with and without FETI's Dirichlet
// preconditioner; a group that fails to factor fails on every thread with its holder's message; more threads than
// groups are refused.
#include <gtest/gtest.h>

#include <barrier>
#include <functional>
#include <thread>

#include "solve/Factorization.h"
#include "solve/MixedStrategy.h"

namespace test_group_distribution {

using namespace rollsim;

namespace {

/// What the threads share: one slot per thread, and the barrier they meet at.
struct Meeting {
  explicit Meeting(int threads) : slots(static_cast<size_t>(threads)), barrier(threads) {}
  std::vector<Eigen::VectorXd> slots;
  std::barrier<> barrier;
};

class ThreadGroups final : public GroupDistribution {
 public:
  ThreadGroups(Meeting& meeting, int me) : meeting_(meeting), me_(me) {}
  int holder(size_t group) const override { return static_cast<int>(group % meeting_.slots.size()); }
  int process() const override { return me_; }
  int processes() const override { return static_cast<int>(meeting_.slots.size()); }
  void sum(Eigen::VectorXd& x) const override {
    meeting_.slots[static_cast<size_t>(me_)] = x;
    meeting_.barrier.arrive_and_wait();
    Eigen::VectorXd total = Eigen::VectorXd::Zero(x.size());
    for (const Eigen::VectorXd& s : meeting_.slots) total += s;
    meeting_.barrier.arrive_and_wait();  // nobody writes its slot again before everyone has read
    x = total;
  }

 private:
  Meeting& meeting_;
  int me_;
};

using Triplets = std::vector<Eigen::Triplet<double, int>>;

/// Nodes 0..4 G held at 0 and a unit force at the last; group g holds nodes 4g+1..4g+4 (group 0) or 4g..4g+4, every
/// group after the first floating (its kernel the constants), glued to the one before at node 4g.
BlockSystem torn_chain(int groups) {
  BlockSystem sys;
  const int rows = groups - 1;
  sys.d = Eigen::VectorXd::Zero(rows);
  for (int g = 0; g < groups; ++g) {
    Group grp;
    grp.name = "g" + std::to_string(g);
    const int n = g == 0 ? 4 : 5;  // dofs: nodes 4g+1..4g+4, or 4g..4g+4
    Triplets k, c;
    for (int e = 0; e < 4; ++e) {  // springs (4g+e, 4g+e+1); in group 0 node 0 is held
      const int a = g == 0 ? e - 1 : e, b = g == 0 ? e : e + 1;
      if (a >= 0) k.emplace_back(a, a, 1.0);
      k.emplace_back(b, b, 1.0);
      if (a >= 0) k.emplace_back(a, b, -1.0), k.emplace_back(b, a, -1.0);
    }
    grp.K.resize(n, n);
    grp.K.setFromTriplets(k.begin(), k.end());
    grp.f = Eigen::VectorXd::Zero(n);
    if (g == groups - 1) grp.f[n - 1] = 1.0;
    if (g > 0) c.emplace_back(g - 1, 0, -1.0);          // its first node, against …
    if (g < groups - 1) c.emplace_back(g, n - 1, 1.0);  // … the one before's last node
    grp.C.resize(rows, n);
    grp.C.setFromTriplets(c.begin(), c.end());
    grp.R = g == 0 ? Eigen::MatrixXd(n, 0) : Eigen::MatrixXd::Ones(n, 1);
    sys.groups.push_back(grp);
  }
  ConstraintBlock glue;
  glue.kind = ConstraintKind::Glue;
  glue.begin = 0, glue.end = rows;
  sys.blocks.push_back(glue);
  return sys;
}

SolverOptions options(Preconditioner p) {
  SolverOptions o;
  o.cg_tolerance = 1e-12;
  o.preconditioner = p;
  return o;
}

/// Runs `work(me, distribution)` on `threads` threads; returns what each threw ("" when nothing).
std::vector<std::string> on_threads(int threads,
                                    const std::function<void(int, std::shared_ptr<const GroupDistribution>)>& work) {
  Meeting meeting(threads);
  std::vector<std::string> thrown(static_cast<size_t>(threads));
  std::vector<std::thread> pool;
  for (int me = 0; me < threads; ++me)
    pool.emplace_back([&, me] {
      try {
        work(me, std::make_shared<ThreadGroups>(meeting, me));
      } catch (const std::exception& e) {
        thrown[static_cast<size_t>(me)] = e.what();
      }
    });
  for (std::thread& t : pool) t.join();
  return thrown;
}

}  // namespace

TEST(GroupDistribution, SpreadOverTwoProcessesTheMixedMethodGivesTheOneProcessAnswer) {
  for (Preconditioner p : {Preconditioner::None, Preconditioner::Dirichlet}) {
    const BlockSystem sys = torn_chain(4);
    MixedStrategy whole(options(p), true);
    const BlockSolution expected = whole.solve(sys);
    std::vector<BlockSolution> got(2);
    std::vector<long> iterations(2);
    std::vector<std::vector<size_t>> held(2);
    const auto thrown = on_threads(2, [&](int me, std::shared_ptr<const GroupDistribution> spread) {
      MixedStrategy mine(options(p), true, "cholmod", spread);
      BlockSystem copy = sys;  // the other's groups unassembled here: their K empty, as under MPI
      for (size_t g = 0; g < copy.groups.size(); ++g)
        if (!spread->holds(g)) copy.groups[g].K = SparseMatrix(0, 0);
      held[static_cast<size_t>(me)] = mine.local_groups({0, 1, 2, 3});
      got[static_cast<size_t>(me)] = mine.solve(copy);
      iterations[static_cast<size_t>(me)] = mine.stats().cg_iterations;
    });
    EXPECT_EQ(thrown, (std::vector<std::string>{"", ""}));
    EXPECT_EQ(held[0], (std::vector<size_t>{0, 2}));
    EXPECT_EQ(held[1], (std::vector<size_t>{1, 3}));
    for (const BlockSolution& s : got) {
      ASSERT_EQ(s.u.size(), 4u);
      for (size_t g = 0; g < 4; ++g) {
        EXPECT_LT((s.u[g] - expected.u[g]).lpNorm<Eigen::Infinity>(), 1e-12) << g;
        EXPECT_NEAR(s.u[g][s.u[g].size() - 1], 4.0 * (static_cast<double>(g) + 1), 1e-9) << g;  // u = node number
      }
      EXPECT_LT((s.lambda - expected.lambda).lpNorm<Eigen::Infinity>(), 1e-12);
    }
    EXPECT_EQ(iterations[0], whole.stats().cg_iterations);
    EXPECT_EQ(iterations[1], whole.stats().cg_iterations);
  }
}

TEST(GroupDistribution, AGroupThatCannotBeFactoredFailsOnEveryProcessWithItsHoldersMessage) {
  BlockSystem sys = torn_chain(4);
  sys.groups[3].R = Eigen::MatrixXd(5, 0);  // floating, but not said to be: its K is singular
  const auto thrown = on_threads(2, [&](int, std::shared_ptr<const GroupDistribution> spread) {
    MixedStrategy mine(options(Preconditioner::None), true, "cholmod", spread);
    try {
      mine.solve(sys);
    } catch (const SingularMatrix& e) {
      throw std::runtime_error(std::string("singular: ") + e.what());
    }
  });
  ASSERT_EQ(thrown.size(), 2u);
  EXPECT_EQ(thrown[0], thrown[1]);  // held by thread 1, thrown by both with its message
  EXPECT_EQ(thrown[0].rfind("singular: ", 0), 0u) << thrown[0];
  EXPECT_GT(thrown[0].size(), std::string("singular: ").size()) << thrown[0];
}

TEST(GroupDistribution, MoreProcessesThanGroupsAreRefused) {
  const BlockSystem sys = torn_chain(2);
  const auto thrown = on_threads(3, [&](int, std::shared_ptr<const GroupDistribution> spread) {
    MixedStrategy(options(Preconditioner::None), true, "cholmod", spread).solve(sys);
  });
  for (const std::string& t : thrown) EXPECT_NE(t.find("3 MPI ranks for 2 groups"), std::string::npos) << t;
}

}  // namespace test_group_distribution
