// Tests of the library thread settings: after set_library_threads(1) a CHOLMOD factorization with large supernodes
// starts no thread (CHOLMOD's OpenMP loops ask for 4 threads whatever omp_set_num_threads says: they ran a team of 4
// on 2 cores for every supernode), and the BLAS is named.
#include <gtest/gtest.h>

#include <filesystem>

#include "../solve/grid_matrix.h"
#include "base/Blas.h"
#include "solve/CholmodFactorization.h"

namespace rollsim::test_blas {
namespace {

long threads_of_this_process() {
  long n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator("/proc/self/task")) ++n;
  return n;
}

TEST(Blas, OneLibraryThreadStartsNoOpenMpTeam) {
  set_library_threads(1);
  const SparseMatrix A = testing::fe_grid_matrix(10, 3, 3, 21);  // 3993 dofs: supernodes of hundreds of columns
  CholmodFactorization chol;
  chol.analyze(A);
  const long before = threads_of_this_process();
  chol.factorize(A);
  EXPECT_EQ(threads_of_this_process(), before);
}

TEST(Blas, NamesTheLibrary) { EXPECT_FALSE(blas_description().empty()); }

}  // namespace
}  // namespace rollsim::test_blas
