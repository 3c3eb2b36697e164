#pragma once
// Independent per-group work on a few threads (--threads): group i goes to thread i mod threads. Callers write
// each group's result to its own slot and combine the slots in group order afterwards, so the arithmetic — and
// the result — does not depend on the thread count. Inside a worker the libraries stay on one thread each
// (CHOLMOD's OpenMP loops would otherwise start a team per worker: 4 threads on 2 cores, spinning).
#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

#include "solve/Blas.h"

namespace rollsim {

template <class Fn>
void for_each_group(size_t n, int threads, Fn&& fn) {
  const size_t t_count = std::min<size_t>(static_cast<size_t>(std::max(1, threads)), n);
  if (t_count <= 1) {
    for (size_t i = 0; i < n; ++i) fn(i);
    return;
  }
  std::vector<std::exception_ptr> errors(t_count);
  std::vector<std::thread> pool;
  for (size_t t = 0; t < t_count; ++t)
    pool.emplace_back([&, t] {
      set_openmp_threads(1);
      try {
        for (size_t i = t; i < n; i += t_count) fn(i);
      } catch (...) {
        errors[t] = std::current_exception();
      }
    });
  for (auto& th : pool) th.join();
  for (const auto& e : errors)  // the first failing thread's exception, as a serial loop would (almost) give
    if (e) std::rethrow_exception(e);
}

}  // namespace rollsim
