#pragma once
// The project being edited in the window: the user's JSON (what Save writes, key order kept), the validated
// Project (defaults filled) and the Model built from it. Every edit goes through the batch command's own
// validation (parse_project + check_references, then build_model); a refused edit leaves everything unchanged.
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "model/Model.h"
#include "project/Project.h"
#include "project/RunForecast.h"

namespace rollsim::ui {

/// The document as the user wrote it: an ordered JSON object (Save keeps the key order of the file).
using Document = nlohmann::ordered_json;

/// Sizes of the built model, for the status bar.
struct ModelCounts {
  long nodes = 0, elements = 0, dofs = 0;
};

class ProjectDocument : public QObject {
  Q_OBJECT

 public:
  explicit ProjectDocument(QObject* parent = nullptr);
  ~ProjectDocument() override;

  /// Replaces the document by `text` (File > New / Open). Throws ProjectError, leaving the document as it was.
  /// `file` empty: untitled (Save asks for a name).
  void load_text(const std::string& text, const QString& file, const QString& source_name);
  /// Opens a project file. Throws ProjectError.
  void open(const QString& file);
  /// The embedded default project (samples/rolling-2d-36x6.json, embedded as :/rollsim/default-project.json), untitled.
  void load_default();
  /// Writes the document atomically (temporary file + rename) and makes `file` the document's file.
  /// Throws std::exception on I/O failure.
  void save_as(const QString& file);

  /// Proposes `value` at the JSON pointer (e.g. "/bodies/0/mesh/nx"); null removes the key (back to the default).
  /// Returns the validation issues; empty means accepted (document and project updated, model rebuilt).
  std::vector<Issue> propose(const std::string& pointer, const Document& value);
  /// Several edits validated together as one change (e.g. a painted map replacing a partition spec).
  std::vector<Issue> propose(const std::vector<std::pair<std::string, Document>>& edits);

  /// A value the user typed that validation refused: the field's text and why. The document keeps its last accepted
  /// value; while any refused edit is left, Save and Run are refused (MainWindow, RunPanel), so that the window never
  /// writes or solves a value the user did not type (e.g. the prefix 0.9 of a refused 0.95).
  struct RefusedEdit {
    QString text;
    QString message;
  };
  void refuse_edit(const std::string& pointer, const QString& text, const QString& message);
  /// The field's refused value withdrawn: its edit was accepted (or the document was replaced).
  void withdraw_refused_edit(const std::string& pointer);
  /// The refused edit at a JSON pointer, or null.
  const RefusedEdit* refused_edit(const std::string& pointer) const;
  /// Every refused edit's message, one a line ("" when none): why Save and Run are refused.
  QString refused_edits() const;

  const Document& document() const { return doc_; }
  /// The document as saved: 2-space indented JSON with a final newline.
  std::string text() const;
  const Project& project() const { return project_; }
  /// The model of the current project; null until the first build finishes.
  std::shared_ptr<const Model> model() const { return model_; }
  ModelCounts counts() const { return counts_; }
  /// What a run of the current project will be and cost (its process's facts, increments, predicted time), made
  /// with each model.
  const RunForecast& forecast() const { return forecast_; }
  /// True while a model build runs in the background.
  bool building() const { return watcher_.isRunning(); }
  bool modified() const { return modified_; }
  QString file() const { return file_; }
  /// File name or "untitled", for titles and messages.
  QString display_name() const;

 signals:
  /// The document's values changed (edit accepted, file loaded); widgets refresh from it.
  void changed();
  /// A new model is available (after every accepted change, once its mesh is built).
  void modelChanged();
  /// An accepted edit could not be built (a problem only visible on the mesh): the document was reverted.
  void buildRefused(const QString& message);
  /// The file name or the modified flag changed.
  void fileStateChanged();
  /// A refused edit was recorded or withdrawn.
  void refusedEditsChanged();

 private:
  struct Build {
    std::shared_ptr<const Model> model;
    ModelCounts counts;
    RunForecast forecast;
    std::string error;
    unsigned long generation = 0;
  };
  void start_build();
  void build_done();
  void set_modified(bool m);

  Document doc_;
  Project project_;
  Document built_doc_;  // the last document whose model built: the revert point of buildRefused
  Project built_project_;
  bool built_modified_ = false;
  std::shared_ptr<const Model> model_;
  ModelCounts counts_;
  RunForecast forecast_;
  QString file_;
  bool modified_ = false;
  unsigned long generation_ = 0;
  bool rebuild_pending_ = false;
  QFutureWatcher<Build> watcher_;
  std::map<std::string, RefusedEdit> refused_;  // by JSON pointer
};

/// Validates a document exactly as `rollsim run` validates the file. Throws ProjectError.
Project validate_document(const Document& doc, const std::string& source);

}  // namespace rollsim::ui
