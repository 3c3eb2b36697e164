#pragma once
// What the view shows: colour by body / subdomain / displacement / von Mises, deformed shape and its scale, the load
// increment whose fields are shown (after a run of more than one increment), camera reset. Result colourings are
// enabled once a run has produced results.
#include <QToolBar>

#include "MeshView.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace rollsim::ui {

class ViewToolBar : public QToolBar {
  Q_OBJECT

 public:
  explicit ViewToolBar(MeshView* view, QWidget* parent = nullptr);

  /// Re-reads the view's state (after new results or a new mesh).
  void refresh();
  QComboBox* color_combo() const { return color_; }
  /// The increment selector (1 … N), shown only for results of more than one increment.
  QSpinBox* increment_selector() const { return increment_; }

 private:
  MeshView* view_;
  QComboBox* color_;
  QCheckBox* deformed_;
  QDoubleSpinBox* scale_;
  QSpinBox* increment_;
  QAction* increment_label_action_;
  QAction* increment_action_;
};

}  // namespace rollsim::ui
