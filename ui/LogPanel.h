#pragma once
// The window's log: stage messages of runs, refused edits, file operations, each with the time of day.
#include <QPlainTextEdit>

namespace rollsim::ui {

class LogPanel : public QPlainTextEdit {
  Q_OBJECT

 public:
  explicit LogPanel(QWidget* parent = nullptr);

 public slots:
  void info(const QString& text);
  void error(const QString& text);
};

}  // namespace rollsim::ui
