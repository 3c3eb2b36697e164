#include "base/BlasCallThreads.h"

#include <dlfcn.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>

namespace rollsim {

namespace {
using SetThreads = void (*)(int);
SetThreads openblas_setter() {
  static const auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  return set;
}
std::atomic<int> allowed_threads{1};
thread_local int depth = 0;  // BlasCallThreads scopes open on this thread
}  // namespace

bool set_blas_call_threads(int threads) {
  allowed_threads = threads < 1 ? 1 : threads;
  const SetThreads set = openblas_setter();
  if (!set) return false;
  // OpenBLAS starts its workers when it is loaded, and an idle worker spins ~2^28 cycles (sched_yield) before it
  // sleeps: 3 % of the main job's CPU time on a second core that one BLAS thread never uses. Stopped here; OpenBLAS
  // starts them again itself when it is set to more than one thread (a large call, BlasCallThreads). Setting it to
  // the one thread it already has would start them again too (its set_num_threads re-creates a stopped pool).
  using Get = int (*)();
  using Shutdown = int (*)();
  static const auto get = reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
  static const auto shutdown = reinterpret_cast<Shutdown>(dlsym(RTLD_DEFAULT, "blas_thread_shutdown_"));
  if (!get || get() != 1) set(1);
  if (allowed_threads == 1 && shutdown) shutdown();
  return true;
}

int blas_threads_for(double flops) { return flops >= kThreadedBlasFlops ? allowed_threads.load() : 1; }

BlasCallThreads::BlasCallThreads(double flops) {
  if (depth++ > 0) return;
  const int threads = blas_threads_for(flops);
  if (threads <= 1 || !openblas_setter()) return;
  openblas_setter()(threads);
  raised_ = true;
}

BlasCallThreads::~BlasCallThreads() {
  --depth;
  if (raised_) openblas_setter()(1);
}

/// The BLAS library's definition of `name` (the next one after the executable's in the search order).
template <class Fn>
Fn next_blas(const char* name) {
  auto fn = reinterpret_cast<Fn>(dlsym(RTLD_NEXT, name));
  if (!fn) {
    std::fprintf(stderr, "rollsim: the BLAS library has no %s\n", name);
    std::abort();
  }
  return fn;
}

}  // namespace rollsim

// The interposed level-3 calls: the flops of each (m·n·k multiply-adds counted twice as in GEMM's 2mnk; syrk n²k,
// trsm the triangle's order times the right-hand sides' size, potrf n³/3), then the library's own routine.
extern "C" {

void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k, const double* alpha,
            const double* a, const int* lda, const double* b, const int* ldb, const double* beta, double* c,
            const int* ldc) {
  using Fn = void (*)(const char*, const char*, const int*, const int*, const int*, const double*, const double*,
                      const int*, const double*, const int*, const double*, double*, const int*);
  static const auto real = rollsim::next_blas<Fn>("dgemm_");
  const rollsim::BlasCallThreads threads(2.0 * *m * static_cast<double>(*n) * *k);
  real(transa, transb, m, n, k, alpha, a, lda, b, ldb, beta, c, ldc);
}

void dsyrk_(const char* uplo, const char* trans, const int* n, const int* k, const double* alpha, const double* a,
            const int* lda, const double* beta, double* c, const int* ldc) {
  using Fn = void (*)(const char*, const char*, const int*, const int*, const double*, const double*, const int*,
                      const double*, double*, const int*);
  static const auto real = rollsim::next_blas<Fn>("dsyrk_");
  const rollsim::BlasCallThreads threads(*n * static_cast<double>(*n) * *k);
  real(uplo, trans, n, k, alpha, a, lda, beta, c, ldc);
}

void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m, const int* n,
            const double* alpha, const double* a, const int* lda, double* b, const int* ldb) {
  using Fn = void (*)(const char*, const char*, const char*, const char*, const int*, const int*, const double*,
                      const double*, const int*, double*, const int*);
  static const auto real = rollsim::next_blas<Fn>("dtrsm_");
  const int order = (*side == 'L' || *side == 'l') ? *m : *n;
  const rollsim::BlasCallThreads threads(*m * static_cast<double>(*n) * order);
  real(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb);
}

void dpotrf_(const char* uplo, const int* n, double* a, const int* lda, int* info) {
  using Fn = void (*)(const char*, const int*, double*, const int*, int*);
  static const auto real = rollsim::next_blas<Fn>("dpotrf_");
  const rollsim::BlasCallThreads threads(*n * static_cast<double>(*n) * *n / 3.0);
  real(uplo, n, a, lda, info);
}

}  // extern "C"
