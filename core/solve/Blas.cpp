#include "solve/Blas.h"

#include <dlfcn.h>

namespace rollsim {

std::string blas_description() {
  using Config = char* (*)();
  using Core = char* (*)();
  auto config = reinterpret_cast<Config>(dlsym(RTLD_DEFAULT, "openblas_get_config"));
  if (!config) return "reference BLAS (not OpenBLAS: expect slow factorizations)";
  std::string s = std::string("OpenBLAS ") + config();
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

bool set_blas_threads(int threads) { return call_setter("openblas_set_num_threads", threads); }

bool set_openmp_threads(int threads) { return call_setter("omp_set_num_threads", threads); }

void set_library_threads(int threads) {
  set_blas_threads(threads);
  set_openmp_threads(threads);
}

}  // namespace rollsim
