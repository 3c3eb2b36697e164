#pragma once
// Edits one object of the project (a body, a material, the solver section, ...) as a form generated from the
// declared schema. Every keystroke is proposed to the ProjectDocument, which validates it as `rollsim run` would;
// a refused value stays in its field, red, with the validator's message under it, and is recorded as the document's
// refused edit (which blocks Save and Run) while the project keeps its old value.
#include <QLabel>
#include <QWidget>
#include <string>
#include <vector>

#include "ProjectDocument.h"
#include "base/Schema.h"

class QFormLayout;
class QVBoxLayout;

namespace rollsim::ui {

class PropertyEditor : public QWidget {
  Q_OBJECT

 public:
  explicit PropertyEditor(ProjectDocument* document, QWidget* parent = nullptr);

  /// Shows the object at a JSON pointer of the project ("" is the project itself, "/solver", "/bodies/0").
  void set_object(const std::string& pointer);
  const std::string& object_pointer() const { return pointer_; }
  /// The editor widget of the field at a JSON pointer (QLineEdit, QComboBox or QCheckBox), or null. Its
  /// objectName is the pointer.
  QWidget* editor_for(const std::string& pointer) const;
  /// The message of the last refused value ("" after an accepted one).
  QString message() const { return message_->text(); }
  /// The message shown under the field at a JSON pointer ("" when its value is not refused).
  QString message_for(const std::string& pointer) const;

 signals:
  void refused(const QString& message);
  void accepted(const QString& pointer);

 private:
  struct Row {
    std::string pointer;
    Field field;
    QWidget* editor = nullptr;
    QLabel* note = nullptr;  // the refused value's message, under the field
  };
  void rebuild();
  void refresh();
  std::vector<std::string> layout_signature() const;
  void add_rows(QFormLayout* form, const ObjectSchema& schema, const json& value, const std::string& pointer);
  QWidget* make_editor(const Field& field, const std::string& pointer);
  void commit(const std::string& pointer, const json& value, QWidget* editor);
  void show_value(const Row& row);
  /// The field's note from the document's refused edit (shown under it, or hidden when there is none).
  void show_note(const Row& row);
  json user_value(const std::string& pointer) const;
  json effective_value(const std::string& pointer) const;

  ProjectDocument* doc_;
  std::string pointer_;
  std::vector<Row> rows_;
  std::vector<std::string> signature_;
  std::string editing_;  // pointer being proposed: its editor keeps what the user typed
  QLabel* title_;
  QWidget* form_host_ = nullptr;
  QVBoxLayout* layout_;
  QLabel* message_;
};

}  // namespace rollsim::ui
