#include "LogPanel.h"

#include <QFontDatabase>
#include <QTime>

namespace rollsim::ui {

LogPanel::LogPanel(QWidget* parent) : QPlainTextEdit(parent) {
  setReadOnly(true);
  setMaximumBlockCount(5000);
  setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
}

void LogPanel::info(const QString& text) {
  appendPlainText(QTime::currentTime().toString(QStringLiteral("HH:mm:ss.zzz  ")) + text);
}

void LogPanel::error(const QString& text) {
  appendHtml(QStringLiteral("<span style=\"color:#b00000\">%1</span>")
                 .arg((QTime::currentTime().toString(QStringLiteral("HH:mm:ss.zzz  ")) + text)
                          .toHtmlEscaped()
                          .replace('\n', QStringLiteral("<br>"))));
}

}  // namespace rollsim::ui
