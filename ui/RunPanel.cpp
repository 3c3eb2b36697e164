#include "RunPanel.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

#include "PropertyEditor.h"
#include "solve/SolverStrategy.h"

namespace rollsim::ui {

RunPanel::RunPanel(ProjectDocument* document, QWidget* parent) : QWidget(parent), doc_(document) {
  auto* layout = new QVBoxLayout(this);
  editor_ = new PropertyEditor(doc_, this);
  editor_->set_object("/solver");
  description_ = new QLabel(this);
  description_->setWordWrap(true);
  description_->setStyleSheet(QStringLiteral("color: #404040;"));
  run_ = new QPushButton(tr("Run"), this);
  run_->setObjectName(QStringLiteral("runButton"));
  run_->setToolTip(tr("Solve the project in the background (F5)"));
  cancel_ = new QPushButton(tr("Cancel"), this);
  cancel_->setObjectName(QStringLiteral("cancelButton"));
  cancel_->setToolTip(tr("Stop at the next safe point (Esc)"));
  cancel_->setEnabled(false);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(run_);
  buttons->addWidget(cancel_);
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 1000);
  progress_->setValue(0);
  progress_->setTextVisible(false);
  status_ = new QLabel(tr("not run"), this);
  status_->setObjectName(QStringLiteral("runStatus"));
  layout->addWidget(editor_);
  layout->addWidget(description_);
  layout->addLayout(buttons);
  layout->addWidget(progress_);
  layout->addWidget(status_);
  layout->addStretch(1);
  connect(run_, &QPushButton::clicked, this, &RunPanel::runRequested);
  connect(cancel_, &QPushButton::clicked, this, &RunPanel::cancelRequested);
  connect(doc_, &ProjectDocument::changed, this, &RunPanel::refresh_description);
  connect(doc_, &ProjectDocument::refusedEditsChanged, this, &RunPanel::refresh_run_button);
  refresh_description();
}

void RunPanel::refresh_run_button() {
  const QString why = doc_->refused_edits();
  run_->setEnabled(!running_ && why.isEmpty());
  run_->setToolTip(why.isEmpty() ? tr("Solve the project in the background (F5)")
                                 : tr("Not while a field holds a refused value: %1").arg(why));
}

void RunPanel::refresh_description() {
  const json& pd = doc_->project().data;
  const std::string mode = pd.contains("solver") ? pd["solver"].value("mode", std::string()) : std::string();
  for (const StrategyInfo& s : solver_registry())
    if (s.name == mode) description_->setText(QString::fromStdString(s.name + ": " + s.description));
  if (mode == kAutoSolver)
    description_->setText(
        QStringLiteral("auto: direct, mixed or feti, whichever the partition table's cost model "
                       "predicts cheapest; the run's log names the choice"));
}

QString RunPanel::status() const { return status_->text(); }

void RunPanel::set_running(bool running) {
  running_ = running;
  refresh_run_button();
  cancel_->setEnabled(running);
  if (!running) return;
  progress_->setValue(0);
  progress_->setTextVisible(false);
  progress_->setFormat(QString());
}

void RunPanel::set_progress_text(const QString& text) {
  progress_->setFormat(text);
  progress_->setTextVisible(true);
}

QString RunPanel::progress_text() const { return progress_->isTextVisible() ? progress_->text() : QString(); }

void RunPanel::set_progress(double fraction) { progress_->setValue(static_cast<int>(1000 * fraction)); }

void RunPanel::set_status(const QString& status) { status_->setText(status); }

}  // namespace rollsim::ui
