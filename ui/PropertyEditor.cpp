#include "PropertyEditor.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLineEdit>
#include <QVBoxLayout>

#include "SchemaFields.h"
#include "solve/SolverStrategy.h"

namespace rollsim::ui {

namespace {

const char* kRefusedStyle = "background-color: #ffd6d6;";

QString label_text(const Field& f) {
  QString s = QString::fromStdString(f.name);
  if (!f.unit.empty() && f.unit != "-") s += QStringLiteral(" [%1]").arg(QString::fromStdString(f.unit));
  return s;
}

/// A description of a choice when the schema's choices are the solver registry's names.
QString choice_description(const std::string& choice) {
  for (const StrategyInfo& s : solver_registry())
    if (s.name == choice) return QString::fromStdString(s.description);
  return {};
}

QString join(const std::vector<Issue>& issues) {
  QStringList lines;
  for (const Issue& i : issues) lines << QString::fromStdString(i.str());
  return lines.join('\n');
}

json lookup(const json& root, const std::string& pointer) {
  const json::json_pointer p(pointer);
  return root.contains(p) ? root.at(p) : json();
}

}  // namespace

PropertyEditor::PropertyEditor(ProjectDocument* document, QWidget* parent) : QWidget(parent), doc_(document) {
  layout_ = new QVBoxLayout(this);
  title_ = new QLabel(this);
  title_->setStyleSheet(QStringLiteral("font-weight: bold;"));
  message_ = new QLabel(this);
  message_->setObjectName(QStringLiteral("validationMessage"));
  message_->setWordWrap(true);
  message_->setStyleSheet(QStringLiteral("color: #b00000;"));
  message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout_->addWidget(title_);
  layout_->addWidget(message_);
  layout_->addStretch(1);
  connect(doc_, &ProjectDocument::changed, this, &PropertyEditor::refresh);
  connect(doc_, &ProjectDocument::buildRefused, this, [this](const QString& m) {
    message_->setText(m);
    emit refused(m);
  });
}

void PropertyEditor::set_object(const std::string& pointer) {
  pointer_ = pointer;
  message_->clear();
  rebuild();
}

QWidget* PropertyEditor::editor_for(const std::string& pointer) const {
  for (const Row& r : rows_)
    if (r.pointer == pointer) return r.editor;
  return nullptr;
}

json PropertyEditor::user_value(const std::string& pointer) const {
  const Document::json_pointer p(pointer);
  const Document& d = doc_->document();
  return d.contains(p) ? json::parse(d.at(p).dump()) : json();
}

json PropertyEditor::effective_value(const std::string& pointer) const { return lookup(doc_->project().data, pointer); }

// The rows depend on the variant chosen (mesh type, condition type) and on which objects exist.
std::vector<std::string> PropertyEditor::layout_signature() const {
  std::vector<std::string> sig;
  std::vector<std::string> todo{pointer_};
  const json& pd = doc_->project().data;
  while (!todo.empty()) {
    const std::string p = todo.back();
    todo.pop_back();
    const ObjectSchema* schema = object_schema_at(pd, p);
    if (!schema) {
      sig.push_back(p + "!");
      continue;
    }
    for (const Field& f : fields_of(*schema, lookup(pd, p))) {
      sig.push_back(p + "/" + f.name);
      if (f.kind == Kind::Object && !p.empty()) todo.push_back(p + "/" + f.name);
    }
  }
  return sig;
}

void PropertyEditor::rebuild() {
  if (form_host_) form_host_->deleteLater();
  rows_.clear();
  form_host_ = new QWidget(this);
  auto* form = new QFormLayout(form_host_);
  form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  const json& pd = doc_->project().data;
  const ObjectSchema* schema = object_schema_at(pd, pointer_);
  const std::string where = issue_path(pointer_);
  title_->setText(
      schema ? QString::fromStdString(schema->name + (where.empty() || where == schema->name ? "" : "  " + where))
             : tr("(nothing selected)"));
  title_->setToolTip(schema ? QString::fromStdString(schema->doc) : QString());
  if (schema) add_rows(form, *schema, lookup(pd, pointer_), pointer_);
  layout_->insertWidget(1, form_host_);
  signature_ = layout_signature();
  for (const Row& r : rows_) show_value(r);
}

void PropertyEditor::add_rows(QFormLayout* form, const ObjectSchema& schema, const json& value,
                              const std::string& pointer) {
  for (const Field& f : fields_of(schema, value)) {
    const std::string p = pointer + "/" + f.name;
    auto* label = new QLabel(label_text(f));
    label->setToolTip(field_help(f));
    if (f.kind == Kind::Object && pointer.empty()) {  // sections of the project have their own tree node
      auto* note = new QLabel(tr("(in the project tree)"));
      note->setEnabled(false);
      form->addRow(label, note);
      continue;
    }
    if (f.kind == Kind::Object) {
      auto* box = new QGroupBox(QString::fromStdString(f.name));
      box->setToolTip(field_help(f));
      auto* inner = new QFormLayout(box);
      inner->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
      const ObjectSchema* nested = object_schema_at(doc_->project().data, p);
      if (nested) add_rows(inner, *nested, lookup(doc_->project().data, p), p);
      form->addRow(box);
      delete label;
      continue;
    }
    if (f.kind == Kind::ObjectArray) {
      const json v = lookup(doc_->project().data, p);
      auto* note =
          new QLabel(tr("%n entries (in the project tree)", "", v.is_array() ? static_cast<int>(v.size()) : 0));
      note->setEnabled(false);
      form->addRow(label, note);
      continue;
    }
    QWidget* editor = make_editor(f, p);
    editor->setToolTip(field_help(f));
    auto* cell = new QWidget;  // the field and, under it, its refused value's message
    auto* column = new QVBoxLayout(cell);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(2);
    auto* note = new QLabel;
    note->setWordWrap(true);
    note->setStyleSheet(QStringLiteral("color: #b00000;"));
    note->setTextInteractionFlags(Qt::TextSelectableByMouse);
    note->hide();
    column->addWidget(editor);
    column->addWidget(note);
    form->addRow(label, cell);
    rows_.push_back({p, f, editor, note});
  }
}

QWidget* PropertyEditor::make_editor(const Field& f, const std::string& p) {
  QWidget* editor = nullptr;
  if (f.kind == Kind::Choice) {
    auto* combo = new QComboBox;
    if (!f.required) combo->addItem(tr("(default)"), QVariant());
    for (const auto& c : f.choices) {
      combo->addItem(QString::fromStdString(c), QString::fromStdString(c));
      combo->setItemData(combo->count() - 1, choice_description(c), Qt::ToolTipRole);
    }
    for (int c : f.int_choices) combo->addItem(QString::number(c), c);
    connect(combo, QOverload<int>::of(&QComboBox::activated), this, [this, combo, f, p](int index) {
      const QVariant v = combo->itemData(index);
      json value;
      if (v.isValid()) value = f.int_choices.empty() ? json(v.toString().toStdString()) : json(v.toInt());
      commit(p, value, combo);
    });
    editor = combo;
  } else if (f.kind == Kind::Boolean) {
    auto* check = new QCheckBox;
    connect(check, &QCheckBox::clicked, this, [this, check, p](bool on) { commit(p, on, check); });
    editor = check;
  } else {
    auto* line = new QLineEdit;
    connect(line, &QLineEdit::textEdited, this,
            [this, line, f, p](const QString& text) { commit(p, parse_value_text(f, text), line); });
    editor = line;
  }
  editor->setObjectName(QString::fromStdString(p));
  return editor;
}

QString PropertyEditor::message_for(const std::string& pointer) const {
  for (const Row& r : rows_)
    if (r.pointer == pointer) return r.note->isHidden() ? QString() : r.note->text();
  return {};
}

void PropertyEditor::show_value(const Row& r) {
  const json user = user_value(r.pointer), effective = effective_value(r.pointer);
  r.editor->setStyleSheet(QString());
  const ProjectDocument::RefusedEdit* refused = doc_->refused_edit(r.pointer);
  show_note(r);
  auto* line = qobject_cast<QLineEdit*>(r.editor);
  if (refused && line) {  // what the user typed stays, refused, until it is corrected
    line->setText(refused->text);
    line->setStyleSheet(QString::fromLatin1(kRefusedStyle));
  } else if (line) {
    line->setText(value_text(user));
    line->setPlaceholderText(value_text(effective.is_null() ? r.field.default_value : effective));
  } else if (auto* combo = qobject_cast<QComboBox*>(r.editor)) {
    const json v = user.is_null() ? effective : user;
    int index = user.is_null() && !r.field.required ? 0 : -1;
    if (index < 0)
      for (int i = 0; i < combo->count(); ++i) {
        const QVariant d = combo->itemData(i);
        if (d.isValid() && ((v.is_string() && d.toString().toStdString() == v.get<std::string>()) ||
                            (v.is_number_integer() && d.toInt() == v.get<int>())))
          index = i;
      }
    combo->setCurrentIndex(index);
    if (!user.is_null() || r.field.required) combo->setToolTip(combo->itemData(index, Qt::ToolTipRole).toString());
    if (!r.field.required && combo->count() > 0)
      combo->setItemText(0, tr("(default: %1)").arg(value_text(r.field.default_value)));
  } else if (auto* check = qobject_cast<QCheckBox*>(r.editor)) {
    const json v = user.is_null() ? effective : user;
    check->setChecked(v.is_boolean() && v.get<bool>());
  }
}

void PropertyEditor::commit(const std::string& pointer, const json& value, QWidget* editor) {
  editing_ = pointer;
  const std::vector<Issue> issues = doc_->propose(pointer, Document::parse(value.dump()));
  editing_.clear();
  auto* line = qobject_cast<QLineEdit*>(editor);
  if (issues.empty()) {
    editor->setStyleSheet(QString());
    message_->clear();
    doc_->withdraw_refused_edit(pointer);
    for (const Row& r : rows_)
      if (r.pointer == pointer) show_note(r);
    emit accepted(QString::fromStdString(pointer));
    return;
  }
  editor->setStyleSheet(QString::fromLatin1(kRefusedStyle));
  message_->setText(join(issues));
  if (line) doc_->refuse_edit(pointer, line->text(), message_->text());  // a choice is never a value not typed
  for (const Row& r : rows_)
    if (r.pointer == pointer) show_note(r);
  emit refused(message_->text());
}

void PropertyEditor::show_note(const Row& r) {
  const ProjectDocument::RefusedEdit* refused = doc_->refused_edit(r.pointer);
  r.note->setText(refused ? refused->message : QString());
  r.note->setVisible(refused != nullptr);
}

void PropertyEditor::refresh() {
  if (layout_signature() != signature_) {
    rebuild();
    return;
  }
  for (const Row& r : rows_)
    if (r.pointer != editing_) show_value(r);
}

}  // namespace rollsim::ui
