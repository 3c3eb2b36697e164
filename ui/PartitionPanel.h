#pragma once
// Partition design: which body, the subdomain to paint into, the tool (camera / brush / box, through the depth or
// visible cells only), fills (structured "4x2x1", METIS N), undo/redo, and the live partition table (per
// subdomain: elements, dofs, interface multipliers, rigid modes, pieces, estimated factorization cost; the
// predicted cost of the partition against one domain).
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QTableWidget;
class QToolButton;

namespace rollsim::ui {

class MeshView;
class PartitionEditor;
class PartitionTable;

class PartitionPanel : public QWidget {
  Q_OBJECT

 public:
  PartitionPanel(PartitionEditor* editor, MeshView* view, QWidget* parent = nullptr);

  PartitionTable* table() const { return table_; }
  QSpinBox* subdomain_box() const { return subdomain_; }

 private:
  void refresh_bodies();
  void choose_tool(int tool);
  void map_changed();

  PartitionEditor* editor_;
  MeshView* view_;
  QComboBox* body_;
  QSpinBox* subdomain_;
  QLabel* swatch_;
  QSpinBox* radius_;
  QCheckBox* through_;
  QLineEdit* spec_;
  QSpinBox* metis_;
  QLabel* message_;
  QLabel* verdict_;
  PartitionTable* table_;
  QToolButton* tools_[3];
};

}  // namespace rollsim::ui
