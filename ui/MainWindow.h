#pragma once
// The rollsim window: project tree and property editor (left), the mesh/results view (centre), solver and run
// controls (right), residual plot and log (bottom), counts and run status in the status bar. It wires the
// ProjectDocument, the AnalysisWorker and the widgets; each widget refreshes itself from the document.
#include <QMainWindow>
#include <QStringList>
#include <vector>

#include "AnalysisWorker.h"

class QAction;
class QLabel;
class QMenu;

namespace rollsim::ui {

class ForecastPanel;
class LogPanel;
class MeshView;
class PartitionEditor;
class PartitionPanel;
class ProjectDocument;
class ProjectTreePanel;
class PropertyEditor;
class RunPlots;
class RunPanel;
class ViewToolBar;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  /// Opens a project file; on an invalid project returns false with the validator's message in `error` (the
  /// window keeps its current project).
  bool open_file(const QString& file, QString* error = nullptr);
  /// The default project (samples/rolling-2d-36x6.json, embedded as :/rollsim/default-project.json), untitled.
  void new_project();
  /// Save / Save As; false when cancelled or failed (the message is logged) or while a field holds a refused value.
  bool save();
  bool save_to(const QString& file);
  /// Starts a run of the current project in the worker thread; false if one is running or a field holds a refused
  /// value.
  bool start_run();
  void cancel_run();
  /// Colours the view and shows the residual plot exactly as after an interactive run (for --screenshot).
  void show_results_view();
  /// Raises the partition panel and colours the view by the edited body's subdomains.
  void show_partitions();
  /// The whole window as an image (QWidget::grab, the 3D view included).
  QImage screenshot();

  ProjectDocument* document() const { return doc_; }
  MeshView* view() const { return view_; }
  RunPlots* plot() const { return plot_; }
  AnalysisWorker* worker() const { return worker_; }
  ProjectTreePanel* tree() const { return tree_; }
  PartitionEditor* partition_editor() const { return partition_; }
  PartitionPanel* partition_panel() const { return partition_panel_; }
  PropertyEditor* property_editor() const { return editor_; }
  RunPanel* run_panel() const { return run_panel_; }
  LogPanel* log() const { return log_; }
  ForecastPanel* forecast() const { return forecast_; }
  /// "nodes 1,234 · elements 1,100 · dofs 2,300" as shown in the status bar.
  QString counts_text() const;
  /// The last run's status: "not run", "running", "converged", "cancelled", "error", ...
  QString run_status() const;

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void build_menus();
  void open_dialog();
  bool save_as_dialog();
  bool maybe_save();
  /// True (the refusal logged and shown in the status bar) while a field holds a value validation refused: `action`
  /// would otherwise write or solve the document's last accepted value, which the user did not type.
  bool refused_while_invalid(const QString& action);
  /// Save, Save As and Run enabled only while no field holds a refused value.
  void refresh_actions();
  void export_vtu();
  void export_pvd();
  void export_png();
  void export_csv();
  void add_recent(const QString& file);
  void refresh_recent_menu();
  void refresh_title();
  void model_changed();
  /// Raises a tab of the bottom dock: the forecast before a run, the convergence plots from its start.
  void show_bottom(QWidget* tab);
  void run_finished(const RunOutcome& outcome);

  ProjectDocument* doc_;
  AnalysisWorker* worker_;
  MeshView* view_;
  ViewToolBar* view_bar_;
  ProjectTreePanel* tree_;
  PropertyEditor* editor_;
  RunPanel* run_panel_;
  PartitionEditor* partition_;
  PartitionPanel* partition_panel_;
  RunPlots* plot_;
  LogPanel* log_;
  ForecastPanel* forecast_;
  QLabel* counts_;
  QLabel* status_;
  QMenu* recent_menu_ = nullptr;
  std::vector<QAction*> write_actions_;  // Save, Save As, Run: refused while a field holds a refused value
  QString run_status_ = QStringLiteral("not run");
};

}  // namespace rollsim::ui
