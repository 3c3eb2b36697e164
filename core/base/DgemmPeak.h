#pragma once
// The machine's practical limit for a factorization: the rate of the loaded BLAS's DGEMM (C = A B, n × n) with the
// thread count in force. A supernodal Cholesky spends its flops in DGEMM / DSYRK / DTRSM / DPOTRF on dense blocks,
// so flops / seconds of a factorization against this rate says how much of the machine it used (issue 14).
namespace rollsim {

struct DgemmPeak {
  double gflops = 0;   // best rate seen, 1e9 flop/s (2 n³ flops per call)
  double seconds = 0;  // what the probe cost, warm-up included
  int n = 0, calls = 0;
};

/// Best of up to `max_calls` DGEMMs of order `n` (0: 256 for one BLAS thread, 384 for more — large enough for the
/// kernels to reach their rate, ~1 ms a call), stopping after `budget_s` seconds. The best, not the median: on a
/// shared machine the fastest call is the one nothing else interrupted.
DgemmPeak measure_dgemm_peak(int threads, int n = 0, int max_calls = 10, double budget_s = 0.03);

/// flops / seconds in GFlop/s (0 when nothing was timed).
double gflops(double flops, double seconds);

}  // namespace rollsim
