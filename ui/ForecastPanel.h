#pragma once
// What a run of the project will be, before it runs: its process's facts in the process's own terms (a pass: the
// reduction, bite angle, contact length, whether the roll bites, the closed forms' force and torque, the speed) and
// the forecast of its cost (dofs, increments, Newton iterations, predicted time). Refreshed from the document with
// every model it builds.
#include <QWidget>

class QLabel;
class QTableWidget;

namespace rollsim::ui {

class ProjectDocument;

class ForecastPanel : public QWidget {
  Q_OBJECT

 public:
  explicit ForecastPanel(ProjectDocument* document, QWidget* parent = nullptr);

  /// The forecast's one line ("2,273 dofs, 50 increments, …: about 12 s").
  QString headline() const;
  /// The facts as shown: one row per fact (name, value, how it follows).
  QTableWidget* facts() const { return table_; }

 private:
  void refresh();

  ProjectDocument* doc_;
  QLabel* headline_;
  QTableWidget* table_;
};

}  // namespace rollsim::ui
