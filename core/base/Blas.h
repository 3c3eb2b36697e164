#pragma once
// Which BLAS is loaded at run time, and the thread counts of the numerical libraries: OpenBLAS's pthreads and the
// OpenMP loops inside CHOLMOD (Debian's SuiteSparse is built with OpenMP). Both are found through dlsym, so the
// program still runs, slower, with the reference BLAS or a CHOLMOD without OpenMP.
#include <string>

namespace rollsim {

/// e.g. "OpenBLAS 0.3.21 DYNAMIC_ARCH ... Haswell MAX_THREADS=64" or "reference BLAS (not OpenBLAS)".
std::string blas_description();
/// Sets the BLAS thread count (process-wide) when the BLAS supports it; returns false otherwise. Only calls of at
/// least kThreadedBlasFlops use them (BlasCallThreads.h): the small ones of a supernodal factorization run on one.
bool set_blas_threads(int threads);
/// Sets the OpenMP thread count of the *calling thread* (OpenMP's nthreads ICV is per thread: a thread started
/// with std::thread begins with the process default, OMP_NUM_THREADS or the core count), and makes every OpenMP
/// region of the process run on its calling thread alone (max-active-levels 0). The second is what counts: the only
/// OpenMP in the process is CHOLMOD's supernodal loops (clear a supernode, scatter A into it), compiled with
/// `num_threads(CHOLMOD_OMP_NUM_THREADS)` = 4, a clause that overrides the thread count set here. They started a
/// team of 4 on this 2-core machine for every supernode — with `--threads 1` too, and per worker in feti — whose
/// spinning and futex wake-ups took a third of the process's CPU time as system time. The parallel work goes to
/// OpenBLAS (large supernodes) and to rollsim's own group threads (Parallel.h).
bool set_openmp_threads(int threads);
/// Both: what a solver needs before it calls CHOLMOD / BLAS with `threads` cores to use.
void set_library_threads(int threads);

}  // namespace rollsim
