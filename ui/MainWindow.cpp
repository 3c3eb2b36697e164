#include "MainWindow.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QSaveFile>
#include <QScrollArea>
#include <QSettings>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>

#include "ForecastPanel.h"
#include "LogPanel.h"
#include "MeshView.h"
#include "PartitionEditor.h"
#include "PartitionPanel.h"
#include "ProjectDocument.h"
#include "ProjectTreePanel.h"
#include "PropertyEditor.h"
#include "RunPanel.h"
#include "RunPlots.h"
#include "ViewToolBar.h"
#include "io/AtomicFile.h"

namespace rollsim::ui {

namespace {
constexpr int kMaxRecent = 8;
const char* kRecentKey = "recentFiles";
const char* kProjectFilter = "rollsim projects (*.json);;All files (*)";
}  // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), doc_(new ProjectDocument(this)), worker_(new AnalysisWorker(this)) {
  setObjectName(QStringLiteral("rollsimMainWindow"));
  view_ = new MeshView(this);
  view_->setMinimumSize(320, 240);
  setCentralWidget(view_);
  view_bar_ = new ViewToolBar(view_, this);
  addToolBar(Qt::TopToolBarArea, view_bar_);

  tree_ = new ProjectTreePanel(doc_);
  editor_ = new PropertyEditor(doc_);
  auto* left = new QSplitter(Qt::Vertical);
  left->addWidget(tree_);
  left->addWidget(editor_);
  left->setSizes({220, 480});
  auto* project_dock = new QDockWidget(tr("Project"), this);
  project_dock->setObjectName(QStringLiteral("projectDock"));
  project_dock->setWidget(left);
  addDockWidget(Qt::LeftDockWidgetArea, project_dock);

  run_panel_ = new RunPanel(doc_);
  auto* run_dock = new QDockWidget(tr("Solver and run"), this);
  run_dock->setObjectName(QStringLiteral("runDock"));
  auto* run_scroll = new QScrollArea;  // the solver's schema rows grow with the strategies; the window does not
  run_scroll->setWidgetResizable(true);
  run_scroll->setFrameShape(QFrame::NoFrame);
  run_scroll->setWidget(run_panel_);
  run_dock->setWidget(run_scroll);
  addDockWidget(Qt::RightDockWidgetArea, run_dock);

  partition_ = new PartitionEditor(doc_, this);
  partition_panel_ = new PartitionPanel(partition_, view_);
  auto* partition_dock = new QDockWidget(tr("Partitions"), this);
  partition_dock->setObjectName(QStringLiteral("partitionDock"));
  partition_dock->setWidget(partition_panel_);
  addDockWidget(Qt::RightDockWidgetArea, partition_dock);
  tabifyDockWidget(run_dock, partition_dock);
  run_dock->raise();

  plot_ = new RunPlots;
  log_ = new LogPanel;
  auto* tabs = new QTabWidget;
  tabs->setObjectName(QStringLiteral("bottomTabs"));
  forecast_ = new ForecastPanel(doc_);
  tabs->addTab(forecast_, tr("Forecast"));
  tabs->addTab(plot_, tr("Convergence"));
  tabs->addTab(log_, tr("Log"));
  auto* bottom_dock = new QDockWidget(tr("Residuals and log"), this);
  bottom_dock->setObjectName(QStringLiteral("bottomDock"));
  bottom_dock->setWidget(tabs);
  addDockWidget(Qt::BottomDockWidgetArea, bottom_dock);
  resizeDocks({project_dock, run_dock}, {300, 260}, Qt::Horizontal);
  resizeDocks({bottom_dock}, {250}, Qt::Vertical);

  counts_ = new QLabel;
  counts_->setObjectName(QStringLiteral("modelCounts"));
  status_ = new QLabel(run_status_);
  status_->setObjectName(QStringLiteral("runStatusBar"));
  statusBar()->addPermanentWidget(counts_);
  statusBar()->addPermanentWidget(status_);

  build_menus();

  connect(tree_, &ProjectTreePanel::objectSelected, this,
          [this](const QString& p) { editor_->set_object(p.toStdString()); });
  connect(editor_, &PropertyEditor::refused, log_, &LogPanel::error);
  connect(run_panel_->solver_editor(), &PropertyEditor::refused, log_, &LogPanel::error);
  connect(editor_, &PropertyEditor::refused, this, [this](const QString& m) { statusBar()->showMessage(m, 8000); });
  connect(doc_, &ProjectDocument::modelChanged, this, &MainWindow::model_changed);
  connect(doc_, &ProjectDocument::fileStateChanged, this, &MainWindow::refresh_title);
  connect(doc_, &ProjectDocument::refusedEditsChanged, this, &MainWindow::refresh_actions);

  connect(run_panel_, &RunPanel::runRequested, this, &MainWindow::start_run);
  connect(run_panel_, &RunPanel::cancelRequested, this, &MainWindow::cancel_run);
  connect(worker_, &AnalysisWorker::stageStarted, this, [this](const QString& stage) {
    log_->info(tr("stage: %1").arg(stage));
    statusBar()->showMessage(stage);
  });
  plot_->watch(worker_);
  connect(worker_, &AnalysisWorker::howFar, run_panel_, &RunPanel::set_progress_text);
  connect(worker_, &AnalysisWorker::tangentsChosen, this, [this](int increment, int iteration, const QString& choices) {
    log_->info(tr("increment %1, iteration %2: %3").arg(increment).arg(iteration).arg(choices));
  });
  connect(worker_, &AnalysisWorker::cutBack, this, [this](int increment, const QString& cause) {
    log_->info(tr("increment %1 cut back (step halved): %2").arg(increment).arg(cause));
  });
  connect(worker_, &AnalysisWorker::progress, run_panel_, &RunPanel::set_progress);
  connect(worker_, &AnalysisWorker::finished, this, &MainWindow::run_finished);

  refresh_recent_menu();
  resize(1280, 800);
}

MainWindow::~MainWindow() { worker_->cancel(); }

void MainWindow::build_menus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(
      tr("&New"), this,
      [this] {
        if (maybe_save()) new_project();
      },
      QKeySequence::New);
  file->addAction(tr("&Open..."), this, &MainWindow::open_dialog, QKeySequence::Open);
  recent_menu_ = file->addMenu(tr("Open &Recent"));
  write_actions_.push_back(file->addAction(tr("&Save"), this, &MainWindow::save, QKeySequence::Save));
  write_actions_.push_back(file->addAction(tr("Save &As..."), this, &MainWindow::save_as_dialog, QKeySequence::SaveAs));
  file->addSeparator();
  file->addAction(tr("Export &VTU..."), this, &MainWindow::export_vtu);
  file->addAction(tr("Export run increments as PV&D..."), this, &MainWindow::export_pvd);
  file->addAction(tr("Export &PNG screenshot..."), this, &MainWindow::export_png);
  file->addAction(tr("Export plotted series as &CSV..."), this, &MainWindow::export_csv);
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);
  QMenu* edit = menuBar()->addMenu(tr("&Edit"));  // undo/redo of partition painting steps
  QAction* undo = partition_->undo_stack()->createUndoAction(this, tr("&Undo"));
  undo->setShortcut(QKeySequence::Undo);
  edit->addAction(undo);
  QAction* redo = partition_->undo_stack()->createRedoAction(this, tr("&Redo"));
  redo->setShortcut(QKeySequence::Redo);
  edit->addAction(redo);
  QMenu* run = menuBar()->addMenu(tr("&Run"));
  write_actions_.push_back(run->addAction(tr("&Run"), this, &MainWindow::start_run, QKeySequence(Qt::Key_F5)));
  run->addAction(tr("&Cancel"), this, &MainWindow::cancel_run, QKeySequence(Qt::Key_Escape));
  QMenu* view = menuBar()->addMenu(tr("&View"));
  view->addAction(tr("&Reset camera"), view_, &MeshView::reset_camera, QKeySequence(Qt::Key_R));
  for (QDockWidget* dock : findChildren<QDockWidget*>()) view->addAction(dock->toggleViewAction());
}

bool MainWindow::open_file(const QString& file, QString* error) {
  try {
    doc_->open(file);
  } catch (const std::exception& e) {
    const QString message = QString::fromUtf8(e.what());
    log_->error(message);
    if (error) *error = message;
    return false;
  }
  log_->info(tr("opened %1").arg(file));
  add_recent(QFileInfo(file).absoluteFilePath());
  tree_->select("");
  return true;
}

void MainWindow::new_project() {
  doc_->load_default();
  log_->info(tr("new project from the default (the paper's rolling pass)"));
  tree_->select("");
}

void MainWindow::open_dialog() {
  if (!maybe_save()) return;
  const QString file = QFileDialog::getOpenFileName(this, tr("Open project"), QString(), tr(kProjectFilter));
  if (file.isEmpty()) return;
  QString error;
  if (!open_file(file, &error)) QMessageBox::warning(this, tr("Invalid project"), error);
}

bool MainWindow::refused_while_invalid(const QString& action) {
  const QString why = doc_->refused_edits();
  if (why.isEmpty()) return false;
  const QString m = tr("%1 refused: a field holds a value that is not valid (correct it, or clear it for the "
                       "default) — %2")
                        .arg(action, why);
  log_->error(m);
  statusBar()->showMessage(m, 8000);
  return true;
}

void MainWindow::refresh_actions() {
  const QString why = doc_->refused_edits();
  for (QAction* a : write_actions_) {
    a->setEnabled(why.isEmpty());
    a->setStatusTip(why);
  }
}

bool MainWindow::save() {
  if (refused_while_invalid(tr("Save"))) return false;
  if (doc_->file().isEmpty()) return save_as_dialog();
  return save_to(doc_->file());
}

bool MainWindow::save_to(const QString& file) {
  partition_->flush();  // a stroke still waiting to be written joins the file
  try {
    doc_->save_as(file);
  } catch (const std::exception& e) {
    log_->error(tr("cannot save %1: %2").arg(file, QString::fromUtf8(e.what())));
    return false;
  }
  log_->info(tr("saved %1").arg(file));
  add_recent(QFileInfo(file).absoluteFilePath());
  return true;
}

bool MainWindow::save_as_dialog() {
  if (refused_while_invalid(tr("Save"))) return false;
  const QString file = QFileDialog::getSaveFileName(this, tr("Save project"), doc_->file(), tr(kProjectFilter));
  return !file.isEmpty() && save_to(file);
}

bool MainWindow::maybe_save() {
  if (!doc_->modified()) return true;
  const auto answer = QMessageBox::question(this, tr("Unsaved changes"),
                                            tr("%1 has unsaved changes. Save them?").arg(doc_->display_name()),
                                            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
  if (answer == QMessageBox::Save) return save();
  return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (maybe_save()) {
    worker_->cancel();
    event->accept();
  } else {
    event->ignore();
  }
}

void MainWindow::add_recent(const QString& file) {
  QSettings settings;
  QStringList files = settings.value(kRecentKey).toStringList();
  files.removeAll(file);
  files.prepend(file);
  while (files.size() > kMaxRecent) files.removeLast();
  settings.setValue(kRecentKey, files);
  refresh_recent_menu();
}

void MainWindow::refresh_recent_menu() {
  recent_menu_->clear();
  const QStringList files = QSettings().value(kRecentKey).toStringList();
  for (const QString& f : files)
    recent_menu_->addAction(f, this, [this, f] {
      if (!maybe_save()) return;
      QString error;
      if (!open_file(f, &error)) QMessageBox::warning(this, tr("Invalid project"), error);
    });
  recent_menu_->setEnabled(!files.isEmpty());
}

void MainWindow::refresh_title() {
  setWindowTitle(QStringLiteral("%1[*] — rollsim").arg(doc_->display_name()));
  setWindowModified(doc_->modified());
}

QString MainWindow::counts_text() const { return counts_->text(); }

QString MainWindow::run_status() const { return run_status_; }

void MainWindow::model_changed() {
  const ModelCounts c = doc_->counts();
  const QLocale l = QLocale::c();
  counts_->setText(tr("nodes %1 · elements %2 · dofs %3")
                       .arg(l.toString(static_cast<qlonglong>(c.nodes)), l.toString(static_cast<qlonglong>(c.elements)),
                            l.toString(static_cast<qlonglong>(c.dofs))));
  view_->set_model(doc_->model());
  view_bar_->refresh();
  for (const std::string& w : doc_->model()->warnings) log_->info(tr("warning: %1").arg(QString::fromStdString(w)));
}

bool MainWindow::start_run() {
  if (worker_->running() || refused_while_invalid(tr("Run"))) return false;
  partition_->flush();
  plot_->clear();
  show_bottom(plot_);
  log_->info(tr("run %1 with solver %2")
                 .arg(QString::fromStdString(doc_->project().name()),
                      QString::fromStdString(doc_->project().data.at("solver").at("mode").get<std::string>())));
  if (!worker_->start(doc_->project(), nlohmann::json::parse(doc_->document().dump()))) return false;
  run_status_ = QStringLiteral("running");
  status_->setText(run_status_);
  run_panel_->set_status(run_status_);
  run_panel_->set_running(true);
  return true;
}

void MainWindow::cancel_run() {
  if (!worker_->running()) return;
  worker_->cancel();
  log_->info(tr("cancel requested: the run stops at the next safe point"));
}

void MainWindow::run_finished(const RunOutcome& o) {
  plot_->flush();
  run_status_ = o.status;
  status_->setText(o.status);
  run_panel_->set_running(false);
  const bool failed = o.status != QLatin1String("converged") && o.status != QLatin1String("cancelled");
  if (failed) {
    run_panel_->set_status(o.status);
    log_->error(tr("run %1: %2").arg(o.status, o.message));
    statusBar()->showMessage(o.message, 15000);
    return;
  }
  run_panel_->set_status(tr("%1 — %2 dofs, %3 CG iterations, %4 s")
                             .arg(o.status)
                             .arg(o.dofs)
                             .arg(o.cg_iterations)
                             .arg(o.seconds, 0, 'f', 3));
  statusBar()->showMessage(tr("run %1 in %2 s").arg(o.status).arg(o.seconds, 0, 'f', 3));  // not the last stage
  if (!o.message.isEmpty()) log_->info(tr("run %1: %2").arg(o.status, o.message));         // ended early by its process
  log_->info(tr("run %1: %2 dofs, %3 CG iterations, %4 s")
                 .arg(o.status)
                 .arg(o.dofs)
                 .arg(o.cg_iterations)
                 .arg(o.seconds, 0, 'f', 3));
  if (o.results && o.model) {
    view_->set_results(o.model, o.results);
    show_results_view();
  }
}

void MainWindow::show_results_view() {
  if (view_->has_results()) {
    // a process says how its results read first (a rolling pass: deformed, by plastic strain, on the roll gap)
    const ProcessResults* process =
        view_->results() && view_->results()->process ? &*view_->results()->process : nullptr;
    const bool own = process && view_->can_color_by(QString::fromStdString(process->view.field));
    view_->set_color_by(own ? QString::fromStdString(process->view.field) : color_by::Displacement);
    view_->set_deformation_scale(process && process->view.deformed ? 1.0 : 0.0);
    if (process && process->view.box) view_->frame(*process->view.box);
  }
  view_bar_->refresh();
  plot_->flush();
  show_bottom(plot_);
}

void MainWindow::show_bottom(QWidget* tab) {
  if (auto* tabs = findChild<QTabWidget*>(QStringLiteral("bottomTabs"))) tabs->setCurrentWidget(tab);
}

void MainWindow::show_partitions() {
  if (auto* dock = findChild<QDockWidget*>(QStringLiteral("partitionDock"))) dock->raise();
  view_->set_partition(partition_->body(), partition_->map());
  view_bar_->refresh();
}

QImage MainWindow::screenshot() {
  view_->render_now();
  return grab().toImage();
}

void MainWindow::export_vtu() {
  const QString file =
      QFileDialog::getSaveFileName(this, tr("Export VTU"), QString(), tr("VTK unstructured grid (*.vtu)"));
  if (file.isEmpty()) return;
  try {
    view_->export_vtu(file.toStdString());
    log_->info(tr("exported %1").arg(file));
  } catch (const std::exception& e) {
    log_->error(tr("cannot export %1: %2").arg(file, QString::fromUtf8(e.what())));
  }
}

void MainWindow::export_pvd() {
  const QString file = QFileDialog::getSaveFileName(this, tr("Export run increments"), QString(),
                                                    tr("ParaView collection, one VTU per increment (*.pvd)"));
  if (file.isEmpty()) return;
  try {
    view_->export_pvd(file.toStdString());
    log_->info(tr("exported %1").arg(file));
  } catch (const std::exception& e) {
    log_->error(tr("cannot export %1: %2").arg(file, QString::fromUtf8(e.what())));
  }
}

void MainWindow::export_png() {
  const QString file = QFileDialog::getSaveFileName(this, tr("Export screenshot"), QString(), tr("PNG image (*.png)"));
  if (file.isEmpty()) return;
  if (screenshot().save(file, "PNG"))
    log_->info(tr("saved %1").arg(file));
  else
    log_->error(tr("cannot write %1").arg(file));
}

void MainWindow::export_csv() {
  const QString file = QFileDialog::getSaveFileName(this, tr("Export plotted series"), QString(), tr("CSV (*.csv)"));
  if (file.isEmpty()) return;
  try {
    write_file_atomically(file.toStdString(), plot_->csv().toStdString());
    log_->info(tr("exported %1").arg(file));
  } catch (const std::exception& e) {
    log_->error(tr("cannot export %1: %2").arg(file, QString::fromUtf8(e.what())));
  }
}

}  // namespace rollsim::ui
