#pragma once
// The boundary between rollsim and its `petsc` module (rollsim_petsc.so, built from PetscStrategy.cpp with
// ROLLSIM_WITH_PETSC): the module exports one C function, rollsim_petsc_module(), returning this table; the core's
// PetscLoader.cpp dlopens the module the first time a run chooses `petsc` and calls through the table, so PETSc and
// its MPI stack are mapped by that run only. Both sides are compiled from this header in one build: kPetscModuleAbi
// changes with the table, and a module of another build is refused instead of called.
#include <filesystem>
#include <memory>

#include "solve/GroupDistribution.h"
#include "solve/SolverStrategy.h"

namespace rollsim {

inline constexpr int kPetscModuleAbi = 7;  // 2: SolverOptions holds enums; 3: max_interface_iterations; 4:
                                           // BlockSystem::interface_tolerance; 5: mumps; 6: mixed (distribution);
                                           // 7: InterfaceTolerance::at_most
inline constexpr const char* kPetscModuleFile = "rollsim_petsc.so";       // beside the executable
inline constexpr const char* kPetscModuleEnv = "ROLLSIM_PETSC_MODULE";    // overrides where it is
inline constexpr const char* kPetscModuleEntry = "rollsim_petsc_module";  // its one exported symbol

struct PetscModule {
  int abi = kPetscModuleAbi;
  std::unique_ptr<SolverStrategy> (*make_strategy)(const SolverOptions&);  // the strategies of PetscStrategy.h
  void (*start)();                                                         // start_processes
  int (*rank)();                                                           // process_rank
  void (*finish)();                                                        // finish_processes
  std::shared_ptr<const GroupDistribution> (*distribution)();  // the groups over the ranks (petsc_method: mixed)
};

/// Where the module is looked for: $ROLLSIM_PETSC_MODULE when set and not empty, else rollsim_petsc.so in the
/// folder of the running executable (/proc/self/exe).
std::filesystem::path petsc_module_path();

}  // namespace rollsim
