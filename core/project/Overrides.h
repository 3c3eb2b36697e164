#pragma once
// Changes a command line makes to a project before it is validated: the flags the schema marks (Field::flag, e.g.
// --threads sets solver.threads), `--set PATH=VALUE` for any field, and --partition's [BODY=]SPEC. They are applied
// to the JSON, so the one validation checks them and its messages name the flag that gave the value.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "base/Schema.h"

namespace rollsim {

struct Override {
  std::string path;    // dotted, with [i] for an array's item: "solver.threads", "bodies[0].partition"
  std::string value;   // as typed: read as a number or true/false where the field takes one, else as a string
  std::string origin;  // what the user wrote, for messages: "--threads", "--set"
};

struct Overrides {
  std::vector<Override> sets;
  std::optional<std::string> partition;  // --partition [BODY=]SPEC: that body's (default: the first) partition
  bool empty() const { return sets.empty() && !partition; }
};

/// Applies `overrides` to an unvalidated project document (an object); returns the problems with what was asked (a
/// path that names no field, an array item that is not there, a body that is not there), each under its origin.
std::vector<Issue> apply_overrides(json& project, const Overrides& overrides);

/// The origin of the override that set `path` (or a field below it): the validation issue's path to show ("" if
/// none did).
std::string override_origin(const Overrides& overrides, const std::string& path);

}  // namespace rollsim
