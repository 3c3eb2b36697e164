#pragma once
// The window's compiled-in resources (resources/rollsim.qrc).
#include <QString>

namespace rollsim::ui {

/// Registers the resources of the static rollsim_ui library (call once, after QApplication exists).
void init_resources();

/// The project the window opens with when given none (samples/rolling-2d-36x6.json, embedded as
/// :/rollsim/default-project.json).
QString default_project_text();

}  // namespace rollsim::ui
