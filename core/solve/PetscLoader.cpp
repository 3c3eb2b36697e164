// The `petsc` strategy in a build with PETSc (ROLLSIM_WITH_PETSC): its code is the module rollsim_petsc.so
// (PetscStrategy.cpp, the only code that links PETSc and MPI), loaded here the first time a run chooses `petsc`.
// Every other command and solver mode runs without mapping PETSc and its MPI stack (docs/BENCHMARKS-AUTO.md,
// start-up). A module that cannot be loaded is invalid input for that run: a message naming the file and why.
#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <mutex>
#include <stdexcept>

#include "base/ModuleLoader.h"
#include "solve/MixedStrategy.h"
#include "solve/PetscModule.h"
#include "solve/PetscStrategy.h"

namespace rollsim {

namespace {

std::mutex load_mutex;
std::atomic<const PetscModule*> loaded{nullptr};  // never unloaded: strategies and PETSc live to the process's end

std::invalid_argument load_error(const std::filesystem::path& file, const std::string& why) {
  return std::invalid_argument("solver 'petsc': cannot load its module " + file.string() + ": " + why +
                               " (it is built beside the rollsim binary with -DROLLSIM_WITH_PETSC=ON; " +
                               kPetscModuleEnv + " names another path)");
}

const PetscModule& load() {
  std::lock_guard lock(load_mutex);
  if (const PetscModule* m = loaded.load()) return *m;
  const std::filesystem::path file = petsc_module_path();
  const PetscModule* module = nullptr;
  try {
    // global: MPI_Init dlopens Open MPI's own components, which look MPI's symbols up in the global scope
    // (open-mpi/ompi#3705)
    module = static_cast<const PetscModule*>(load_module(file, kPetscModuleEntry, true));
  } catch (const std::runtime_error& e) {
    throw load_error(file, e.what());
  }
  if (module->abi != kPetscModuleAbi)
    throw load_error(file, "it was built by another rollsim (module interface " + std::to_string(module->abi) +
                               ", this binary's " + std::to_string(kPetscModuleAbi) + "): rebuild both together");
  loaded = module;
  return *module;
}

}  // namespace

std::filesystem::path petsc_module_path() { return module_path(kPetscModuleEnv, kPetscModuleFile); }

bool petsc_available() { return true; }

std::unique_ptr<SolverStrategy> make_petsc_strategy(const SolverOptions& options) {
  const PetscModule& module = load();
  if (options.petsc_method == PetscMethod::Mixed)  // the paper's mixed method, its groups spread over the ranks
    return std::make_unique<MixedStrategy>(options, true, "cholmod", module.distribution());
  return module.make_strategy(options);
}

void start_processes() { load().start(); }

int process_rank() {
  const PetscModule* m = loaded.load();
  return m ? m->rank() : 0;  // no module loaded: PETSc and MPI were never started here
}

void finish_processes() {
  if (const PetscModule* m = loaded.load()) m->finish();
}

}  // namespace rollsim
