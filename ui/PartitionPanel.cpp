#include "PartitionPanel.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QShortcut>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

#include "MeshView.h"
#include "PartitionEditor.h"
#include "PartitionTable.h"

namespace rollsim::ui {

PartitionPanel::PartitionPanel(PartitionEditor* editor, MeshView* view, QWidget* parent)
    : QWidget(parent), editor_(editor), view_(view) {
  body_ = new QComboBox;
  body_->setObjectName(QStringLiteral("partitionBody"));
  subdomain_ = new QSpinBox;
  subdomain_->setObjectName(QStringLiteral("paintSubdomain"));
  subdomain_->setRange(0, 999);
  subdomain_->setToolTip(tr("the subdomain strokes paint into (keys 0-9)"));
  swatch_ = new QLabel;
  swatch_->setFixedSize(22, 22);
  radius_ = new QSpinBox;
  radius_->setRange(1, 200);
  radius_->setValue(view_->brush_radius());
  radius_->setSuffix(tr(" px"));
  radius_->setToolTip(tr("brush radius on screen"));
  through_ = new QCheckBox(tr("through the depth"));
  through_->setChecked(true);
  through_->setToolTip(
      tr("paint every cell under the brush across the depth (columns of a slab); off: only the "
         "cells visible on screen"));

  auto* tools = new QHBoxLayout;
  const QString names[3] = {tr("Camera"), tr("Brush"), tr("Box")};
  const QString keys[3] = {QStringLiteral("C"), QStringLiteral("B"), QStringLiteral("X")};
  for (int i = 0; i < 3; ++i) {
    tools_[i] = new QToolButton;
    tools_[i]->setText(names[i]);
    tools_[i]->setCheckable(true);
    tools_[i]->setAutoExclusive(true);
    tools_[i]->setShortcut(QKeySequence(keys[i]));
    tools_[i]->setToolTip(tr("%1 (%2)").arg(names[i], keys[i]));
    connect(tools_[i], &QToolButton::clicked, this, [this, i] { choose_tool(i); });
    tools->addWidget(tools_[i]);
  }
  tools_[0]->setChecked(true);
  auto* undo = new QToolButton;
  undo->setDefaultAction(editor_->undo_stack()->createUndoAction(this, tr("Undo")));
  auto* redo = new QToolButton;
  redo->setDefaultAction(editor_->undo_stack()->createRedoAction(this, tr("Redo")));
  tools->addStretch();
  tools->addWidget(undo);
  tools->addWidget(redo);

  spec_ = new QLineEdit;
  spec_->setPlaceholderText(tr("e.g. 4x2 or 2x2x1"));
  auto* fill = new QPushButton(tr("Fill"));
  metis_ = new QSpinBox;
  metis_->setRange(1, 4096);
  metis_->setValue(4);
  auto* metis = new QPushButton(tr("METIS"));
  auto* fills = new QHBoxLayout;
  fills->addWidget(spec_);
  fills->addWidget(fill);
  fills->addWidget(metis_);
  fills->addWidget(metis);

  auto* paint_row = new QHBoxLayout;
  paint_row->addWidget(subdomain_);
  paint_row->addWidget(swatch_);
  paint_row->addWidget(radius_);
  paint_row->addWidget(through_);

  message_ = new QLabel;
  message_->setWordWrap(true);
  message_->setStyleSheet(QStringLiteral("color: #b00020"));
  table_ = new PartitionTable;
  verdict_ = new QLabel;
  verdict_->setObjectName(QStringLiteral("partitionVerdict"));
  verdict_->setWordWrap(true);
  connect(table_, &PartitionTable::verdictChanged, verdict_, &QLabel::setText);

  auto* form = new QFormLayout;
  form->addRow(tr("body"), body_);
  form->addRow(tr("tool"), tools);
  form->addRow(tr("paint into"), paint_row);
  form->addRow(tr("fill"), fills);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(message_);
  layout->addWidget(table_, 1);
  layout->addWidget(verdict_);

  connect(body_, QOverload<int>::of(&QComboBox::activated), this, [this](int b) {
    editor_->set_body(b);
    view_->set_paint_body(b);
  });
  connect(subdomain_, QOverload<int>::of(&QSpinBox::valueChanged), this, [this](int id) {
    editor_->set_current_subdomain(id);
    swatch_->setStyleSheet(QStringLiteral("background: %1; border: 1px solid #333").arg(category_color(id).name()));
  });
  emit subdomain_->valueChanged(0);
  for (int k = 0; k <= 9; ++k)  // digit keys pick the subdomain (line edits keep their typing)
    connect(new QShortcut(QKeySequence(Qt::Key_0 + k), this), &QShortcut::activated, subdomain_,
            [this, k] { subdomain_->setValue(k); });
  connect(radius_, QOverload<int>::of(&QSpinBox::valueChanged), view_, &MeshView::set_brush_radius);
  connect(through_, &QCheckBox::toggled, view_, &MeshView::set_paint_through);
  connect(fill, &QPushButton::clicked, this, [this] { message_->setText(editor_->fill(spec_->text())); });
  connect(spec_, &QLineEdit::returnPressed, this, [this] { message_->setText(editor_->fill(spec_->text())); });
  connect(metis, &QPushButton::clicked, this,
          [this] { message_->setText(editor_->fill(QStringLiteral("metis:%1").arg(metis_->value()))); });
  connect(view_, &MeshView::painted, this,
          [this](const std::vector<int>& cells, int stroke) { editor_->paint(cells, stroke); });
  connect(editor_, &PartitionEditor::mapChanged, this, &PartitionPanel::map_changed);
  connect(editor_, &PartitionEditor::refused, message_, &QLabel::setText);
  map_changed();
}

void PartitionPanel::refresh_bodies() {
  const QStringList names = editor_->bodies();
  QStringList shown;
  for (int i = 0; i < body_->count(); ++i) shown << body_->itemText(i);
  if (shown != names) {
    body_->clear();
    body_->addItems(names);
  }
  body_->setCurrentIndex(editor_->body());
  view_->set_paint_body(editor_->body());
}

void PartitionPanel::choose_tool(int tool) {
  view_->set_paint_tool(static_cast<PaintTool>(tool));
  if (tool != 0) view_->set_partition(editor_->body(), editor_->map());
}

void PartitionPanel::map_changed() {
  refresh_bodies();
  if (view_->paint_tool() != PaintTool::Camera || view_->color_by() == color_by::Subdomain)
    view_->set_partition(editor_->body(), editor_->map());
  table_->show_map(editor_->model(), editor_->body(), editor_->map());
}

}  // namespace rollsim::ui
