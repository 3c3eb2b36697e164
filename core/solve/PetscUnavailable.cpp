// The `petsc` strategy in a build without PETSc (ROLLSIM_WITH_PETSC off): the name stays in the registry, so a
// project or command line asking for it gets this message instead of "unknown solver".
#include <stdexcept>

#include "solve/PetscStrategy.h"

namespace rollsim {

bool petsc_available() { return false; }

std::unique_ptr<SolverStrategy> make_petsc_strategy(const SolverOptions&) {
  throw std::invalid_argument(
      "solver 'petsc': this build has no PETSc — install libpetsc-real-dev (scripts/install-deps.sh) and configure "
      "with -DROLLSIM_WITH_PETSC=ON");
}

void start_processes() {}
int process_rank() { return 0; }
void finish_processes() {}

}  // namespace rollsim
