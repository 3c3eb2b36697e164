// Tests of the per-call BLAS thread choice: the level-3 routines CHOLMOD calls resolve to rollsim's interposers, a
// call below kThreadedBlasFlops runs on one OpenBLAS thread whatever --threads allows and a large one on the allowed
// count, and a factorization on 2 threads gives the 1-thread solution to round-off. One allowed thread stops
// OpenBLAS's idle workers (they spin before they sleep), and setting it again does not start them again.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <thread>

#include "../solve/grid_matrix.h"
#include "base/Blas.h"
#include "base/BlasCallThreads.h"
#include "solve/CholmodFactorization.h"

namespace rollsim::test_blas_call_threads {
namespace {

/// OpenBLAS's current thread count, or 0 when the BLAS is not OpenBLAS.
int openblas_threads() {
  using Get = int (*)();
  auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  return get ? get() : 0;
}

TEST(BlasCallThreads, LevelThreeCallsResolveToTheInterposers) {
  const std::string self = std::filesystem::canonical("/proc/self/exe").string();
  for (const char* name : {"dgemm_", "dsyrk_", "dtrsm_", "dpotrf_"}) {
    Dl_info info{};
    void* symbol = dlsym(RTLD_DEFAULT, name);
    ASSERT_NE(symbol, nullptr) << name;
    ASSERT_NE(dladdr(symbol, &info), 0) << name;
    EXPECT_EQ(std::filesystem::canonical(info.dli_fname).string(), self) << name << " comes from " << info.dli_fname;
  }
}

TEST(BlasCallThreads, OnlyLargeCallsGetTheAllowedThreads) {
  if (openblas_threads() == 0) GTEST_SKIP() << "not OpenBLAS";
  set_blas_threads(2);
  EXPECT_EQ(openblas_threads(), 1);  // between calls
  {
    const BlasCallThreads small(kThreadedBlasFlops / 10);
    EXPECT_EQ(openblas_threads(), 1);
  }
  {
    const BlasCallThreads large(kThreadedBlasFlops);
    EXPECT_EQ(openblas_threads(), 2);
    {
      const BlasCallThreads inner(1e3);  // a routine called from inside the large one keeps its threads
      EXPECT_EQ(openblas_threads(), 2);
    }
    EXPECT_EQ(openblas_threads(), 2);
  }
  EXPECT_EQ(openblas_threads(), 1);
  set_blas_threads(1);
  {
    const BlasCallThreads large(1e12);
    EXPECT_EQ(openblas_threads(), 1);
  }
  EXPECT_EQ(blas_threads_for(1e12), 1);
}

TEST(BlasCallThreads, TwoThreadsSolveLikeOne) {
  const SparseMatrix A = testing::fe_grid_matrix(12, 3, 3, 7);  // 6591 dofs: top supernodes of ~1e9 flops
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0);
  Eigen::VectorXd x[2];
  for (int threads : {1, 2}) {
    set_library_threads(threads);
    CholmodFactorization chol;
    chol.factorize(A);
    x[threads - 1] = chol.solve(b);
  }
  set_library_threads(1);
  EXPECT_LE((x[1] - x[0]).norm(), 1e-12 * x[0].norm());
  EXPECT_LE((A * x[1] - b).norm(), 1e-10 * b.norm());
}

/// This process's threads.
long threads_now() {
  long n = 0;
  for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task")) ++n;
  return n;
}

TEST(BlasCallThreads, OneAllowedThreadStopsTheIdleWorkersForGood) {
  if (openblas_threads() == 0) GTEST_SKIP() << "not OpenBLAS";
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "OpenBLAS has no worker on one core";
  set_blas_call_threads(2);
  { const BlasCallThreads large(1e9); }  // a large call's threads: OpenBLAS's workers running
  const long with_workers = threads_now();
  set_blas_call_threads(1);
  const long stopped = threads_now();
  EXPECT_LT(stopped, with_workers);
  for (int i = 0; i < 3; ++i) set_blas_call_threads(1);  // every mixed solve sets it again
  EXPECT_EQ(threads_now(), stopped);
  EXPECT_EQ(openblas_threads(), 1);
}

}  // namespace
}  // namespace rollsim::test_blas_call_threads
