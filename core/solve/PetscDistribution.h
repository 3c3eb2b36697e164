#pragma once
// The MPI GroupDistribution of the petsc module (PetscDistribution.cpp): group g on rank g mod P.
#include <memory>

#include "solve/GroupDistribution.h"

namespace rollsim {

/// Starts PETSc and MPI if needed and returns this rank's view of the groups over PETSC_COMM_WORLD.
std::shared_ptr<const GroupDistribution> mpi_group_distribution();

}  // namespace rollsim
