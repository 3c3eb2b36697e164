// The document behind the window: edits validated as `rollsim run` validates files, the model rebuilt off the
// GUI thread with its counts, save -> open round trips, and a saved project runs unchanged with `rollsim run`.
#include <sys/stat.h>

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include "ProjectDocument.h"
#include "Resources.h"
#include "io/AtomicFile.h"
#include "project/ModelBuilder.h"

using namespace rollsim;
using namespace rollsim::ui;

namespace {
const QString kSample = QStringLiteral(ROLLSIM_SOURCE_DIR "/samples/plate-hole-2d.json");

unsigned mode_of(const QString& file) {
  struct stat s {};
  ::stat(file.toLocal8Bit().constData(), &s);
  return s.st_mode & 07777;
}

QByteArray read(const QString& file) {
  QFile f(file);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}
}  // namespace

class TestProjectDocument : public QObject {
  Q_OBJECT

 private slots:
  void opens_a_sample_with_its_counts() {
    ProjectDocument doc;
    doc.open(kSample);
    QVERIFY(doc.model());
    QCOMPARE(doc.counts().elements, 32L * 24);
    QCOMPARE(doc.counts().nodes, 33L * 25);
    QVERIFY(doc.counts().dofs > 0 && doc.counts().dofs < 2 * doc.counts().nodes);
    QVERIFY(!doc.modified());
    QCOMPARE(doc.display_name(), QStringLiteral("plate-hole-2d.json"));
  }

  void edit_updates_project_and_mesh_counts() {
    ProjectDocument doc;
    doc.open(kSample);
    QSignalSpy built(&doc, &ProjectDocument::modelChanged);
    QVERIFY(doc.propose("/bodies/0/mesh/n_radial", 12).empty());
    QCOMPARE(doc.document()["bodies"][0]["mesh"]["n_radial"].get<int>(), 12);
    QCOMPARE(doc.project().data["bodies"][0]["mesh"]["n_radial"].get<int>(), 12);
    QVERIFY(doc.modified());
    QVERIFY(built.wait(10000));
    QCOMPARE(doc.counts().elements, 32L * 12);
    QCOMPARE(doc.counts().nodes, 33L * 13);
    QCOMPARE(doc.model()->total_elements(), 32L * 12);
  }

  void bad_value_is_refused_with_the_batch_message() {
    ProjectDocument doc;
    doc.open(kSample);
    const std::string before = doc.text();
    const auto issues = doc.propose("/bodies/0/mesh/n_radial", -3);
    QCOMPARE(issues.size(), size_t{1});
    // the batch command's message for the same file
    auto data = json::parse(read(kSample).toStdString());
    data["bodies"][0]["mesh"]["n_radial"] = -3;
    try {
      parse_project(data.dump(), "x");
      QFAIL("the batch validation accepted -3");
    } catch (const ProjectError& e) {
      QCOMPARE(issues[0].str(), e.issues()[0].str());
    }
    QCOMPARE(QString::fromStdString(issues[0].str()),
             QStringLiteral("bodies[0].mesh.n_radial: must be a positive integer, got -3"));
    QCOMPARE(doc.text(), before);
    QVERIFY(!doc.modified());
    // a cross-reference problem (an odd count around the hole) is refused the same way
    const auto odd = doc.propose("/bodies/0/mesh/n_around", 33);
    QVERIFY(!odd.empty());
    QCOMPARE(QString::fromStdString(odd[0].path), QStringLiteral("bodies[0].mesh.n_around"));
    QCOMPARE(doc.text(), before);
    // a value of the wrong type names what was typed
    const auto text = doc.propose("/materials/0/E", "abc");
    QCOMPARE(QString::fromStdString(text[0].str()),
             QStringLiteral("materials[0].E: must be a finite number > 0, got \"abc\""));
  }

  void removing_an_optional_value_restores_its_default() {
    ProjectDocument doc;
    doc.open(kSample);
    QVERIFY(doc.propose("/bodies/0/mesh/grading", nullptr).empty());
    QVERIFY(!doc.document()["bodies"][0]["mesh"].contains("grading"));
    QCOMPARE(doc.project().data["bodies"][0]["mesh"]["grading"].get<double>(), 1.0);
  }

  void save_open_round_trip_is_identical() {
    QTemporaryDir dir;
    ProjectDocument doc;
    doc.open(kSample);
    QVERIFY(doc.propose("/bodies/0/mesh/n_radial", 10).empty());
    QVERIFY(doc.propose("/solver/threads", 2).empty());
    const QString file = dir.filePath(QStringLiteral("saved.json"));
    doc.save_as(file);
    QVERIFY(!doc.modified());
    QCOMPARE(doc.file(), file);
    const QByteArray saved = read(file);
    QCOMPARE(saved.toStdString(), doc.text());
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{QStringLiteral("saved.json")});

    ProjectDocument again;
    again.open(file);
    QCOMPARE(again.text(), doc.text());
    const QString file2 = dir.filePath(QStringLiteral("saved2.json"));
    again.save_as(file2);
    QCOMPARE(read(file2), saved);
    // key order of the original file is kept, so the diff against the sample is the two edits only
    QCOMPARE(QString::fromStdString(again.document().begin().key()), QStringLiteral("name"));
  }

  void saved_project_runs_unchanged_with_rollsim_run() {
    QTemporaryDir dir;
    ProjectDocument doc;
    doc.open(kSample);
    QVERIFY(doc.propose("/bodies/0/mesh/n_radial", 8).empty());
    QVERIFY(doc.propose("/bodies/0/mesh/n_around", 16).empty());
    const QString file = dir.filePath(QStringLiteral("p.json"));
    doc.save_as(file);
    QProcess run;
    run.start(QStringLiteral(ROLLSIM_BINARY), {QStringLiteral("run"), file, QStringLiteral("--out"),
                                               dir.filePath(QStringLiteral("out")), QStringLiteral("--quiet")});
    QVERIFY(run.waitForFinished(60000));
    QCOMPARE(run.exitCode(), 0);
    const auto summary = json::parse(read(dir.filePath(QStringLiteral("out/summary.json"))).toStdString());
    QCOMPARE(summary["status"].get<std::string>(), std::string("converged"));
  }

  void default_project_is_valid() {
    ProjectDocument doc;
    doc.load_default();
    QVERIFY(doc.model());
    QVERIFY(doc.file().isEmpty());
    QCOMPARE(doc.display_name(), QStringLiteral("untitled"));
    QCOMPARE(QString::fromStdString(doc.project().name()), QStringLiteral("rolling-2d-36x6"));
  }

  void invalid_file_is_refused_and_the_document_kept() {
    QTemporaryDir dir;
    const QString bad = dir.filePath(QStringLiteral("bad.json"));
    QFile f(bad);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("{\"dimension\": 2, \"materials\": []}");
    f.close();
    ProjectDocument doc;
    doc.open(kSample);
    const std::string before = doc.text();
    QVERIFY_EXCEPTION_THROWN(doc.open(bad), ProjectError);
    QCOMPARE(doc.text(), before);
    QCOMPARE(doc.file(), kSample);
  }

  // The reported risks of the window's Save (io/AtomicFile): a read-only target was replaced, 0600 widened to 0644,
  // a symlink replaced by a file, and a planted `.NAME.tmp` symlink followed.
  void save_keeps_the_target_safe() {
    QTemporaryDir dir;
    ProjectDocument doc;
    doc.open(kSample);
    const QString file = dir.filePath(QStringLiteral("p.json"));
    doc.save_as(file);
    QVERIFY(::chmod(file.toLocal8Bit().constData(), 0600) == 0);
    QVERIFY(doc.propose("/solver/threads", 2).empty());
    doc.save_as(file);
    QCOMPARE(mode_of(file), 0600u);

    const QString link = dir.filePath(QStringLiteral("link.json"));
    QVERIFY(QFile::link(file, link));
    QVERIFY(doc.propose("/solver/threads", 3).empty());
    doc.save_as(link);
    QVERIFY(QFileInfo(link).isSymLink());
    QCOMPARE(read(file).toStdString(), doc.text());

    const QByteArray before = read(file);
    QVERIFY(::chmod(file.toLocal8Bit().constData(), 0444) == 0);
    QVERIFY(doc.propose("/solver/threads", 4).empty());
    QVERIFY_EXCEPTION_THROWN(doc.save_as(file), WriteError);
    QVERIFY(doc.modified());
    QCOMPARE(read(file), before);

    const QString victim = dir.filePath(QStringLiteral("victim"));
    QFile v(victim);
    QVERIFY(v.open(QIODevice::WriteOnly) && v.write("keep me") == 7);
    v.close();
    QVERIFY(QFile::link(victim, dir.filePath(QStringLiteral(".q.json.tmp"))));
    doc.save_as(dir.filePath(QStringLiteral("q.json")));
    QCOMPARE(read(victim), QByteArray("keep me"));
  }
};

QTEST_MAIN(TestProjectDocument)
#include "test_project_document.moc"
