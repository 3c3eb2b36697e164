#pragma once
// The solver and run controls: the project's `solver` section as a schema-driven form (mode from the strategy
// registry, CG tolerance, threads, and whatever fields the schema gains), the selected strategy's description,
// Run / Cancel, a progress bar and the run status.
#include <QWidget>

#include "ProjectDocument.h"

class QLabel;
class QProgressBar;
class QPushButton;

namespace rollsim::ui {

class PropertyEditor;

class RunPanel : public QWidget {
  Q_OBJECT

 public:
  explicit RunPanel(ProjectDocument* document, QWidget* parent = nullptr);

  PropertyEditor* solver_editor() const { return editor_; }
  QPushButton* run_button() const { return run_; }
  QPushButton* cancel_button() const { return cancel_; }
  QString status() const;
  /// The progress bar's text ("" until an increment starts).
  QString progress_text() const;

 public slots:
  void set_running(bool running);
  void set_progress(double fraction);
  /// Shows how far the run is on the progress bar (AnalysisWorker::howFar).
  void set_progress_text(const QString& text);
  void set_status(const QString& status);

 signals:
  void runRequested();
  void cancelRequested();

 private:
  void refresh_description();
  /// Run enabled while no run is going and no field holds a refused value (its message as the button's tooltip).
  void refresh_run_button();

  ProjectDocument* doc_;
  PropertyEditor* editor_;
  QLabel* description_;
  QPushButton* run_;
  QPushButton* cancel_;
  QProgressBar* progress_;
  QLabel* status_;
  bool running_ = false;
};

}  // namespace rollsim::ui
