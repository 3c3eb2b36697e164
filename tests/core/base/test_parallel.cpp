// for_each_group: every index exactly once for any thread count, the lowest failing index's exception rethrown
// after all groups ran, concurrent callers (the pool busy) served by their own threads, and worker threads that
// keep their OpenMP setting between calls.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "base/Parallel.h"

namespace test_parallel {

using namespace rollsim;

TEST(ForEachGroup, CallsEveryIndexExactlyOnceForAnyThreadCount) {
  for (int threads : {1, 2, 3, 8})
    for (size_t n : {size_t{0}, size_t{1}, size_t{2}, size_t{7}, size_t{100}}) {
      std::vector<std::atomic<int>> calls(n);
      for_each_group(n, threads, [&](size_t i) { ++calls[i]; });
      for (size_t i = 0; i < n; ++i) EXPECT_EQ(calls[i].load(), 1) << "threads " << threads << ", n " << n;
    }
}

TEST(ForEachGroup, RethrowsTheLowestFailingIndexAfterRunningTheRest) {
  std::atomic<int> ran{0};
  try {
    for_each_group(20, 2, [&](size_t i) {
      ++ran;
      if (i == 5 || i == 13) throw std::runtime_error("group " + std::to_string(i));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "group 5");
  }
  EXPECT_EQ(ran.load(), 20);
  std::atomic<int> after{0};  // the pool is usable again
  for_each_group(10, 2, [&](size_t) { ++after; });
  EXPECT_EQ(after.load(), 10);
}

TEST(ForEachGroup, ConcurrentCallersEachGetAllTheirIndices) {
  std::vector<std::atomic<int>> a(500), b(500);
  std::thread other([&] {
    for (int k = 0; k < 20; ++k) for_each_group(25, 2, [&](size_t i) { ++b[k * 25 + i]; });
  });
  for (int k = 0; k < 20; ++k) for_each_group(25, 2, [&](size_t i) { ++a[k * 25 + i]; });
  other.join();
  for (size_t i = 0; i < 500; ++i) {
    EXPECT_EQ(a[i].load(), 1);
    EXPECT_EQ(b[i].load(), 1);
  }
}

}  // namespace test_parallel
