#include "base/ModuleLoader.h"

#include <dlfcn.h>

#include <cstdlib>

namespace rollsim {

std::filesystem::path module_path(const char* env, const char* file) {
  if (const char* set = std::getenv(env); set && *set) return set;
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path(file) : exe.parent_path() / file;
}

const void* load_module(const std::filesystem::path& file, const char* entry, bool global) {
  // RTLD_NOW: a missing symbol is this message, not a crash in the middle of a run
  void* handle = dlopen(file.c_str(), RTLD_NOW | (global ? RTLD_GLOBAL : RTLD_LOCAL));
  if (!handle) throw std::runtime_error(dlerror());
  using Entry = const void* (*)();
  const auto function = reinterpret_cast<Entry>(dlsym(handle, entry));
  if (!function) {
    const std::string why = dlerror();
    dlclose(handle);
    throw std::runtime_error("no entry point " + std::string(entry) + " (" + why + ")");
  }
  const void* table = function();
  if (!table) throw std::runtime_error("its entry point " + std::string(entry) + " returned nothing");
  return table;
}

}  // namespace rollsim
