#include "ProjectTreePanel.h"

#include <QHeaderView>

#include "project/ProjectSchema.h"

namespace rollsim::ui {

namespace {

constexpr int kPointerRole = Qt::UserRole + 1;

/// "plate", "symmetry plate/left", "A": what identifies an entry of a section.
QString entry_label(const json& entry, size_t index) {
  QString s;
  if (entry.contains("type") && entry["type"].is_string()) s = QString::fromStdString(entry["type"].get<std::string>());
  if (entry.contains("name") && entry["name"].is_string())
    s += (s.isEmpty() ? "" : " ") + QString::fromStdString(entry["name"].get<std::string>());
  if (entry.contains("body") && entry["body"].is_string()) {
    s += (s.isEmpty() ? "" : " ") + QString::fromStdString(entry["body"].get<std::string>());
    if (entry.contains("set") && entry["set"].is_string())
      s += "/" + QString::fromStdString(entry["set"].get<std::string>());
    if (entry.contains("surface") && entry["surface"].is_string())
      s += "/" + QString::fromStdString(entry["surface"].get<std::string>());
  }
  return s.isEmpty() ? QStringLiteral("#%1").arg(index) : s;
}

}  // namespace

ProjectTreePanel::ProjectTreePanel(ProjectDocument* document, QWidget* parent) : QTreeWidget(parent), doc_(document) {
  setHeaderHidden(true);
  setColumnCount(1);
  connect(doc_, &ProjectDocument::changed, this, &ProjectTreePanel::refresh);
  connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
    if (item && item->data(0, kPointerRole).isValid()) emit objectSelected(item->data(0, kPointerRole).toString());
  });
  refresh();  // a document opened before the panel existed shows at once
}

std::string ProjectTreePanel::selected_pointer() const {
  const QTreeWidgetItem* item = currentItem();
  return item && item->data(0, kPointerRole).isValid() ? item->data(0, kPointerRole).toString().toStdString()
                                                       : std::string();
}

void ProjectTreePanel::select(const std::string& pointer) {
  const QString p = QString::fromStdString(pointer);
  for (QTreeWidgetItemIterator it(this); *it; ++it)
    if ((*it)->data(0, kPointerRole).isValid() && (*it)->data(0, kPointerRole).toString() == p) {
      setCurrentItem(*it);
      return;
    }
}

void ProjectTreePanel::refresh() {
  const std::string keep = selected_pointer();
  QSignalBlocker block(this);
  clear();
  const json& project_data = doc_->project().data;
  if (!project_data.is_object()) return;  // no project loaded yet
  auto* root = new QTreeWidgetItem(this, {QString::fromStdString(doc_->project().name())});
  root->setData(0, kPointerRole, QString());
  root->setToolTip(0, tr("the project: name, dimension, description"));
  for (const Field& f : project_schema().fields) {
    if (f.kind != Kind::Object && f.kind != Kind::ObjectArray) continue;
    const std::string p = "/" + f.name;
    auto* section = new QTreeWidgetItem(root, {QString::fromStdString(f.name)});
    section->setToolTip(0, QString::fromStdString(f.doc));
    if (f.kind == Kind::Object) {
      section->setData(0, kPointerRole, QString::fromStdString(p));
      continue;
    }
    const json& entries = project_data.contains(f.name) ? project_data[f.name] : json::array();
    section->setText(0, QStringLiteral("%1 (%2)").arg(QString::fromStdString(f.name)).arg(entries.size()));
    for (size_t i = 0; i < entries.size(); ++i) {
      auto* item = new QTreeWidgetItem(section, {entry_label(entries[i], i)});
      item->setData(0, kPointerRole, QString::fromStdString(p + "/" + std::to_string(i)));
    }
  }
  expandAll();
  select(keep);  // the same object stays selected without a new objectSelected (the editor keeps its focus)
  const bool kept = currentItem() != nullptr;
  block.unblock();
  if (!kept) setCurrentItem(root);
}

}  // namespace rollsim::ui
