#pragma once
// One parameter schema (name, type, range, default, unit, doc) that drives project validation, the generated
// docs/project-format.md, the GUI's property editor and the command line's flags. Each layer declares the section it
// reads (solve/SolverSchema, analysis/NewtonSchema, process/…): defaults are written there and nowhere else.
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rollsim {

using json = nlohmann::json;

enum class Kind {
  Integer,  // whole number within [min, max]
  Number,   // finite real within [min, max]
  String,   // non-empty string
  Boolean,
  Choice,       // one of `choices` (strings), or of `int_choices`
  ChoiceList,   // array of at least `min_items` distinct strings, each one of `choices`
  Vector,       // array of `dimension` finite numbers (a point or direction)
  Object,       // nested object described by `object`
  ObjectArray,  // array of objects described by `object`
};

struct ObjectSchema;

struct Field {
  std::string name;
  Kind kind = Kind::Number;
  bool required = false;
  json default_value = nullptr;  // filled in when absent (null: no default)
  std::optional<double> min, max;
  bool min_exclusive = false, max_exclusive = false;
  std::string unit;  // "length", "force", "stress", "-", ...
  std::string doc;
  std::vector<std::string> choices;
  std::vector<int> int_choices;
  const ObjectSchema* object = nullptr;
  int vector_size = 0;  // 0: the model dimension; -1: any length
  size_t min_items = 0;
  std::string flag;  // `rollsim run --<flag>` sets this field (empty: only `--set path=value`)
  // a check beyond the kind's (a value of the right kind): the problem, or "" (e.g. `selective:2` of solver.update)
  std::function<std::string(const json&)> check;
};

/// An object type. If `discriminator` is set, the value of that field selects one of `variants`,
/// whose fields are added to the common ones.
struct ObjectSchema {
  std::string name;
  std::string doc;
  std::vector<Field> fields;
  std::string discriminator;
  std::map<std::string, const ObjectSchema*> variants;
  std::string default_variant = {};  // the discriminator's value when absent (empty: it is required)
};

/// One problem found in a project: the JSON path (e.g. "bodies[1].mesh.nx") and the reason.
struct Issue {
  std::string path;
  std::string message;
  std::string str() const { return path.empty() ? message : path + ": " + message; }
};

/// The field at a dotted path below `root` ("solver.cg_tolerance", "bodies[0].partition"), following objects and
/// arrays of objects (not a discriminator's variants); null when there is none.
const Field* find_field(const ObjectSchema& root, const std::string& path);

/// Every field of `root` (recursively) that has a command-line flag, with its dotted path.
std::vector<std::pair<std::string, const Field*>> flagged_fields(const ObjectSchema& root);

/// Checks `value` against `schema` (recursively) and fills defaults; appends problems to `issues`.
void validate_object(json& value, const ObjectSchema& schema, const std::string& path, int dimension,
                     std::vector<Issue>& issues);

/// Markdown reference of a schema and all object types it reaches.
std::string schema_markdown(const ObjectSchema& root);

/// Short human description of a JSON value for messages: `-3`, `"abc"`, `an array`.
std::string describe(const json& v);

}  // namespace rollsim
