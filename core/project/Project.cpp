#include "project/Project.h"

#include <fstream>
#include <sstream>

#include "project/DuplicateKeys.h"
#include "project/ModelBuilder.h"
#include "project/ProjectSchema.h"

namespace rollsim {

namespace {
std::string join(const std::string& source, const std::vector<Issue>& issues) {
  std::string s = source + ": invalid project";
  for (const Issue& i : issues) s += "\n  " + i.str();
  return s;
}

std::string line_column(const std::string& text, size_t byte) {
  size_t line = 1, col = 1;
  for (size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(col);
}

// nlohmann's messages start with "[json.exception.parse_error.101] parse error at line 3, column 5: "
std::string parse_reason(const std::string& what) {
  const auto p = what.find(": ", what.find("parse error"));
  std::string r = p == std::string::npos ? what : what.substr(p + 2);
  if (r.rfind("syntax error while parsing value - ", 0) == 0) r = r.substr(35);
  return r;
}

// nlohmann::json parses iteratively but dumps recursively: refuse deep nesting before parsing (no stack overflow).
constexpr int kMaxNesting = 64;

void check_nesting(const std::string& text, const std::string& source) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxNesting)
        throw ProjectError(source, {{"", "arrays and objects nested deeper than " + std::to_string(kMaxNesting) +
                                             " levels at " + line_column(text, i)}});
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

// nlohmann reports "number overflow parsing '1e400'" without a position: locate the literal in the text.
std::string number_overflow(const std::string& text, const std::string& what) {
  const auto open = what.find('\''), close = what.rfind('\'');
  if (open == std::string::npos || close <= open) return "not valid JSON: " + what;
  const std::string literal = what.substr(open + 1, close - open - 1);
  const auto at = text.find(literal);
  return "not valid JSON" + (at == std::string::npos ? std::string() : " at " + line_column(text, at)) + ": number " +
         literal + " is beyond the range of a double";
}
}  // namespace

ProjectError::ProjectError(std::string source, std::vector<Issue> issues)
    : std::runtime_error(join(source, issues)), issues_(std::move(issues)) {}

namespace {
/// Issues at a path an override set are shown under the flag that set it ("--threads: must be …").
std::vector<Issue> named_by_origin(std::vector<Issue> issues, const Overrides& overrides) {
  for (Issue& i : issues)
    if (std::string origin = override_origin(overrides, i.path); !origin.empty()) i.path = origin;
  return issues;
}
}  // namespace

Project parse_project(const std::string& text, const std::string& source, const Overrides& overrides) {
  Project p;
  p.source = source;
  check_nesting(text, source);
  try {
    p.data = json::parse(text);
  } catch (const json::parse_error& e) {
    throw ProjectError(source, {{"", "not valid JSON at " + line_column(text, e.byte ? e.byte - 1 : 0) + ": " +
                                         parse_reason(e.what())}});
  } catch (const json::out_of_range& e) {
    throw ProjectError(source, {{"", number_overflow(text, e.what())}});
  } catch (const json::exception& e) {
    throw ProjectError(source, {{"", std::string("not valid JSON: ") + e.what()}});
  }
  if (!p.data.is_object()) throw ProjectError(source, {{"", "the top level must be a JSON object"}});
  if (std::vector<Issue> twice = duplicate_keys(text); !twice.empty()) throw ProjectError(source, twice);
  if (std::vector<Issue> asked = apply_overrides(p.data, overrides); !asked.empty()) throw ProjectError(source, asked);
  // the dimension is needed to check vectors, so it is checked first
  const auto d = p.data.find("dimension");
  if (d == p.data.end() || !d->is_number_integer() || (d->get<long long>() != 2 && d->get<long long>() != 3))
    throw ProjectError(source, {{"dimension", d == p.data.end() ? "is required (2 or 3)"
                                                                : "must be one of 2, 3, got " + describe(*d)}});
  std::vector<Issue> issues;
  validate_object(p.data, project_schema(), "", p.dimension(), issues);
  if (!issues.empty()) throw ProjectError(source, named_by_origin(issues, overrides));
  if (!p.data.contains("name")) p.data["name"] = std::filesystem::path(source).stem().string();
  check_references(p, issues);
  if (!issues.empty()) throw ProjectError(source, named_by_origin(issues, overrides));
  return p;
}

Project load_project(const std::filesystem::path& file, const Overrides& overrides) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw ProjectError(file.string(), {{"", "no such file (or not a regular file)"}});
  const auto size = std::filesystem::file_size(file, ec);
  if (ec || size > (64u << 20)) throw ProjectError(file.string(), {{"", "file is larger than 64 MiB"}});
  std::ifstream in(file, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  if (!in.good() && !in.eof()) throw ProjectError(file.string(), {{"", "cannot be read"}});
  return parse_project(ss.str(), file.string(), overrides);
}

}  // namespace rollsim
