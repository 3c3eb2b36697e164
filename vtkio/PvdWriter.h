#pragma once
// The load increments of a run as a ParaView collection: one VTU per increment and a .pvd file that lists them with
// their time — the process's clock (a rolling pass: the roll travel) or else the load factor — so ParaView steps
// through the increments in the process's own terms. Each VTU carries its load factor (and clock value) as field
// data. No VTK header appears here.
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/Results.h"
#include "model/Model.h"

namespace rollsim {

/// Writes `<stem>_0001.vtu`, `<stem>_0002.vtu`, … beside `pvd` (stem: the pvd file's, the fields of
/// Results::increments in order, arrays as write_vtu's) and then `pvd`, a VTKFile of type Collection with one DataSet
/// per increment (timestep = the process clock's value, else the load factor; file relative to the pvd). Every file is
/// written atomically, the collection last; the arrays those `selected` names (output.fields; empty: every one). When
/// `stop` turns true (asked before each VTU), the collection lists the increments written so far. Returns the VTU
/// files. Throws WriteError when a file cannot be written. The field data of a state at `load_factor`: load_factor, and
/// the process clock's value under its name.
std::vector<std::pair<std::string, double>> state_values(const Results& results, double load_factor);

std::vector<std::filesystem::path> write_increment_collection(const std::filesystem::path& pvd, const Model& model,
                                                              const Results& results,
                                                              const std::vector<std::string>& selected = {},
                                                              const std::function<bool()>& stop = {},
                                                              const std::string& compression = "lz4");

}  // namespace rollsim
