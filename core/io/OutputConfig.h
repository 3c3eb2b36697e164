#pragma once
// The output section of a run, typed: where results go and which are written. Read from the validated project
// (project/RunConfig), whose schema holds the defaults.
#include <optional>
#include <string>
#include <vector>

namespace rollsim {

struct OutputConfig {
  std::optional<std::string> dir;   // output.dir (none: results/<project name>, or --out)
  bool vtu = false;                 // write result.vtu
  bool all_increments = false;      // and results.pvd with one VTU per increment (output.increments: all)
  std::vector<std::string> fields;  // output.fields as given (`all`, or names; empty: every one)
  std::string compression = "lz4";  // output.compression of the VTU files: lz4, zlib or none
};

}  // namespace rollsim
