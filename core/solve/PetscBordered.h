#pragma once
// `petsc` with `petsc_method: mumps` (issue 37): paper eq. (1) whole — every group's stiffness, the contact rows
// (frictionless, sticking, Coulomb's unsymmetric slip) and any subdomain glue — as one distributed PETSc matrix,
// factored by MUMPS's parallel LU, on any number of MPI ranks. Each rank assembles the tangents of its share of the
// groups (group g on rank g mod P) and hands their entries over by global position; rank 0 adds the border. The
// same matrix as `direct` (solve/BorderedMatrix), so the same answer to round-off: the distributed direct baseline.
// Part of the module rollsim_petsc.so (PetscStrategy.cpp chooses it), never of the core.
#include <memory>

#include "solve/SolverStrategy.h"

namespace rollsim {

std::unique_ptr<SolverStrategy> make_petsc_bordered(const SolverOptions& options);

}  // namespace rollsim
