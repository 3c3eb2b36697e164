#include "base/Blas.h"

#include <dlfcn.h>

#include <atomic>

#include "base/BlasCallThreads.h"

namespace rollsim {

std::string blas_description() {
  using Config = char* (*)();
  using Core = char* (*)();
  auto config = reinterpret_cast<Config>(dlsym(RTLD_DEFAULT, "openblas_get_config"));
  if (!config) return "reference BLAS (not OpenBLAS: expect slow factorizations)";
  std::string s = config();  // "OpenBLAS 0.3.21 NO_LAPACKE DYNAMIC_ARCH ..."
  if (s.rfind("OpenBLAS", 0) != 0) s = "OpenBLAS " + s;
  if (auto core = reinterpret_cast<Core>(dlsym(RTLD_DEFAULT, "openblas_get_corename")))
    s += " core=" + std::string(core());
  return s;
}

namespace {
bool call_setter(const char* name, int threads) {
  using Set = void (*)(int);
  auto set = reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, name));
  if (!set) return false;
  set(threads);
  return true;
}
}  // namespace

bool set_blas_threads(int threads) { return set_blas_call_threads(threads); }

namespace {
std::atomic<bool> serial_regions{false};
}  // namespace

bool set_openmp_threads(int threads) {
  serial_regions = true;
  if (!call_setter("omp_set_num_threads", threads)) return false;
  return call_setter("omp_set_max_active_levels", 0);
}

void set_library_threads(int threads) {
  set_blas_threads(threads);
  set_openmp_threads(threads);
}

}  // namespace rollsim

/// libgomp's entry to a `#pragma omp parallel` region, interposed (the executable's definition comes before
/// libgomp's in the dynamic linker's search). Of the libraries rollsim loads, CHOLMOD calls it, and SuperLU_dist,
/// reachable only through PETSc, whose regions then run serially too: the same results, one core. Once
/// set_openmp_threads has been called, a region runs as a direct call on the calling thread: outside a team,
/// omp_get_num_threads() is 1 and omp_get_thread_num() 0, so CHOLMOD's `parallel for` loops (static schedules computed
/// from those two) take their whole range. max-active-levels 0 alone gives the same result but still enters libgomp:
/// a team of one and a futex wake-up per region, 2-5 µs each, ~6700 per factorization of the 16³ cube.
extern "C" void GOMP_parallel(void (*fn)(void*), void* data, unsigned num_threads, unsigned flags) {
  if (rollsim::serial_regions) {
    fn(data);
    return;
  }
  using Real = void (*)(void (*)(void*), void*, unsigned, unsigned);
  static const auto real = reinterpret_cast<Real>(dlsym(RTLD_NEXT, "GOMP_parallel"));
  if (real)
    real(fn, data, num_threads, flags);
  else
    fn(data);
}
