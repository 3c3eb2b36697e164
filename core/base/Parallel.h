#pragma once
// Independent per-group work on a few threads (--threads). Callers write each group's result to its own slot and
// combine the slots in group order afterwards, so the arithmetic — and the result — does not depend on the thread
// count or on which thread took which group. The threads are kept between calls (a projected CG calls this twice
// per iteration; starting threads each time cost ~5 % of a 2D FETI iteration) and take the next group as they
// become free, which balances groups of unequal cost (floating and clamped subdomains). Inside a worker the
// libraries stay on one thread each (CHOLMOD's OpenMP loops would otherwise start a team per worker: 4 threads on
// 2 cores, spinning).
#include <cstddef>
#include <functional>

namespace rollsim {

/// Calls fn(i) for i in [0, n) on up to `threads` threads (the caller's included) and returns when all are done.
/// An exception thrown by fn is rethrown here (the one of the lowest index that threw); the other groups still run.
/// Calls from several threads at once are safe (a call that finds the pool busy starts its own threads).
void for_each_group(size_t n, int threads, const std::function<void(size_t)>& fn);

}  // namespace rollsim
