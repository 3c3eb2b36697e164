#include "ProjectDocument.h"

#include <QFile>
#include <QFileInfo>
#include <QStringList>
#include <QtConcurrent/QtConcurrentRun>

#include "Resources.h"
#include "io/AtomicFile.h"
#include "model/DofMap.h"
#include "project/ModelBuilder.h"

namespace rollsim::ui {

namespace {

/// Meshes, node sets and conditions (the batch command's build_model), counted for the status bar.
ModelCounts count(const Model& m) {
  ModelCounts c;
  c.nodes = m.total_nodes();
  c.elements = m.total_elements();
  for (size_t b = 0; b < m.bodies.size(); ++b)
    c.dofs += DofMap(m.bodies[b], static_cast<int>(b), m.displacements).num_free();
  return c;
}

}  // namespace

Project validate_document(const Document& doc, const std::string& source) { return parse_project(doc.dump(), source); }

ProjectDocument::ProjectDocument(QObject* parent) : QObject(parent) {
  connect(&watcher_, &QFutureWatcher<Build>::finished, this, &ProjectDocument::build_done);
}

ProjectDocument::~ProjectDocument() { watcher_.waitForFinished(); }

QString ProjectDocument::display_name() const {
  return file_.isEmpty() ? QStringLiteral("untitled") : QFileInfo(file_).fileName();
}

std::string ProjectDocument::text() const { return doc_.dump(2) + "\n"; }

void ProjectDocument::load_text(const std::string& text, const QString& file, const QString& source_name) {
  const std::string source = source_name.toStdString();
  Project project = parse_project(text, source);                     // throws: nothing changed
  auto model = std::make_shared<const Model>(build_model(project));  // opening builds at once: errors refuse it
  Document doc = Document::parse(text);
  file_ = file;
  watcher_.waitForFinished();
  ++generation_;
  rebuild_pending_ = false;
  doc_ = std::move(doc);
  project_ = std::move(project);
  built_doc_ = doc_;
  built_project_ = project_;
  built_modified_ = false;
  set_modified(false);
  model_ = std::move(model);
  counts_ = count(*model_);
  forecast_ = forecast_run(project_.config(), *model_);
  const bool had_refused = !refused_.empty();
  refused_.clear();
  emit changed();
  emit fileStateChanged();
  emit modelChanged();
  if (had_refused) emit refusedEditsChanged();
}

void ProjectDocument::open(const QString& file) {
  const Project checked = load_project(file.toStdString());  // the batch command's reader and messages
  QFile f(file);
  if (!f.open(QIODevice::ReadOnly)) throw ProjectError(file.toStdString(), {{"", "cannot be read"}});
  load_text(f.readAll().toStdString(), file, file);
}

void ProjectDocument::load_default() {
  load_text(default_project_text().toStdString(), QString(), QStringLiteral("untitled"));
}

void ProjectDocument::save_as(const QString& file) {
  write_file_atomically(file.toStdString(), text());
  file_ = file;
  set_modified(false);
  emit fileStateChanged();
}

std::vector<Issue> ProjectDocument::propose(const std::string& pointer, const Document& value) {
  return propose({{pointer, value}});
}

std::vector<Issue> ProjectDocument::propose(const std::vector<std::pair<std::string, Document>>& edits) {
  Document doc = doc_;
  for (const auto& [pointer, value] : edits) {
    try {
      const Document::json_pointer ptr(pointer);
      if (value.is_null()) {
        Document& parent = doc.at(ptr.parent_pointer());
        if (parent.is_object()) parent.erase(ptr.back());
      } else {
        doc[ptr] = value;
      }
    } catch (const nlohmann::json::exception& e) {
      return {{pointer, std::string("cannot be set: ") + e.what()}};
    }
  }
  if (doc == doc_) return {};
  try {
    Project project = validate_document(doc, display_name().toStdString());
    doc_ = std::move(doc);
    project_ = std::move(project);
    set_modified(true);
    emit changed();
    emit fileStateChanged();
    start_build();
  } catch (const ProjectError& e) {
    return e.issues();
  }
  return {};
}

void ProjectDocument::refuse_edit(const std::string& pointer, const QString& text, const QString& message) {
  refused_[pointer] = {text, message};
  emit refusedEditsChanged();
}

void ProjectDocument::withdraw_refused_edit(const std::string& pointer) {
  if (refused_.erase(pointer)) emit refusedEditsChanged();
}

const ProjectDocument::RefusedEdit* ProjectDocument::refused_edit(const std::string& pointer) const {
  const auto it = refused_.find(pointer);
  return it == refused_.end() ? nullptr : &it->second;
}

QString ProjectDocument::refused_edits() const {
  QStringList lines;
  for (const auto& [pointer, edit] : refused_) lines << edit.message;
  return lines.join('\n');
}

void ProjectDocument::set_modified(bool m) { modified_ = m; }

// Meshes are built off the GUI thread; edits made meanwhile queue one more build of the newest document.
void ProjectDocument::start_build() {
  if (watcher_.isRunning()) {
    rebuild_pending_ = true;
    return;
  }
  rebuild_pending_ = false;
  const unsigned long generation = ++generation_;
  auto project = std::make_shared<const Project>(project_);
  watcher_.setFuture(QtConcurrent::run([project, generation]() {
    Build b;
    b.generation = generation;
    try {
      auto model = std::make_shared<Model>(build_model(*project));
      b.counts = count(*model);
      b.forecast = forecast_run(project->config(), *model);
      b.model = std::move(model);
    } catch (const ProjectError& e) {
      b.error = e.what();
    } catch (const std::exception& e) {
      b.error = e.what();
    }
    return b;
  }));
}

void ProjectDocument::build_done() {
  const Build b = watcher_.result();
  if (b.generation != generation_) return;  // superseded by a file load
  if (rebuild_pending_) {                   // the document moved on: build the newest one
    start_build();
    return;
  }
  if (!b.error.empty()) {
    doc_ = built_doc_;
    project_ = built_project_;
    set_modified(built_modified_);
    emit changed();
    emit fileStateChanged();
    emit buildRefused(QString::fromStdString(b.error));
    return;
  }
  built_doc_ = doc_;
  built_project_ = project_;
  built_modified_ = modified_;
  model_ = b.model;
  counts_ = b.counts;
  forecast_ = b.forecast;
  emit modelChanged();
}

}  // namespace rollsim::ui
