#pragma once
// A body's mesh read from a file (a project's mesh `type: import`): the reader chosen by the file's extension from a
// table (.inp: CalculiX / Abaqus decks, mesh/InpReader), and each file read once per change — the checks of a
// project and the model built from it ask for the same mesh several times.
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "mesh/Mesh.h"

namespace rollsim {

/// A mesh file that cannot be read or used: the message names the file (and the line where there is one); `field`
/// is the mesh spec's field at fault ("file" or "element_set").
class MeshImportError : public std::runtime_error {
 public:
  explicit MeshImportError(const std::string& what, std::string field = "file")
      : std::runtime_error(what), field_(std::move(field)) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

/// What the importer reads: ".inp — CalculiX / Abaqus input deck", one line per reader (for the schema's doc).
std::vector<std::string> importable_formats();

/// The mesh of `file` (absolute, or relative to the working folder) for a `dim`-dimensional model, made of the
/// elements of `element_set` (all when empty); the same object while the file is unchanged. Throws MeshImportError.
std::shared_ptr<const Mesh> import_mesh(const std::filesystem::path& file, int dim, const std::string& element_set);

}  // namespace rollsim
