#pragma once
// A schema field bound to the member of a typed options struct that it fills: one declaration gives the field's
// name, range, unit and documentation (validation, docs/project-format.md, the window, the command line's flags),
// its default — the member's initializer in S, so it is written once — and how the validated value is read into S.
// A new option is its member and one bind(...) line in the struct's table.
#include <functional>
#include <type_traits>
#include <vector>

#include "base/Schema.h"
#include "base/Words.h"

namespace rollsim {

template <class S>
struct BoundField {
  Field field;
  std::function<void(const json&, S&)> read;  // from the validated section's value of `field`
  std::function<json(const S&)> write;        // the value in the project's words (summary.json's echo)
};

/// `f` with the default of `member` and its reader: a number, an integer, a flag or a string; an enum becomes a
/// choice among words<E>().
template <class S, class T>
BoundField<S> bind(Field f, T S::*member) {
  const S defaults{};
  if constexpr (std::is_enum_v<T>) {
    f.kind = Kind::Choice;
    f.choices = words<T>();
    f.default_value = word(defaults.*member);
    return {std::move(f), [member](const json& v, S& s) { s.*member = from_word<T>(v.get<std::string>()); },
            [member](const S& s) { return json(word(s.*member)); }};
  } else {
    f.default_value = defaults.*member;
    return {std::move(f), [member](const json& v, S& s) { s.*member = v.get<T>(); },
            [member](const S& s) { return json(s.*member); }};
  }
}

/// The fields of a table, for a schema section.
template <class S>
std::vector<Field> fields_of(const std::vector<BoundField<S>>& table) {
  std::vector<Field> fields;
  for (const BoundField<S>& b : table) fields.push_back(b.field);
  return fields;
}

/// S read from a validated section (validation filled the defaults; a field declared without one — its default a
/// rule the reader applies, e.g. solver.cg_tolerance's — keeps the member's initializer when absent).
template <class S>
S read_bound(const std::vector<BoundField<S>>& table, const json& section) {
  S s{};
  for (const BoundField<S>& b : table) {
    if (!section.contains(b.field.name) && b.field.default_value.is_null()) continue;
    b.read(section.at(b.field.name), s);
  }
  return s;
}

/// `b` without a default filled in by validation: absent, the reader applies its rule (see read_bound).
template <class S>
BoundField<S> without_default(BoundField<S> b) {
  b.field.default_value = nullptr;
  return b;
}

}  // namespace rollsim
