#pragma once
// The project schema seen from the property editor: which fields an object at a JSON pointer has, how a value
// reads as text, and how edited text becomes a value. Nothing is re-declared: fields come from project_schema().
#include <QString>
#include <string>
#include <vector>

#include "base/Schema.h"

namespace rollsim::ui {

/// The fields of `value` under `schema`: the discriminator first (as a choice of the variant names), then the
/// common fields, then those of the selected variant.
std::vector<Field> fields_of(const ObjectSchema& schema, const json& value);

/// The schema of the object at a JSON pointer of validated project data ("" is the project, "/bodies/0",
/// "/bodies/0/mesh", "/solver"); null when the pointer does not name an object of the schema.
const ObjectSchema* object_schema_at(const json& data, const std::string& pointer);

/// "/bodies/0/mesh/nx" -> "bodies[0].mesh.nx", the path validation messages (Issue::path) use.
std::string issue_path(const std::string& pointer);

/// A value as the editor shows it: numbers as JSON, strings bare, vectors as "x, y, z"; null as "".
QString value_text(const json& value);

/// Edited text to the value proposed for `field`: "" is null (remove: back to the default); text that does not
/// read as the field's type is proposed as a string, so that validation names what was typed.
json parse_value_text(const Field& field, const QString& text);

/// One line of help: doc, unit, range, default.
QString field_help(const Field& field);

}  // namespace rollsim::ui
