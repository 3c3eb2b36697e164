#pragma once
// A validated project: the JSON document with defaults filled in, plus where it came from.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "project/Schema.h"

namespace rollsim {

struct Project {
  json data;
  std::string source;  // file path, for messages
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

/// Parses and validates a project file (syntax, schema and cross-references). Throws ProjectError.
Project load_project(const std::filesystem::path& file);
/// Same, from text already in memory (`source` names it in messages).
Project parse_project(const std::string& text, const std::string& source);

}  // namespace rollsim
