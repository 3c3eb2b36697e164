#pragma once
// Short builders of schema fields, for the files that declare a section (project/ProjectSchema, solve/SolverSchema,
// analysis/NewtonSchema, process/rolling): a field is one expression, its default written beside its name.
#include <string>
#include <utility>
#include <vector>

#include "base/Schema.h"

namespace rollsim::schema {

inline Field num(std::string name, std::string unit, std::string doc) {
  Field f;
  f.name = std::move(name);
  f.kind = Kind::Number;
  f.unit = std::move(unit);
  f.doc = std::move(doc);
  return f;
}
inline Field positive(std::string name, std::string unit, std::string doc) {
  Field f = num(std::move(name), std::move(unit), std::move(doc));
  f.min = 0.0;
  f.min_exclusive = true;
  return f;
}
inline Field non_negative(std::string name, std::string unit, std::string doc) {
  Field f = num(std::move(name), std::move(unit), std::move(doc));
  f.min = 0.0;
  return f;
}
inline Field count(std::string name, std::string doc, double max = 1e6) {
  Field f;
  f.name = std::move(name);
  f.kind = Kind::Integer;
  f.min = 1;
  f.max = max;
  f.doc = std::move(doc);
  return f;
}
inline Field str(std::string name, std::string doc) {
  Field f;
  f.name = std::move(name);
  f.kind = Kind::String;
  f.doc = std::move(doc);
  return f;
}
inline Field boolean(std::string name, std::string doc) {
  Field f;
  f.name = std::move(name);
  f.kind = Kind::Boolean;
  f.doc = std::move(doc);
  return f;
}
inline Field vec(std::string name, std::string unit, std::string doc, int size = 0) {
  Field f = num(std::move(name), std::move(unit), std::move(doc));
  f.kind = Kind::Vector;
  f.vector_size = size;
  return f;
}
/// One of `choices`, `def` by default.
inline Field choice(std::string name, std::vector<std::string> choices, std::string def, std::string doc) {
  Field f;
  f.name = std::move(name);
  f.kind = Kind::Choice;
  f.choices = std::move(choices);
  f.default_value = std::move(def);
  f.doc = std::move(doc);
  return f;
}
inline Field req(Field f) {
  f.required = true;
  return f;
}
inline Field def(Field f, json d) {
  f.default_value = std::move(d);
  return f;
}
inline Field bounded(Field f, double lo, double hi) {
  f.min = lo;
  f.max = hi;
  return f;
}
/// Strictly below `hi`.
inline Field below(Field f, double hi) {
  f.max = hi;
  f.max_exclusive = true;
  return f;
}
/// Also settable on the command line as `--<flag>`.
inline Field flag(Field f, std::string name) {
  f.flag = std::move(name);
  return f;
}
inline Field objects(std::string name, const ObjectSchema& o, std::string doc, size_t min_items = 0) {
  Field f;
  f.name = std::move(name);
  f.kind = Kind::ObjectArray;
  f.object = &o;
  f.doc = std::move(doc);
  f.min_items = min_items;
  f.required = min_items > 0;
  if (!f.required) f.default_value = json::array();
  return f;
}
inline Field object(std::string name, const ObjectSchema& o, std::string doc) {
  Field f;
  f.name = std::move(name);
  f.kind = Kind::Object;
  f.object = &o;
  f.doc = std::move(doc);
  f.default_value = json::object();
  return f;
}

/// The defaults of `section` as a validated object (every default filled in): what a typed configuration is read
/// from when nothing was given.
inline json defaults_of(const ObjectSchema& section) {
  json v = json::object();
  std::vector<Issue> issues;
  validate_object(v, section, "", 3, issues);
  return v;
}

}  // namespace rollsim::schema
