#include "Resources.h"

#include <QFile>

// Q_INIT_RESOURCE must be used outside any namespace.
static void init_rollsim_resources() { Q_INIT_RESOURCE(rollsim); }

namespace rollsim::ui {

void init_resources() { init_rollsim_resources(); }

QString default_project_text() {
  init_resources();
  QFile f(QStringLiteral(":/rollsim/default-project.json"));
  if (!f.open(QIODevice::ReadOnly)) return {};
  return QString::fromUtf8(f.readAll());
}

}  // namespace rollsim::ui
