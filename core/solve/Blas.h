#pragma once
// Which BLAS is loaded at run time, and the thread counts of the numerical libraries: OpenBLAS's pthreads and the
// OpenMP loops inside CHOLMOD (Debian's SuiteSparse is built with OpenMP). Both are found through dlsym, so the
// program still runs, slower, with the reference BLAS or a CHOLMOD without OpenMP.
#include <string>

namespace rollsim {

/// e.g. "OpenBLAS 0.3.21 DYNAMIC_ARCH ... Haswell MAX_THREADS=64" or "reference BLAS (not OpenBLAS)".
std::string blas_description();
/// Sets the BLAS thread count (process-wide) when the BLAS supports it; returns false otherwise.
bool set_blas_threads(int threads);
/// Sets the OpenMP thread count of the *calling thread* (OpenMP's nthreads ICV is per thread: a thread started
/// with std::thread begins with the process default, OMP_NUM_THREADS or the core count).
bool set_openmp_threads(int threads);
/// Both: what a solver needs before it calls CHOLMOD / BLAS with `threads` cores to use.
void set_library_threads(int threads);

}  // namespace rollsim
