#include "SchemaFields.h"

#include "project/ProjectSchema.h"

#include <QRegularExpression>
#include <QStringList>
#include <cmath>

namespace rollsim::ui {

std::vector<Field> fields_of(const ObjectSchema& schema, const json& value) {
  std::vector<Field> out;
  const ObjectSchema* variant = nullptr;
  if (!schema.discriminator.empty()) {
    Field d;
    d.name = schema.discriminator;
    d.kind = Kind::Choice;
    d.required = true;
    d.doc = schema.doc;
    for (const auto& [name, v] : schema.variants) d.choices.push_back(name);
    out.push_back(d);
    const auto it = value.find(schema.discriminator);
    if (it != value.end() && it->is_string() && schema.variants.count(it->get<std::string>()))
      variant = schema.variants.at(it->get<std::string>());
  }
  for (const Field& f : schema.fields) out.push_back(f);
  if (variant)
    for (const Field& f : variant->fields) out.push_back(f);
  return out;
}

const ObjectSchema* object_schema_at(const json& data, const std::string& pointer) {
  const ObjectSchema* schema = &project_schema();
  const json* value = &data;
  const json::json_pointer ptr(pointer);
  std::vector<std::string> tokens;
  for (json::json_pointer p = ptr; !p.empty(); p = p.parent_pointer()) tokens.insert(tokens.begin(), p.back());
  for (size_t i = 0; i < tokens.size(); ++i) {
    const Field* field = nullptr;
    const std::vector<Field> fields = fields_of(*schema, *value);
    for (const Field& f : fields)
      if (f.name == tokens[i]) field = &f;
    if (!field || !field->object || !value->contains(tokens[i])) return nullptr;
    value = &(*value)[tokens[i]];
    const ObjectSchema* next = field->object;
    if (field->kind == Kind::ObjectArray) {
      if (i + 1 >= tokens.size()) return nullptr;  // the array itself is not an object
      const std::string& index = tokens[++i];
      if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos) return nullptr;
      const size_t k = std::stoul(index);
      if (!value->is_array() || k >= value->size()) return nullptr;
      value = &(*value)[k];
    }
    if (!value->is_object()) return nullptr;
    schema = next;
  }
  return schema;
}

std::string issue_path(const std::string& pointer) {
  std::string out;
  size_t pos = 0;
  while (pos < pointer.size()) {
    const size_t next = pointer.find('/', pos + 1);
    const std::string token = pointer.substr(pos + 1, next == std::string::npos ? std::string::npos : next - pos - 1);
    const bool index = !token.empty() && token.find_first_not_of("0123456789") == std::string::npos;
    out += index ? "[" + token + "]" : (out.empty() ? "" : ".") + token;
    pos = next == std::string::npos ? pointer.size() : next;
  }
  return out;
}

QString value_text(const json& value) {
  if (value.is_null()) return {};
  if (value.is_string()) return QString::fromStdString(value.get<std::string>());
  if (value.is_array()) {
    QStringList parts;
    for (const json& v : value) parts << value_text(v);
    return parts.join(QStringLiteral(", "));
  }
  return QString::fromStdString(value.dump());
}

namespace {

/// A JSON number from text, or null.
json number(const QString& text) {
  bool ok = false;
  const qlonglong i = text.toLongLong(&ok);
  if (ok) return static_cast<long long>(i);
  const double d = text.toDouble(&ok);
  if (ok) return d;
  return nullptr;
}

}  // namespace

json parse_value_text(const Field& field, const QString& raw) {
  const QString text = raw.trimmed();
  if (text.isEmpty()) return nullptr;
  switch (field.kind) {
    case Kind::Integer:
    case Kind::Number: {
      json n = number(text);
      return n.is_null() ? json(text.toStdString()) : n;
    }
    case Kind::Boolean:
      if (text == QLatin1String("true")) return true;
      if (text == QLatin1String("false")) return false;
      return text.toStdString();
    case Kind::Choice:
      if (!field.int_choices.empty()) {
        json n = number(text);
        return n.is_null() ? json(text.toStdString()) : n;
      }
      return text.toStdString();
    case Kind::ChoiceList: {  // "displacement, plastic_strain" (or with brackets) → an array of the names
      QString inner = text;
      if (inner.startsWith('[') && inner.endsWith(']')) inner = inner.mid(1, inner.size() - 2);
      json out = json::array();
      for (const QString& part : inner.split(QRegularExpression(QStringLiteral("[,;\\s\"]+")), Qt::SkipEmptyParts))
        out.push_back(part.toStdString());
      return out;
    }
    case Kind::Vector: {
      QString inner = text;
      if (inner.startsWith('[') && inner.endsWith(']')) inner = inner.mid(1, inner.size() - 2);
      json out = json::array();
      for (const QString& part : inner.split(QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts)) {
        json n = number(part);
        if (n.is_null()) return text.toStdString();
        out.push_back(n);
      }
      return out;
    }
    default:
      return text.toStdString();
  }
}

QString field_help(const Field& f) {
  QString s = QString::fromStdString(f.doc);
  if (!f.unit.empty() && f.unit != "-") s += QStringLiteral(" [%1]").arg(QString::fromStdString(f.unit));
  if (f.min || f.max) {
    const QString lo = f.min ? QString::number(*f.min) + (f.min_exclusive ? " <" : " ≤") : QString();
    const QString hi = f.max ? QString(f.max_exclusive ? "< " : "≤ ") + QString::number(*f.max) : QString();
    s += QStringLiteral("; range: %1 value %2").arg(lo, hi).simplified();
  }
  if (f.required)
    s += QStringLiteral("; required");
  else if (!f.default_value.is_null() && !f.default_value.is_object() && !f.default_value.is_array())
    s += QStringLiteral("; default: %1").arg(value_text(f.default_value));
  return s;
}

}  // namespace rollsim::ui
