#pragma once
// Strategy "petsc" (issue 15): the subdomain groups handed to PETSc as one unassembled MATIS matrix — each MPI rank
// holds its own subdomain's K_g, the local-to-global map recovered from the glue rows B_i — and solved by PCBDDC in
// CG or by KSPFETIDP. PETSc is an optional dependency: this header is the same in every build; PetscStrategy.cpp
// implements it with PETSc (ROLLSIM_WITH_PETSC), PetscUnavailable.cpp without (every call that needs PETSc
// refuses with std::invalid_argument, which the CLI reports as invalid input, exit 2).
#include <memory>

#include "solve/SolverStrategy.h"

namespace rollsim {

/// True when this build links PETSc.
bool petsc_available();

/// The `petsc` strategy; without PETSc throws std::invalid_argument saying how to build with it.
std::unique_ptr<SolverStrategy> make_petsc_strategy(const SolverOptions& options);

/// Starts PETSc and MPI (once; a no-op without PETSc): every rank of `mpirun -n P` calls it before building the model.
void start_processes();
/// This process's MPI rank (0 without MPI started): rank 0 writes the outputs.
int process_rank();
/// Ends PETSc and MPI when start_processes started them (at the end of main).
void finish_processes();

}  // namespace rollsim
