#pragma once
// What the view shows: colour by body / subdomain / displacement / von Mises, deformed shape and its scale, camera
// reset. Result colourings are enabled once a run has produced results.
#include <QToolBar>

#include "MeshView.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;

namespace rollsim::ui {

class ViewToolBar : public QToolBar {
  Q_OBJECT

 public:
  explicit ViewToolBar(MeshView* view, QWidget* parent = nullptr);

  /// Re-reads the view's state (after new results or a new mesh).
  void refresh();
  QComboBox* color_combo() const { return color_; }

 private:
  MeshView* view_;
  QComboBox* color_;
  QCheckBox* deformed_;
  QDoubleSpinBox* scale_;
};

}  // namespace rollsim::ui
