// `rollsim gui [PROJECT] [--screenshot FILE.png] [--size WxH] [--run] [--partitions] [--color-by FIELD]` and `rollsim`
// with no arguments:
// the window.
#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QImage>
#include <QRegularExpression>
#include <QSurfaceFormat>
#include <QTimer>
#include <QWindow>
#include <cstdlib>
#include <iostream>

#include "Commands.h"
#include "MainWindow.h"
#include "MeshView.h"
#include "Resources.h"

namespace rollsim::app {

namespace {

int invalid(const std::string& message) {
  std::cerr << "rollsim: error: " << message << "\n";
  return 2;
}

bool has_display() {
  for (const char* v : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
    if (const char* s = std::getenv(v); s && *s) return true;
  return false;
}

/// Lets the event loop run for `ms` milliseconds (queued signals, chart and view repaints).
void settle(int ms) {
  QEventLoop loop;
  QTimer::singleShot(ms, &loop, &QEventLoop::quit);
  loop.exec();
}

/// Shows the window, waits until it is on screen and rendered, grabs it and writes the PNG.
int screenshot(ui::MainWindow& w, const GuiOptions& o) {
  w.show();
  QElapsedTimer clock;
  clock.start();
  while (!(w.windowHandle() && w.windowHandle()->isExposed()) && clock.elapsed() < 10000) settle(20);
  if (o.run) {
    QEventLoop loop;
    QObject::connect(w.worker(), &ui::AnalysisWorker::finished, &loop, &QEventLoop::quit);
    if (w.start_run()) loop.exec();
    if (w.run_status() == QLatin1String("error")) std::cerr << "rollsim: warning: the run failed (see the log)\n";
  }
  if (o.partitions) w.show_partitions();
  if (!o.color_by.empty()) {
    const QString field = QString::fromStdString(o.color_by);
    if (!w.view()->can_color_by(field))
      std::cerr << "rollsim: warning: --color-by " << o.color_by << ": no such field in these results\n";
    w.view()->set_color_by(field);
  }
  settle(300);
  const QImage image = w.screenshot();
  if (image.isNull() || !image.save(QString::fromStdString(o.screenshot), "PNG")) {
    std::cerr << "rollsim: error: cannot write " << o.screenshot << "\n";
    return 1;
  }
  std::cout << o.screenshot << "\n";
  return 0;
}

}  // namespace

int gui_command(GuiOptions o) {
  int width = 1280, height = 800;
  if (!o.size.empty()) {
    const auto m = QRegularExpression(QStringLiteral("^(\\d{2,5})x(\\d{2,5})$")).match(QString::fromStdString(o.size));
    if (!m.hasMatch()) return invalid("--size: must be WxH, e.g. 1280x800, got " + o.size);
    width = m.captured(1).toInt();
    height = m.captured(2).toInt();
  }
  if (!has_display())
    return invalid(
        "the window needs a display: none found (DISPLAY is not set); run it under xvfb-run for "
        "--screenshot, or use the batch commands (rollsim --help)");
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(o.argc, o.argv);
  QApplication::setOrganizationName(QStringLiteral("rollsim"));
  QApplication::setApplicationName(QStringLiteral("rollsim"));
  ui::init_resources();
  ui::MainWindow w;
  w.resize(width, height);
  if (o.project.empty()) {
    w.new_project();
  } else {
    QString error;
    if (!w.open_file(QString::fromStdString(o.project), &error)) return invalid(error.toStdString());
  }
  if (!o.screenshot.empty()) return screenshot(w, o);
  w.show();
  if (o.partitions) w.show_partitions();
  if (o.run) w.start_run();
  return QApplication::exec();
}

}  // namespace rollsim::app
