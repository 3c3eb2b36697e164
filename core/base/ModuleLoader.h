#pragma once
// The optional parts that link heavy libraries (the petsc strategy: PETSc and MPI; the .msh reader: Gmsh with
// OpenCASCADE and FLTK) are modules beside the executable, dlopened the first time a run needs them, so that every
// other run starts without mapping those libraries. This finds and opens one; the caller checks its table's version.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace rollsim {

/// Where a module is looked for: $`env` when set and not empty, else `file` in the running executable's folder.
std::filesystem::path module_path(const char* env, const char* file);

/// The table that the entry point `entry` of the module `file` returns (never unloaded). `global`: its symbols are
/// made available to libraries it loads itself (MPI's components). Throws std::runtime_error with why (dlerror).
const void* load_module(const std::filesystem::path& file, const char* entry, bool global);

}  // namespace rollsim
