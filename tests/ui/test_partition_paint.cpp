// Painting partitions in the real window under Xvfb: a brush stroke and a rubber-band box on the VTK view assign
// the current subdomain to the cells under them (through VTK's camera transform; the visible-cells mode through
// VTK's hardware selector), the view shows the subdomain colour where painted and the original colour elsewhere,
// and undo restores both.
#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

#include "MainWindow.h"
#include "MeshView.h"
#include "PartitionEditor.h"

using namespace rollsim;
using namespace rollsim::ui;

namespace {
// a beam of 40 x 10 cells: cells of ~20 px on screen, so that pixels at a cell centre show its colour, not an edge
const char* kBeam = R"({"name": "beam", "dimension": 2, "materials": [{"name": "m", "E": 1000, "nu": 0.3}],
  "bodies": [{"name": "beam", "material": "m", "mesh": {"type": "block", "nx": 40, "ny": 10, "lx": 40, "ly": 10}}],
  "boundary_conditions": [{"type": "displacement", "body": "beam", "set": "xmin", "ux": 0, "uy": 0},
                          {"type": "displacement", "body": "beam", "set": "xmax", "uy": 1}]})";

/// Whether most pixels of the 9 x 9 patch around `p` have colour `c` (cell edges are drawn in dark grey).
bool shows(const QImage& image, QPoint p, const QColor& c) {
  int match = 0;
  for (int dy = -4; dy <= 4; ++dy)
    for (int dx = -4; dx <= 4; ++dx) {
      const QColor got = image.pixelColor(p + QPoint(dx, dy));
      match += std::hypot(got.red() - c.red(), got.green() - c.green(), got.blue() - c.blue()) < 30;
    }
  return match > 40;
}

QImage view_image(MeshView* view) {
  view->render_now();
  return view->grabFramebuffer().scaled(view->size());
}

int painted_count(const PartitionEditor* editor, int id) {
  return static_cast<int>(std::count(editor->map().begin(), editor->map().end(), id));
}
}  // namespace

class TestPartitionPaint : public QObject {
  Q_OBJECT

 private slots:
  void brush_and_box_paint_where_the_pointer_is() {
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("beam.json"));
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(kBeam);
    f.close();
    MainWindow w;
    QVERIFY(w.open_file(file));
    w.resize(1280, 800);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    MeshView* view = w.view();
    PartitionEditor* editor = w.partition_editor();
    QCOMPARE(editor->body(), 0);
    editor->set_current_subdomain(3);
    view->set_paint_tool(PaintTool::Brush);
    view->set_brush_radius(15);
    view->set_partition(0, editor->map());  // colour by subdomain, all 0
    const QPoint centre = view->rect().center();
    const QPoint left = centre - QPoint(view->width() / 4, 0);
    QImage before = view_image(view);
    const QColor zero = category_color(0);
    QVERIFY2(shows(before, centre, zero), "the beam is drawn in subdomain 0's colour");
    QVERIFY2(shows(before, left, zero), "the beam is drawn in subdomain 0's colour");

    QTest::mousePress(view, Qt::LeftButton, {}, centre);
    for (int dx = 5; dx <= 40; dx += 5) {  // a drag: moves with the button held (QTest::mouseMove sends none)
      QMouseEvent move(QEvent::MouseMove, centre + QPoint(dx, 0), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
      QApplication::sendEvent(view, &move);
    }
    QTest::mouseRelease(view, Qt::LeftButton, {}, centre + QPoint(40, 0));
    const int stroke_cells = painted_count(editor, 3);
    QVERIFY2(stroke_cells > 20, qPrintable(QStringLiteral("%1 cells painted").arg(stroke_cells)));
    QCOMPARE(editor->undo_stack()->count(), 1);  // one drag, one undo step
    // every painted cell lies under the stroke (its centre within the brush of some point of the drag)
    QImage after = view_image(view);
    QVERIFY2(shows(after, centre + QPoint(20, 0), category_color(3)), "painted colour along the stroke");
    QVERIFY2(shows(after, left, zero), "the rest keeps its colour");

    view->set_paint_tool(PaintTool::Box);
    editor->set_current_subdomain(1);
    QTest::mousePress(view, Qt::LeftButton, {}, left - QPoint(30, 30));
    QMouseEvent move(QEvent::MouseMove, left, Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(view, &move);
    QTest::mouseRelease(view, Qt::LeftButton, {}, left + QPoint(30, 30));
    const int box_cells = painted_count(editor, 1);
    QVERIFY2(box_cells > 20, qPrintable(QStringLiteral("%1 cells in the box").arg(box_cells)));
    after = view_image(view);
    QVERIFY(shows(after, left, category_color(1)));

    // the visible-cells mode (hardware selection) picks the same cells on a flat 2D mesh
    view->set_paint_through(false);
    const QRect box(centre - QPoint(30, 20), centre + QPoint(30, 20));
    std::vector<int> through_cells, visible = view->cells_in_box(0, box);
    view->set_paint_through(true);
    through_cells = view->cells_in_box(0, box);
    QVERIFY(!visible.empty());
    std::vector<int> common;
    std::set_intersection(visible.begin(), visible.end(), through_cells.begin(), through_cells.end(),
                          std::back_inserter(common));
    QVERIFY2(common.size() >= through_cells.size() * 9 / 10,
             qPrintable(QStringLiteral("visible %1, through %2, common %3")
                            .arg(visible.size())
                            .arg(through_cells.size())
                            .arg(common.size())));

    editor->undo_stack()->undo();
    editor->undo_stack()->undo();
    QCOMPARE(painted_count(editor, 0), static_cast<int>(editor->map().size()));
    after = view_image(view);
    QVERIFY(shows(after, centre + QPoint(20, 0), zero));
    QVERIFY(shows(after, left, zero));
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  TestPartitionPaint test;
  return QTest::qExec(&test, argc, argv);
}

#include "test_partition_paint.moc"
