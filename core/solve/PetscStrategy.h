#pragma once
// Strategy "petsc" (issue 15): the subdomain groups handed to PETSc as one unassembled MATIS matrix — each MPI rank
// holds its own subdomain's K_g, the local-to-global map recovered from the glue rows B_i — and solved by PCBDDC in
// CG or by KSPFETIDP. PETSc is an optional dependency: this header is the same in every build; with PETSc
// (ROLLSIM_WITH_PETSC) PetscLoader.cpp implements it by loading the module rollsim_petsc.so (PetscStrategy.cpp) the
// first time it is needed, without PETSc PetscUnavailable.cpp (every call that needs PETSc refuses with
// std::invalid_argument, which the CLI reports as invalid input, exit 2; so does a module that cannot be loaded).
#include <memory>

#include "solve/SolverStrategy.h"

namespace rollsim {

/// True when this build has the petsc module (whether it loads is known when it is first needed).
bool petsc_available();

/// The `petsc` strategy, loading the module on first use; without PETSc, or when the module cannot be loaded, throws
/// std::invalid_argument saying why.
std::unique_ptr<SolverStrategy> make_petsc_strategy(const SolverOptions& options);

/// Starts PETSc and MPI (once; a no-op without PETSc): every rank of `mpirun -n P` calls it before building the model.
void start_processes();
/// This process's MPI rank (0 without MPI started, and without the module loaded): rank 0 writes the outputs.
int process_rank();
/// Ends PETSc and MPI when start_processes started them (at the end of main).
void finish_processes();

}  // namespace rollsim
