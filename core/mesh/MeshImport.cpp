#include "mesh/MeshImport.h"

#include <cctype>
#include <map>
#include <mutex>
#include <tuple>

#include "mesh/GmshReader.h"
#include "mesh/InpReader.h"

namespace rollsim {

namespace {

struct Reader {
  std::string extension, format;
  Mesh (*read)(const std::filesystem::path& file, int dim, const std::string& element_set);
};

Mesh read_inp(const std::filesystem::path& file, int dim, const std::string& element_set) {
  return inp_body_mesh(read_inp_deck(file), dim, element_set, file.string());
}

const std::vector<Reader>& readers() {
  static const std::vector<Reader> table{
      {".inp", "CalculiX / Abaqus input deck", read_inp},
      {".msh", "Gmsh mesh, version 4 or 2, ASCII or binary (Gmsh's library)", read_msh}};
  return table;
}

const Reader& reader_for(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const Reader& r : readers())
    if (r.extension == ext) return r;
  std::string known;
  for (const std::string& f : importable_formats()) known += (known.empty() ? "" : "; ") + f;
  throw MeshImportError(file.string() + ": no reader for files ending '" + file.extension().string() +
                        "' (rollsim reads " + known + ")");
}

/// A file as last read: which file, when it was changed and how big it was, and for which body.
using Key = std::tuple<std::string, std::filesystem::file_time_type, std::uintmax_t, int, std::string>;

}  // namespace

std::vector<std::string> importable_formats() {
  std::vector<std::string> out;
  for (const Reader& r : readers()) out.push_back(r.extension + " — " + r.format);
  return out;
}

std::shared_ptr<const Mesh> import_mesh(const std::filesystem::path& file, int dim, const std::string& element_set) {
  const Reader& reader = reader_for(file);
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  const auto changed = ec ? std::filesystem::file_time_type{} : std::filesystem::last_write_time(file, ec);
  if (ec || !std::filesystem::is_regular_file(file))
    throw MeshImportError(file.string() + ": cannot be read (" + (ec ? ec.message() : "not a regular file") + ")");
  static std::mutex mutex;
  static std::map<Key, std::shared_ptr<const Mesh>> cache;  // a handful of files per project
  const Key key{std::filesystem::absolute(file).string(), changed, size, dim, element_set};
  {
    std::lock_guard lock(mutex);
    if (const auto it = cache.find(key); it != cache.end()) return it->second;
  }
  auto mesh = std::make_shared<const Mesh>(reader.read(file, dim, element_set));
  std::lock_guard lock(mutex);
  if (cache.size() > 16) cache.clear();
  return cache.emplace(key, std::move(mesh)).first->second;
}

}  // namespace rollsim
