#pragma once
// The project as a tree: the project itself, then one node per section of the schema (materials, bodies,
// boundary conditions, contacts, solver, probes, output) with its entries. Selecting a node shows its object in
// the property editor. Refreshed from the ProjectDocument on every change.
#include <QTreeWidget>
#include <string>

#include "ProjectDocument.h"

namespace rollsim::ui {

class ProjectTreePanel : public QTreeWidget {
  Q_OBJECT

 public:
  explicit ProjectTreePanel(ProjectDocument* document, QWidget* parent = nullptr);
  /// Selects the node of a JSON pointer if it exists.
  void select(const std::string& pointer);
  std::string selected_pointer() const;

 signals:
  /// The JSON pointer of the selected object ("" for the project).
  void objectSelected(const QString& pointer);

 private:
  void refresh();

  ProjectDocument* doc_;
};

}  // namespace rollsim::ui
