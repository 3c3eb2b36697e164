#pragma once
// A fresh empty folder under the system temp dir for one test: rollsim-<tag>-<pid>, emptied if it exists.
#include <unistd.h>

#include <filesystem>
#include <string>

inline std::filesystem::path fresh_dir(const std::string& tag) {
  const std::filesystem::path d =
      std::filesystem::temp_directory_path() / ("rollsim-" + tag + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}
