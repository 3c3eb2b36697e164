#pragma once
// The BLAS thread count chosen per call by the call's work (OpenBLAS's own thresholds thread a call from ~1e4
// flops on: dtrsm from m·n ≥ 1024, dpotrf from n ≥ 64, dsyrk from n ≥ 100). A supernodal Cholesky makes thousands of
// such calls per factorization, most of them small (counted on the 16³ cube: 41 of ~5600 calls reach 1e7 flops and hold
// 60 % of the flops; on the 120² square 2 calls). Each threaded call wakes OpenBLAS's worker and waits for it: on two
// cores shared with other work that wait can be a scheduler time slice: `--threads 2` took 1.3x the time of `--threads
// 1` on the 3D cubes in docs/BENCHMARKS.md before this (load ~6), and its factorization of the 16³ cube 8.5 s
// against 1.95 s at load 10. So a call runs on the allowed threads only when it is large enough to pay for the
// hand-over, and on one otherwise. The choice is made by interposing dgemm_, dsyrk_, dtrsm_ and dpotrf_ (CHOLMOD's and
// UMFPACK's level-3 calls): the executable's definitions come before the BLAS library's in the dynamic linker's search,
// like GOMP_parallel in Blas.cpp.

namespace rollsim {

/// Work, in flops, from which a level-3 BLAS call may use more than one thread (~1 ms on one core of this machine).
inline constexpr double kThreadedBlasFlops = 1e7;

/// Sets the BLAS threads a large call may use (process-wide); OpenBLAS itself is left on one thread between calls.
/// Returns false when the BLAS cannot set its thread count (not OpenBLAS).
bool set_blas_call_threads(int threads);
/// The threads a call of `flops` gets: the allowed count from kThreadedBlasFlops on, 1 below.
int blas_threads_for(double flops);

/// For its lifetime, OpenBLAS runs on blas_threads_for(flops) threads; nested scopes (a BLAS routine calling another
/// through the interposers) keep the outermost choice.
class BlasCallThreads {
 public:
  explicit BlasCallThreads(double flops);
  ~BlasCallThreads();
  BlasCallThreads(const BlasCallThreads&) = delete;
  BlasCallThreads& operator=(const BlasCallThreads&) = delete;

 private:
  bool raised_ = false;
};

}  // namespace rollsim
