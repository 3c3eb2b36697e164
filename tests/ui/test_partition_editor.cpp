// Partition design without the view: paint steps assign the current subdomain to exactly the given cells, one
// stroke is one undo step, undo/redo restore the map, fills equal the core's partitions, the map reaches the
// project (bodies[].partition_map, or process.slab_partition_map for a rolling pass) and the rebuilt model, and a
// saved painted project opens with the same map.
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include "PartitionEditor.h"
#include "ProjectDocument.h"
#include "partition/PartitionSpec.h"

using namespace rollsim;
using namespace rollsim::ui;

namespace {
const QString kBlock = QStringLiteral(ROLLSIM_SOURCE_DIR "/samples/cantilever-2d-240x60.json");

/// Waits until the document's model has been rebuilt after the last edit.
bool wait_model(ProjectDocument& doc) {
  QSignalSpy built(&doc, &ProjectDocument::modelChanged);
  return built.wait(20000);
}
}  // namespace

class TestPartitionEditor : public QObject {
  Q_OBJECT

 private slots:
  void paint_undo_redo() {
    ProjectDocument doc;
    doc.open(kBlock);
    PartitionEditor editor(&doc);
    QCOMPARE(editor.body(), 0);
    const int n = static_cast<int>(editor.map().size());
    QCOMPARE(n, 240 * 60);
    QCOMPARE(editor.subdomain_count(), 1);
    editor.set_current_subdomain(2);
    const int stroke = editor.next_stroke();
    QVERIFY(editor.paint({5, 6, 7}, stroke));
    QVERIFY(editor.paint({7, 8, 60000, -1}, stroke));  // out-of-range ids are ignored, 7 already painted
    QVERIFY(!editor.paint({5}, stroke));               // nothing changes: no step
    QCOMPARE(editor.undo_stack()->count(), 1);         // one stroke, one undo step
    for (int e = 0; e < n; ++e) QCOMPARE(editor.map()[static_cast<size_t>(e)], e >= 5 && e <= 8 ? 2 : 0);
    editor.set_current_subdomain(1);
    QVERIFY(editor.paint({8, 9}, editor.next_stroke()));
    QCOMPARE(editor.undo_stack()->count(), 2);
    QCOMPARE(editor.map()[8], 1);
    editor.undo_stack()->undo();
    QCOMPARE(editor.map()[8], 2);
    QCOMPARE(editor.map()[9], 0);
    editor.undo_stack()->undo();
    for (int e = 0; e < n; ++e) QCOMPARE(editor.map()[static_cast<size_t>(e)], 0);
    editor.undo_stack()->redo();
    editor.undo_stack()->redo();
    QCOMPARE(editor.map()[5], 2);
    QCOMPARE(editor.map()[8], 1);
    QCOMPARE(editor.map()[9], 1);
  }

  void fills_equal_the_core_and_reach_the_model() {
    ProjectDocument doc;
    doc.open(kBlock);
    PartitionEditor editor(&doc);
    QVERIFY(editor.fill(QStringLiteral("4x2")).isEmpty());
    const std::shared_ptr<const Model> model = doc.model();
    QVERIFY(model);
    const Mesh& mesh = model->bodies[0].mesh;
    QCOMPARE(editor.map(), make_partition(mesh, parse_partition_spec("4x2")).element_subdomain);
    QVERIFY(editor.fill(QStringLiteral("metis:6")).isEmpty());
    QCOMPARE(editor.map(), make_partition(mesh, parse_partition_spec("metis:6")).element_subdomain);
    QVERIFY(editor.fill(QStringLiteral("4y")).startsWith(QStringLiteral("partition")));  // the core's message
    QVERIFY(editor.flush().isEmpty());
    QCOMPARE(doc.document()["bodies"][0]["partition_map"].get<std::vector<int>>(), editor.map());
    QVERIFY(!doc.document()["bodies"][0].contains("partition"));
    QVERIFY(wait_model(doc));
    QCOMPARE(doc.model()->bodies[0].partition.element_subdomain, editor.map());
    QCOMPARE(editor.undo_stack()->count(), 2);  // the rebuilt model is ours: the history stays
    editor.undo_stack()->undo();
    QCOMPARE(editor.map(), make_partition(mesh, parse_partition_spec("4x2")).element_subdomain);
  }

  void painted_rolling_slab_saves_and_opens() {
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("painted.json"));
    std::vector<int> painted;
    {
      ProjectDocument doc;
      doc.load_default();
      PartitionEditor editor(&doc);
      QCOMPARE(editor.bodies(), QStringList({QStringLiteral("slab"), QStringLiteral("roll")}));
      editor.set_current_subdomain(1);
      std::vector<int> half;
      for (int e = 0; e < static_cast<int>(editor.map().size()) / 2; ++e) half.push_back(e);
      QVERIFY(editor.paint(half));
      QVERIFY(editor.flush().isEmpty());
      QVERIFY(doc.document()["process"].contains("slab_partition_map"));
      painted = editor.map();
      doc.save_as(file);
    }
    ProjectDocument reopened;
    reopened.open(file);
    PartitionEditor editor(&reopened);
    QCOMPARE(editor.map(), painted);
    QCOMPARE(editor.subdomain_count(), 2);
  }
};

QTEST_GUILESS_MAIN(TestPartitionEditor)
#include "test_partition_editor.moc"
