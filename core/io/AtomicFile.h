#pragma once
// Files written whole or not at all: write to a temporary name beside the target, then rename.
#include <filesystem>
#include <string>

namespace rollsim {

void write_file_atomically(const std::filesystem::path& target, const std::string& content);

}  // namespace rollsim
