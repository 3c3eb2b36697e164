#include "base/DgemmPeak.h"

#include <algorithm>
#include <vector>

#include "base/Stopwatch.h"

extern "C" void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
                       const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
                       const double* beta, double* c, const int* ldc);

namespace rollsim {

DgemmPeak measure_dgemm_peak(int threads, int n, int max_calls, double budget_s) {
  DgemmPeak peak;
  peak.n = n > 0 ? n : (threads > 1 ? 384 : 256);
  const size_t size = static_cast<size_t>(peak.n) * static_cast<size_t>(peak.n);
  std::vector<double> a(size), b(size), c(size, 0.0);
  for (size_t i = 0; i < size; ++i) {  // values that neither overflow nor underflow over repeated products
    a[i] = 1.0 / static_cast<double>(i % 7 + 1);
    b[i] = 1.0 / static_cast<double>(i % 5 + 1);
  }
  const double one = 1.0, zero = 0.0;
  const double flops = 2.0 * peak.n * static_cast<double>(peak.n) * peak.n;
  Stopwatch total;
  double best = 0;
  for (int call = 0; call <= max_calls; ++call) {  // call 0 warms up (BLAS buffers, thread wake-up) and is not kept
    Stopwatch t;
    dgemm_("N", "N", &peak.n, &peak.n, &peak.n, &one, a.data(), &peak.n, b.data(), &peak.n, &zero, c.data(), &peak.n);
    const double s = t.seconds();
    if (call > 0) {
      best = std::max(best, gflops(flops, s));
      ++peak.calls;
    }
    if (total.seconds() > budget_s && peak.calls > 0) break;
  }
  peak.gflops = best;
  peak.seconds = total.seconds();
  return peak;
}

double gflops(double flops, double seconds) { return seconds > 0 ? flops / seconds / 1e9 : 0.0; }

}  // namespace rollsim
