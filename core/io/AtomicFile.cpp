#include "io/AtomicFile.h"

#include <fstream>
#include <stdexcept>

namespace rollsim {

void write_file_atomically(const std::filesystem::path& target, const std::string& content) {
  const auto tmp = target.parent_path() / ("." + target.filename().string() + ".tmp");
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  out << content;
  out.close();
  std::error_code ec;
  if (out) std::filesystem::rename(tmp, target, ec);
  if (!out || ec) {
    std::filesystem::remove(tmp, ec);  // no temporary left behind
    throw std::runtime_error("cannot write " + target.string());
  }
}

}  // namespace rollsim
