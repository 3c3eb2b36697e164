#include "ViewToolBar.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QStandardItemModel>
#include <algorithm>

#include "io/OutputFields.h"

namespace rollsim::ui {

ViewToolBar::ViewToolBar(MeshView* view, QWidget* parent) : QToolBar(tr("View"), parent), view_(view) {
  setObjectName(QStringLiteral("viewToolBar"));
  addWidget(new QLabel(tr(" Colour by ")));
  color_ = new QComboBox;
  color_->setObjectName(QStringLiteral("colorBy"));
  color_->addItem(tr("body"), color_by::Body);
  color_->addItem(tr("subdomain"), color_by::Subdomain);
  for (const OutputField& f : output_fields())  // the results the view can show, from the output registry
    if (f.colourable) color_->addItem(QString::fromStdString(f.label), QString::fromStdString(f.name));
  addWidget(color_);
  addSeparator();
  deformed_ = new QCheckBox(tr("deformed ×"));
  deformed_->setObjectName(QStringLiteral("deformed"));
  addWidget(deformed_);
  scale_ = new QDoubleSpinBox;
  scale_->setObjectName(QStringLiteral("deformationScale"));
  scale_->setDecimals(1);
  scale_->setRange(0, 1e9);
  scale_->setValue(1);
  addWidget(scale_);
  addSeparator();
  auto* increment_label = new QLabel(tr(" &increment "));
  increment_ = new QSpinBox;
  increment_->setObjectName(QStringLiteral("incrementSelector"));
  increment_->setAccessibleName(tr("load increment shown"));
  increment_->setToolTip(tr("load increment whose fields the view shows (Alt+I, then the arrow keys)"));
  increment_label->setBuddy(increment_);  // Alt+I focuses it; Up/Down/PageUp/PageDown step through increments
  increment_label_action_ = addWidget(increment_label);
  increment_action_ = addWidget(increment_);
  addAction(tr("Reset camera"), view_, &MeshView::reset_camera);

  connect(color_, QOverload<int>::of(&QComboBox::activated), this,
          [this](int i) { view_->set_color_by(color_->itemData(i).toString()); });
  connect(view_, &MeshView::colorByChanged, this, &ViewToolBar::refresh);
  auto apply = [this] { view_->set_deformation_scale(deformed_->isChecked() ? scale_->value() : 0.0); };
  connect(deformed_, &QCheckBox::toggled, this, apply);
  connect(scale_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, apply);
  connect(increment_, QOverload<int>::of(&QSpinBox::valueChanged), this,
          [this](int i) { view_->set_increment(i - 1); });
  connect(view_, &MeshView::incrementChanged, this, &ViewToolBar::refresh);
  refresh();
}

void ViewToolBar::refresh() {
  const bool results = view_->has_results();
  auto* items = qobject_cast<QStandardItemModel*>(color_->model());
  for (int i = 0; i < color_->count() && items; ++i)
    items->item(i)->setEnabled(view_->can_color_by(color_->itemData(i).toString()));
  for (int i = 0; i < color_->count(); ++i)
    if (color_->itemData(i).toString() == view_->color_by()) color_->setCurrentIndex(i);
  deformed_->setEnabled(results);
  scale_->setEnabled(results);
  {  // the view's deformation as the bar shows it (a process may open its results deformed ×1)
    const QSignalBlocker a(deformed_), b(scale_);
    deformed_->setChecked(results && view_->deformation_scale() > 0);
    if (view_->deformation_scale() > 0) scale_->setValue(view_->deformation_scale());
  }
  const int count = view_->increment_count();
  const QSignalBlocker quiet(increment_);  // showing the view's state is not a request to change it
  increment_->setRange(1, std::max(count, 1));
  increment_->setValue(view_->increment() < 0 ? count : view_->increment() + 1);
  increment_->setSuffix(tr(" of %1").arg(count));
  increment_label_action_->setVisible(count > 1);
  increment_action_->setVisible(count > 1);
}

}  // namespace rollsim::ui
