#include "PartitionEditor.h"

#include <QUndoCommand>
#include <algorithm>
#include <unordered_map>

#include "ProjectDocument.h"
#include "partition/PartitionSpec.h"

namespace rollsim::ui {

namespace {
constexpr int kWriteDelayMs = 250;  // a stroke's steps within this time make one document write
}

/// One undoable change of the map: `elements` go from `before` to `after`; steps of one stroke merge.
class MapCommand : public QUndoCommand {
 public:
  MapCommand(PartitionEditor* editor, std::vector<int> elements, std::vector<int> before, std::vector<int> after,
             int stroke, const QString& text)
      : QUndoCommand(text),
        editor_(editor),
        elements_(std::move(elements)),
        before_(std::move(before)),
        after_(std::move(after)),
        stroke_(stroke) {
    for (size_t i = 0; i < elements_.size(); ++i) index_[elements_[i]] = i;
  }
  void redo() override { editor_->apply(elements_, after_); }
  void undo() override { editor_->apply(elements_, before_); }
  int id() const override { return stroke_ > 0 ? 1 : -1; }
  bool mergeWith(const QUndoCommand* other) override {
    const auto* o = static_cast<const MapCommand*>(other);
    if (o->stroke_ != stroke_) return false;
    for (size_t i = 0; i < o->elements_.size(); ++i) {  // a cell painted twice keeps its first `before`
      const auto [at, added] = index_.try_emplace(o->elements_[i], elements_.size());
      if (added) {
        elements_.push_back(o->elements_[i]);
        before_.push_back(o->before_[i]);
        after_.push_back(o->after_[i]);
      } else {
        after_[at->second] = o->after_[i];
      }
    }
    return true;
  }

 private:
  PartitionEditor* editor_;
  std::vector<int> elements_, before_, after_;
  std::unordered_map<int, size_t> index_;  // element -> position in elements_
  int stroke_;
};

PartitionEditor::PartitionEditor(ProjectDocument* document, QObject* parent) : QObject(parent), doc_(document) {
  write_timer_.setSingleShot(true);
  write_timer_.setInterval(kWriteDelayMs);
  connect(&write_timer_, &QTimer::timeout, this, [this] { flush(); });
  connect(doc_, &ProjectDocument::modelChanged, this, &PartitionEditor::model_changed);
  model_changed();
}

QStringList PartitionEditor::bodies() const {
  QStringList names;
  if (model_)
    for (const Body& b : model_->bodies) names << QString::fromStdString(b.name);
  return names;
}

int PartitionEditor::subdomain_count() const {
  return map_.empty() ? 0 : *std::max_element(map_.begin(), map_.end()) + 1;
}

void PartitionEditor::set_current_subdomain(int id) { current_ = std::max(0, id); }

void PartitionEditor::set_body(int model_body) {
  if (model_body == body_) return;
  flush();
  body_ = model_ && model_body >= 0 && model_body < static_cast<int>(model_->bodies.size()) ? model_body : -1;
  undo_.clear();
  load_from_model();
}

void PartitionEditor::load_from_model() {
  map_.clear();
  if (body_ >= 0) {
    const Body& b = model_->bodies[static_cast<size_t>(body_)];
    map_ = b.partition.element_subdomain;
    map_.resize(static_cast<size_t>(b.mesh.num_elements()), 0);
  }
  dirty_ = false;
  emit mapChanged();
}

void PartitionEditor::model_changed() {
  model_ = doc_->model();
  if (!model_) return;
  if (body_ < 0 || body_ >= static_cast<int>(model_->bodies.size())) {
    body_ = model_->bodies.empty() ? -1 : 0;
    undo_.clear();
    load_from_model();
    return;
  }
  if (dirty_) return;  // our own change is on its way to the document
  // the document's map is ours (the model may have split a disconnected piece: keep the painted ids)
  const auto [map_ptr, spec_ptr] = pointers();
  const Document::json_pointer ptr(map_ptr);
  const Document& d = doc_->document();
  const bool ours =
      !map_ptr.empty() && (d.contains(ptr) ? d.at(ptr).get<std::vector<int>>() == map_
                                           : subdomain_count() <= 1 && !d.contains(Document::json_pointer(spec_ptr)));
  if (!ours) {
    undo_.clear();  // the mesh or the partition changed elsewhere (property editor, file): start from it
    load_from_model();
  }
}

std::pair<std::string, std::string> PartitionEditor::pointers() const {
  if (body_ < 0) return {};
  const std::string& name = model_->bodies[static_cast<size_t>(body_)].name;
  const Document& d = doc_->document();
  if (d.contains("process")) {
    return name == "slab"
               ? std::pair<std::string, std::string>{"/process/slab_partition_map", "/process/slab_partition"}
               : std::pair<std::string, std::string>{};
  }
  const Document& bodies = d.at("bodies");
  for (size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].value("name", "") == name) {
      const std::string p = "/bodies/" + std::to_string(i);
      return {p + "/partition_map", p + "/partition"};
    }
  return {};
}

bool PartitionEditor::paint(const std::vector<int>& elements, int stroke) {
  std::vector<int> cells, before, after;
  std::vector<char> taken(map_.size(), 0);
  for (const int e : elements)
    if (e >= 0 && e < static_cast<int>(map_.size()) && map_[static_cast<size_t>(e)] != current_ &&
        !taken[static_cast<size_t>(e)]) {
      taken[static_cast<size_t>(e)] = 1;
      cells.push_back(e);
      before.push_back(map_[static_cast<size_t>(e)]);
      after.push_back(current_);
    }
  if (cells.empty()) return false;
  const QString text = tr("paint %1 cells into subdomain %2").arg(cells.size()).arg(current_);
  undo_.push(new MapCommand(this, std::move(cells), std::move(before), std::move(after), stroke, text));
  return true;
}

QString PartitionEditor::fill(const QString& spec) {
  if (body_ < 0) return tr("no body to partition");
  std::vector<int> ids;
  try {
    const Body& b = model_->bodies[static_cast<size_t>(body_)];
    ids = make_partition(b.mesh, parse_partition_spec(spec.toStdString())).element_subdomain;
  } catch (const std::exception& e) {
    return QString::fromUtf8(e.what());
  }
  std::vector<int> all(map_.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  undo_.push(new MapCommand(this, std::move(all), map_, std::move(ids), 0, tr("fill %1").arg(spec)));
  return {};
}

void PartitionEditor::apply(const std::vector<int>& elements, const std::vector<int>& ids) {
  for (size_t i = 0; i < elements.size(); ++i) map_[static_cast<size_t>(elements[i])] = ids[i];
  dirty_ = true;
  write_timer_.start();
  emit mapChanged();
}

QString PartitionEditor::flush() {
  write_timer_.stop();
  if (!dirty_) return {};
  dirty_ = false;
  const auto [map_ptr, spec_ptr] = pointers();
  if (map_ptr.empty()) return {};
  const bool single = subdomain_count() <= 1;  // one domain: no map in the file
  const auto issues = doc_->propose({{spec_ptr, Document()}, {map_ptr, single ? Document() : Document(map_)}});
  if (issues.empty()) return {};
  QString message;
  for (const Issue& i : issues) message += QString::fromStdString(i.path + ": " + i.message) + "\n";
  message = message.trimmed();
  emit refused(message);
  return message;
}

}  // namespace rollsim::ui
