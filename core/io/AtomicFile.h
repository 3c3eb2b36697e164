#pragma once
// Files written whole or not at all. The content goes to a fresh temporary beside the target — created exclusively
// (O_EXCL: an existing name, a planted symlink included, is never followed or reused), each write's byte count
// checked, fsync'ed — and is renamed over the target only then, after which the folder is fsync'ed too. A target
// that is a symlink is written through (the link stays a link); an existing target keeps its permissions; a target
// the user cannot write (read-only) is refused rather than replaced. Every failure throws WriteError naming the
// target and the OS reason, and leaves the target as it was and no temporary behind.
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace rollsim {

struct WriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void write_file_atomically(const std::filesystem::path& target, const std::string& content);

/// False for what the user cannot write or has marked read-only (no write bit: refused even for root, whom the
/// kernel would let write).
bool is_writable(const std::filesystem::path& path);

/// The name a temporary of write_file_atomically stands for: ".NAME.<tag>.tmp" (and an older ".NAME.tmp") give
/// NAME; any other name gives nothing.
std::optional<std::string> temporary_for(const std::string& filename);

}  // namespace rollsim
