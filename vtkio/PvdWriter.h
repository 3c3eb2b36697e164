#pragma once
// The load increments of a run as a ParaView collection: one VTU per increment and a .pvd file that lists them with
// their load factor as the time step, so ParaView steps through the increments. No VTK header appears here.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/Results.h"
#include "model/Model.h"

namespace rollsim {

/// Writes `<stem>_0001.vtu`, `<stem>_0002.vtu`, … beside `pvd` (stem: the pvd file's, the fields of
/// Results::increments in order, arrays as write_vtu's) and then `pvd`, a VTKFile of type Collection with one DataSet
/// per increment (timestep = load factor i / N, file relative to the pvd). Every file is written atomically, the
/// collection last; the arrays those `selected` names (output.fields; empty: every one). Returns the VTU files. Throws
/// std::runtime_error when a file cannot be written.
std::vector<std::filesystem::path> write_increment_collection(const std::filesystem::path& pvd, const Model& model,
                                                              const Results& results,
                                                              const std::vector<std::string>& selected = {});

}  // namespace rollsim
