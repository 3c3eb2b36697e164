#include "OffscreenQt.h"

#include <QApplication>
#include <cstdio>

namespace rollsim::ui {

OffscreenQt::OffscreenQt() {
  if (QApplication::instance()) return;
  qputenv("QT_QPA_PLATFORM", "offscreen");
  previous_ = qInstallMessageHandler([](QtMsgType type, const QMessageLogContext&, const QString& msg) {
    if (type == QtCriticalMsg || type == QtFatalMsg) std::fprintf(stderr, "rollsim: Qt: %s\n", qPrintable(msg));
  });
  static int argc = 1;
  static char name[] = "rollsim";
  static char* argv[] = {name, nullptr};
  own_ = std::make_unique<QApplication>(argc, argv);
}

OffscreenQt::~OffscreenQt() {
  if (!own_) return;
  own_.reset();
  qInstallMessageHandler(previous_);
}

}  // namespace rollsim::ui
