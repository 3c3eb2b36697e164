#include "base/Schema.h"

#include <cmath>
#include <set>
#include <sstream>

namespace rollsim {

std::string describe(const json& v) {
  switch (v.type()) {
    case json::value_t::null:
      return "null";
    case json::value_t::boolean:
      return v.get<bool>() ? "true" : "false";
    case json::value_t::string: {
      std::string s = v.get<std::string>();
      if (s.size() > 40) s = s.substr(0, 40) + "...";
      return "\"" + s + "\"";
    }
    case json::value_t::array:
      return "an array of " + std::to_string(v.size());
    case json::value_t::object:
      return "an object";
    default:
      return v.dump();
  }
}

namespace {

std::string range_text(const Field& f) {
  std::ostringstream s;
  auto num = [](double x) {
    std::ostringstream o;
    o << x;
    return o.str();
  };
  if (f.min && f.max)
    s << "in " << (f.min_exclusive ? "(" : "[") << num(*f.min) << ", " << num(*f.max) << (f.max_exclusive ? ")" : "]");
  else if (f.min)
    s << (f.min_exclusive ? "> " : ">= ") << num(*f.min);
  else if (f.max)
    s << (f.max_exclusive ? "< " : "<= ") << num(*f.max);
  return s.str();
}

bool in_range(const Field& f, double x) {
  if (f.min && (f.min_exclusive ? !(x > *f.min) : !(x >= *f.min))) return false;
  if (f.max && (f.max_exclusive ? !(x < *f.max) : !(x <= *f.max))) return false;
  return true;
}

std::string expectation(const Field& f) {
  std::string r = range_text(f);
  switch (f.kind) {
    case Kind::Integer:
      if (f.min && *f.min == 1) return "must be a positive integer";
      return "must be an integer" + (r.empty() ? "" : " " + r);
    case Kind::Number:
      return "must be a finite number" + (r.empty() ? "" : " " + r);
    case Kind::String:
      return "must be a non-empty string";
    case Kind::Boolean:
      return "must be true or false";
    default:
      return "";
  }
}

void check_scalar(json& v, const Field& f, const std::string& path, std::vector<Issue>& out) {
  const auto got = ", got " + describe(v);
  switch (f.kind) {
    case Kind::Integer: {
      const bool integral = v.is_number_integer() ||
                            (v.is_number_float() && std::isfinite(v.get<double>()) &&
                             std::floor(v.get<double>()) == v.get<double>() && std::fabs(v.get<double>()) < 9e15);
      if (!integral || (f.min && v.get<double>() < *f.min)) {
        out.push_back({path, expectation(f) + got});
      } else if (f.max && v.get<double>() > *f.max) {
        std::ostringstream m;
        m << "must be at most " << *f.max << got;
        out.push_back({path, m.str()});
      } else {
        v = v.get<long long>();
      }
      return;
    }
    case Kind::Number:
      if (!v.is_number() || !std::isfinite(v.get<double>()) || !in_range(f, v.get<double>()))
        out.push_back({path, expectation(f) + got});
      return;
    case Kind::String:
      if (!v.is_string() || v.get<std::string>().empty()) out.push_back({path, expectation(f) + got});
      return;
    case Kind::Boolean:
      if (!v.is_boolean()) out.push_back({path, expectation(f) + got});
      return;
    default:
      return;
  }
}

void check_choice(const json& v, const Field& f, const std::string& path, std::vector<Issue>& out) {
  std::string list;
  if (!f.int_choices.empty()) {
    for (int c : f.int_choices) {
      if (v.is_number_integer() && v.get<long long>() == c) return;
      list += (list.empty() ? "" : ", ") + std::to_string(c);
    }
  } else {
    for (const auto& c : f.choices) {
      if (v.is_string() && v.get<std::string>() == c) return;
      list += (list.empty() ? "" : ", ") + c;
    }
  }
  out.push_back({path, "must be one of " + list + ", got " + describe(v)});
}

void check_choice_list(const json& v, const Field& f, const std::string& path, std::vector<Issue>& out) {
  std::string list;
  for (const auto& c : f.choices) list += (list.empty() ? "" : ", ") + c;
  if (!v.is_array() || v.size() < f.min_items) {
    out.push_back({path, "must be an array of " +
                             (f.min_items > 0 ? "at least " + std::to_string(f.min_items) + " " : "") + "of: " + list +
                             "; got " + describe(v)});
    return;
  }
  std::set<std::string> seen;
  for (size_t i = 0; i < v.size(); ++i) {
    const std::string p = path + "[" + std::to_string(i) + "]";
    check_choice(v[i], f, p, out);
    if (v[i].is_string() && !seen.insert(v[i].get<std::string>()).second)
      out.push_back({p, "names " + describe(v[i]) + " a second time"});
  }
}

void check_vector(const json& v, const Field& f, const std::string& path, int dim, std::vector<Issue>& out) {
  const bool any = f.vector_size < 0;
  const size_t n = any ? (v.is_array() ? v.size() : 0) : f.vector_size ? f.vector_size : static_cast<size_t>(dim);
  bool ok = v.is_array() && v.size() == n;
  if (ok)
    for (const auto& x : v) ok = ok && x.is_number() && std::isfinite(x.get<double>()) && in_range(f, x.get<double>());
  if (!ok) {
    std::string r = range_text(f);
    out.push_back({path, "must be an array of " + (any ? std::string("") : std::to_string(n) + " ") + "finite numbers" +
                             (r.empty() ? "" : " " + r) + ", got " +
                             (v.is_array() ? "[" + v.dump().substr(1, 60) : describe(v))});
  }
}

void check_field(json& v, const Field& f, const std::string& path, int dim, std::vector<Issue>& out) {
  switch (f.kind) {
    case Kind::Choice:
      check_choice(v, f, path, out);
      return;
    case Kind::ChoiceList:
      check_choice_list(v, f, path, out);
      return;
    case Kind::Vector:
      check_vector(v, f, path, dim, out);
      return;
    case Kind::Object:
      validate_object(v, *f.object, path, dim, out);
      return;
    case Kind::ObjectArray:
      if (!v.is_array()) {
        out.push_back({path, "must be an array of " + f.object->name + " objects, got " + describe(v)});
        return;
      }
      if (v.size() < f.min_items) out.push_back({path, "needs at least " + std::to_string(f.min_items) + " entries"});
      for (size_t i = 0; i < v.size(); ++i)
        validate_object(v[i], *f.object, path + "[" + std::to_string(i) + "]", dim, out);
      return;
    default: {
      const size_t before = out.size();
      check_scalar(v, f, path, out);
      if (out.size() == before && f.check)
        if (std::string problem = f.check(v); !problem.empty()) out.push_back({path, problem});
    }
  }
}

std::string join_names(const std::vector<const Field*>& fields) {
  std::string s;
  for (const Field* f : fields) s += (s.empty() ? "" : ", ") + f->name;
  return s;
}

}  // namespace

const Field* find_field(const ObjectSchema& root, const std::string& path) {
  const ObjectSchema* object = &root;
  const Field* field = nullptr;
  size_t at = 0;
  while (at <= path.size()) {
    if (!object) return nullptr;
    size_t end = path.find('.', at);
    if (end == std::string::npos) end = path.size();
    std::string name = path.substr(at, end - at);
    if (const auto bracket = name.find('['); bracket != std::string::npos) name.resize(bracket);  // an array's item
    field = nullptr;
    for (const Field& f : object->fields)
      if (f.name == name) field = &f;
    if (!field) return nullptr;
    object = field->object;
    at = end + 1;
  }
  return field;
}

namespace {
void collect_flags(const ObjectSchema& object, const std::string& path,
                   std::vector<std::pair<std::string, const Field*>>& out) {
  for (const Field& f : object.fields) {
    const std::string p = path.empty() ? f.name : path + "." + f.name;
    if (!f.flag.empty()) out.emplace_back(p, &f);
    if (f.kind == Kind::Object && f.object) collect_flags(*f.object, p, out);
  }
}
}  // namespace

std::vector<std::pair<std::string, const Field*>> flagged_fields(const ObjectSchema& root) {
  std::vector<std::pair<std::string, const Field*>> out;
  collect_flags(root, "", out);
  return out;
}

void validate_object(json& value, const ObjectSchema& schema, const std::string& path, int dim,
                     std::vector<Issue>& out) {
  if (!value.is_object()) {
    out.push_back({path, "must be a " + schema.name + " object, got " + describe(value)});
    return;
  }
  std::vector<const Field*> fields;
  for (const Field& f : schema.fields) fields.push_back(&f);
  if (!schema.discriminator.empty()) {
    if (!schema.default_variant.empty() && !value.contains(schema.discriminator))
      value[schema.discriminator] = schema.default_variant;
    const auto it = value.find(schema.discriminator);
    const std::string p = path + (path.empty() ? "" : ".") + schema.discriminator;
    std::string names;
    for (const auto& [k, _] : schema.variants) names += (names.empty() ? "" : ", ") + k;
    if (it == value.end() || !it->is_string() || !schema.variants.count(it->get<std::string>())) {
      out.push_back({p, "must be one of " + names + (it == value.end() ? " (missing)" : ", got " + describe(*it))});
      return;
    }
    for (const Field& f : schema.variants.at(it->get<std::string>())->fields) fields.push_back(&f);
  }
  std::set<std::string> known{schema.discriminator};
  for (const Field* f : fields) known.insert(f->name);
  for (const auto& [key, _] : value.items())
    if (!known.count(key))
      out.push_back({path + (path.empty() ? "" : ".") + key, "unknown field (allowed: " + join_names(fields) + ")"});
  for (const Field* f : fields) {
    const std::string p = path + (path.empty() ? "" : ".") + f->name;
    auto it = value.find(f->name);
    if (it == value.end()) {
      if (f->required)
        out.push_back({p, "is required (" + f->doc + ")"});
      else if (!f->default_value.is_null()) {
        value[f->name] = f->default_value;
        if (f->kind == Kind::Object) validate_object(value[f->name], *f->object, p, dim, out);  // nested defaults
      }
      continue;
    }
    check_field(*it, *f, p, dim, out);
  }
}

namespace {

std::string anchor(const std::string& title) {
  std::string a;
  for (char c : title) a += c == ' ' ? '-' : c;
  return "[" + title + "](#" + a + ")";
}

std::string type_text(const Field& f) {
  switch (f.kind) {
    case Kind::Integer:
      return "integer";
    case Kind::Number:
      return "number";
    case Kind::String:
      return "string";
    case Kind::Boolean:
      return "boolean";
    case Kind::Choice: {
      std::string s;
      for (const auto& c : f.choices) s += (s.empty() ? "" : " \\| ") + ("`" + c + "`");
      for (int c : f.int_choices) s += (s.empty() ? "" : " \\| ") + ("`" + std::to_string(c) + "`");
      return s;
    }
    case Kind::ChoiceList: {
      std::string s;
      for (const auto& c : f.choices) s += (s.empty() ? "" : " \\| ") + ("`" + c + "`");
      return "array of " + s;
    }
    case Kind::Vector:
      return f.vector_size < 0 ? "array of numbers"
             : f.vector_size   ? "array of " + std::to_string(f.vector_size) + " numbers"
                               : "array of `dimension` numbers";
    case Kind::Object:
      return anchor(f.object->name);
    case Kind::ObjectArray:
      return "array of " + anchor(f.object->name);
  }
  return "";
}

void field_rows(std::ostringstream& s, const std::vector<Field>& fields) {
  for (const Field& f : fields) {
    std::string def = f.required ? "required" : f.default_value.is_null() ? "optional" : f.default_value.dump();
    s << "| `" << f.name << "` | " << type_text(f) << " | " << def << " | " << range_text(f) << " | "
      << (f.unit.empty() ? "" : f.unit) << " | " << f.doc
      << (f.flag.empty() ? "" : " (command line: `--" + f.flag + "`)") << " |\n";
  }
}

void collect(const ObjectSchema& o, std::vector<const ObjectSchema*>& seen) {
  for (const ObjectSchema* s : seen)
    if (s == &o) return;
  seen.push_back(&o);
  for (const Field& f : o.fields)
    if (f.object) collect(*f.object, seen);
  for (const auto& [_, v] : o.variants)
    for (const Field& f : v->fields)
      if (f.object) collect(*f.object, seen);
}

}  // namespace

std::string schema_markdown(const ObjectSchema& root) {
  std::vector<const ObjectSchema*> all;
  collect(root, all);
  std::ostringstream s;
  const char* header = "| field | type | default | range | unit | meaning |\n|---|---|---|---|---|---|\n";
  for (const ObjectSchema* o : all) {
    s << "## " << o->name << "\n\n" << o->doc;
    if (!o->default_variant.empty()) s << " Without `" << o->discriminator << "`: `" << o->default_variant << "`.";
    s << "\n\n" << header;
    field_rows(s, o->fields);
    for (const auto& [name, v] : o->variants) {
      s << "\n### " << o->name << " with `" << o->discriminator << "`: `" << name << "`\n\n" << v->doc << "\n\n";
      if (!v->fields.empty()) s << header;
      field_rows(s, v->fields);
    }
    s << "\n";
  }
  return s.str();
}

}  // namespace rollsim
