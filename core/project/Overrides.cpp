#include "project/Overrides.h"

#include "project/ProjectSchema.h"

namespace rollsim {

namespace {

/// The value as the field at `path` takes it: a number or a flag parsed, anything else (and what does not parse)
/// a string, so that validation names the wrong value.
json typed_value(const std::string& path, const std::string& text) {
  const Field* f = find_field(project_schema(), path);
  const bool textual = f && (f->kind == Kind::String || f->kind == Kind::Choice);
  if (!textual) {
    try {
      return json::parse(text);
    } catch (const json::exception&) {
    }
  }
  return text;
}

/// The node at `path` below `root`, created as objects where missing; null when an array item is not there.
json* node_at(json& root, const std::string& path) {
  json* node = &root;
  size_t at = 0;
  while (at < path.size()) {
    size_t end = path.find('.', at);
    if (end == std::string::npos) end = path.size();
    std::string key = path.substr(at, end - at);
    std::optional<size_t> item;
    if (const auto open = key.find('['); open != std::string::npos) {
      const std::string digits = key.substr(open + 1, key.size() - open - 2);
      if (digits.size() > 9) return nullptr;  // beyond any array a project holds
      item = std::stoul(digits);
      key.resize(open);
    }
    if (node->is_null()) *node = json::object();
    if (!node->is_object()) return nullptr;
    node = &(*node)[key];
    if (item) {
      if (!node->is_array() || *item >= node->size()) return nullptr;
      node = &(*node)[*item];
    }
    at = end + 1;
  }
  return node;
}

bool well_formed(const std::string& path) {
  if (path.empty() || path.front() == '.' || path.back() == '.' || path.find("..") != std::string::npos) return false;
  for (size_t open = path.find('['); open != std::string::npos; open = path.find('[', open + 1)) {
    const size_t close = path.find(']', open);
    if (close == std::string::npos || close == open + 1) return false;
    for (size_t i = open + 1; i < close; ++i)
      if (!std::isdigit(static_cast<unsigned char>(path[i]))) return false;
  }
  return true;
}

/// --partition [BODY=]SPEC: the named body's (default: the first) partition, or the generated slab's of a process.
std::string apply_partition(json& p, const std::string& arg) {
  const auto eq = arg.find('=');
  const std::string body = eq == std::string::npos ? "" : arg.substr(0, eq);
  const std::string spec = eq == std::string::npos ? arg : arg.substr(eq + 1);
  json& bodies = p["bodies"];
  if (bodies.is_null()) bodies = json::array();
  const bool slab = p.contains("process") && (body == "slab" || (body.empty() && bodies.empty()));
  if (slab) {
    p["process"].erase("slab_partition_map");
    p["process"]["slab_partition"] = spec;
    return "";
  }
  json* target = body.empty() && !bodies.empty() ? &bodies[0] : nullptr;
  for (auto& b : bodies)
    if (!body.empty() && b.is_object() && b.value("name", "") == body) target = &b;
  if (!target) return "no body named '" + body + "'";
  target->erase("partition_map");
  (*target)["partition"] = spec;
  return "";
}

}  // namespace

std::vector<Issue> apply_overrides(json& project, const Overrides& overrides) {
  std::vector<Issue> issues;
  for (const Override& o : overrides.sets) {
    if (!well_formed(o.path)) {
      issues.push_back({o.origin, "'" + o.path + "' is not a field path (e.g. solver.threads, bodies[0].partition)"});
      continue;
    }
    json* node = node_at(project, o.path);
    if (!node) {
      issues.push_back({o.origin, o.path + ": no such array item in the project"});
      continue;
    }
    *node = typed_value(o.path, o.value);
  }
  if (overrides.partition)
    if (std::string problem = apply_partition(project, *overrides.partition); !problem.empty())
      issues.push_back({"--partition", problem});
  return issues;
}

std::string override_origin(const Overrides& overrides, const std::string& path) {
  std::string origin;
  for (const Override& o : overrides.sets)
    if (path == o.path || path.rfind(o.path + ".", 0) == 0 || path.rfind(o.path + "[", 0) == 0)
      origin = o.origin == "--set" ? "--set " + o.path : o.origin;  // the last one that set it
  return origin;
}

}  // namespace rollsim
