#pragma once
// The partition being designed in the window: one body's element -> subdomain map, changed by undoable steps
// (paint strokes, box selections, structured and METIS fills) on a QUndoStack, and written to the project as that
// body's `partition_map` (for the generated slab of a rolling process: `process.slab_partition_map`). The view
// and the partition table redraw from mapChanged(); the document is written shortly after the last step (a stroke
// of many small steps is one write), or at once by flush().
#include <QObject>
#include <QString>
#include <QTimer>
#include <QUndoStack>
#include <memory>
#include <string>
#include <vector>

#include "model/Model.h"

namespace rollsim::ui {

class ProjectDocument;

class PartitionEditor : public QObject {
  Q_OBJECT

 public:
  explicit PartitionEditor(ProjectDocument* document, QObject* parent = nullptr);

  QUndoStack* undo_stack() { return &undo_; }
  /// Bodies whose partition can be designed (named as in the model), and the one being edited (-1: none).
  QStringList bodies() const;
  int body() const { return body_; }
  std::shared_ptr<const Model> model() const { return model_; }
  void set_body(int model_body);
  /// The map of the edited body: one subdomain id per element.
  const std::vector<int>& map() const { return map_; }
  int subdomain_count() const;
  /// The subdomain new strokes paint into.
  int current_subdomain() const { return current_; }
  void set_current_subdomain(int id);

  /// One painting step (undoable): `elements` of the edited body take the current subdomain. Steps with the same
  /// `stroke` id (> 0) merge into one undo step. Returns false when nothing changed.
  bool paint(const std::vector<int>& elements, int stroke = 0);
  /// Replaces the map by a structured ("4x2", "2x2x1") or METIS ("metis:8") partition of the body (undoable);
  /// returns the error message, empty on success.
  QString fill(const QString& spec);
  /// Writes a pending map change to the document now (before Save or Run); returns the refusal, empty if accepted.
  QString flush();
  /// A new stroke id for paint().
  int next_stroke() { return ++stroke_; }

 signals:
  /// The map changed (a step, an undo or redo, another body, a new model).
  void mapChanged();
  /// The document refused the map (message of the validation).
  void refused(const QString& message);

 private:
  friend class MapCommand;
  void apply(const std::vector<int>& elements, const std::vector<int>& ids);
  void model_changed();
  void load_from_model();
  std::pair<std::string, std::string> pointers() const;  // {map pointer, spec pointer} of the edited body

  ProjectDocument* doc_;
  QUndoStack undo_;
  QTimer write_timer_;
  std::shared_ptr<const Model> model_;
  int body_ = -1;
  std::vector<int> map_;
  int current_ = 0;
  int stroke_ = 0;
  bool dirty_ = false;
};

}  // namespace rollsim::ui
