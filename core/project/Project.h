#pragma once
// A validated project: the JSON document with defaults filled in, plus where it came from.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/Schema.h"
#include "project/Overrides.h"
#include "project/RunConfig.h"

namespace rollsim {

struct Project {
  json data;           // validated, defaults filled in: what the model is built from and the window edits
  std::string source;  // file path, for messages
  /// The run's options, typed, read from `data` (a front end reads them once per run and passes them on).
  RunConfig config() const { return read_run_config(data); }
  std::string name() const { return data.value("name", std::string("project")); }
  int dimension() const { return data.at("dimension").get<int>(); }
};

/// Invalid input: every problem found, each with its JSON path.
class ProjectError : public std::runtime_error {
 public:
  ProjectError(std::string source, std::vector<Issue> issues);
  const std::vector<Issue>& issues() const { return issues_; }

 private:
  std::vector<Issue> issues_;
};

/// Parses and validates a project file (syntax, schema and cross-references), with a command line's `overrides`
/// applied to the JSON first (their problems named by their flags). Throws ProjectError.
Project load_project(const std::filesystem::path& file, const Overrides& overrides = {});
/// Same, from text already in memory (`source` names it in messages).
Project parse_project(const std::string& text, const std::string& source, const Overrides& overrides = {});

}  // namespace rollsim
