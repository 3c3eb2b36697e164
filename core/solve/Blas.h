#pragma once
// Which BLAS is loaded at run time, and its thread count (OpenBLAS is found through dlsym,
// so the program still runs, slower, with the reference BLAS).
#include <string>

namespace rollsim {

/// e.g. "OpenBLAS 0.3.21 DYNAMIC_ARCH ... Haswell MAX_THREADS=64" or "reference BLAS (not OpenBLAS)".
std::string blas_description();
/// Sets the BLAS thread count when the BLAS supports it; returns false otherwise.
bool set_blas_threads(int threads);

}  // namespace rollsim
