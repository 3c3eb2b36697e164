// rollsim_gui_paint_bench — the time of one paint step in the real window (issue 6: "a paint stroke on a 1e5-cell
// slab updates colours and the partition table in under 100 ms"): the generated slab of the paper's rolling pass
// meshed with ~1e5 hexahedra, split 4x2x1, then brush steps at points across the view, each timed from the pointer
// position to the rendered frame: pick (cells under the brush, through the depth), map update with undo step,
// partition table (core PartitionReporter), colours and render. Markdown on stdout. Needs a display (xvfb-run).
// Usage: xvfb-run -a rollsim_gui_paint_bench [--steps N] [--radius PX] [--nx N --nt N --nw N]
#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "MainWindow.h"
#include "MeshView.h"
#include "PartitionEditor.h"
#include "PartitionPanel.h"
#include "PartitionTable.h"
#include "ProjectDocument.h"

using namespace rollsim::ui;

namespace {
struct Options {
  int steps = 30, radius = 25, nx = 200, nt = 20, nw = 25;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i];
    const int v = std::atoi(argv[i + 1]);
    if (k == "--steps") o.steps = v;
    if (k == "--radius") o.radius = v;
    if (k == "--nx") o.nx = v;
    if (k == "--nt") o.nt = v;
    if (k == "--nw") o.nw = v;
  }
  return o;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}
}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  QTemporaryDir dir;
  nlohmann::json project = {
      {"name", "paint-bench"},
      {"dimension", 3},
      {"process", {{"type", "rolling"}, {"slab_nx", o.nx}, {"slab_nt", o.nt}, {"slab_nw", o.nw}}}};
  const QString file = dir.filePath(QStringLiteral("paint.json"));
  QFile f(file);
  if (!f.open(QIODevice::WriteOnly)) return 1;
  f.write(QByteArray::fromStdString(project.dump()));
  f.close();

  MainWindow w;
  w.resize(1280, 800);
  QElapsedTimer clock;
  clock.start();
  if (!w.open_file(file)) return 1;
  const double open_ms = static_cast<double>(clock.elapsed());
  w.show();
  if (!QTest::qWaitForWindowExposed(&w)) return 1;
  w.show_partitions();
  PartitionEditor* editor = w.partition_editor();
  MeshView* view = w.view();
  const long cells = static_cast<long>(editor->map().size());
  clock.restart();
  editor->fill(QStringLiteral("4x2x1"));
  QCoreApplication::processEvents();
  view->render_now();
  const double fill_ms = static_cast<double>(clock.elapsed());

  view->set_paint_tool(PaintTool::Brush);
  view->set_brush_radius(o.radius);
  std::vector<double> pick, update, total, render;
  std::vector<int> painted;
  const std::vector<QPointF> centres = view->projected_centres(0);  // brush steps over slab cells on screen
  for (int s = 0; s < o.steps; ++s) {
    const QPoint at = centres[static_cast<size_t>(s) * centres.size() / static_cast<size_t>(o.steps)].toPoint();
    editor->set_current_subdomain(s % 8);
    QElapsedTimer t;
    t.start();
    const std::vector<int> under = view->cells_in_circle(0, at, o.radius);
    const double picked = static_cast<double>(t.nsecsElapsed()) / 1e6;
    editor->paint(under, editor->next_stroke());  // mapChanged: view colours and render, partition table
    const double all = static_cast<double>(t.nsecsElapsed()) / 1e6;
    t.restart();
    view->render_now();  // for scale: a frame alone, nothing changed
    render.push_back(static_cast<double>(t.nsecsElapsed()) / 1e6);
    pick.push_back(picked);
    update.push_back(all - picked);
    total.push_back(all);
    painted.push_back(static_cast<int>(under.size()));
  }
  std::printf(
      "| slab cells | brush | cells per step (median) | open project [ms] | fill 4x2x1 [ms] | pick [ms] | "
      "map + table + colours + render [ms] | whole step [ms] (median, max) | a frame alone [ms] |\n");
  std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  std::vector<double> counts(painted.begin(), painted.end());
  std::printf("| %ld | %d px | %.0f | %.0f | %.0f | %.1f | %.1f | %.1f, %.1f | %.1f |\n", cells, o.radius,
              median(counts), open_ms, fill_ms, median(pick), median(update), median(total),
              *std::max_element(total.begin(), total.end()), median(render));
  // the parts of an update, each alone: colours (+ frame) and table
  std::vector<double> colours, table;
  for (int s = 0; s < 5; ++s) {
    QElapsedTimer t;
    t.start();
    view->set_partition(0, editor->map());
    colours.push_back(static_cast<double>(t.nsecsElapsed()) / 1e6);
    t.restart();
    w.partition_panel()->table()->show_map(editor->model(), 0, editor->map());
    table.push_back(static_cast<double>(t.nsecsElapsed()) / 1e6);
  }
  std::printf("\nAlone: colours + frame %.1f ms, partition table (nothing changed) %.1f ms\n", median(colours),
              median(table));
  std::printf("\nPartition table after the strokes: %s\n",
              w.partition_panel()->table()->verdict().toStdString().c_str());
  return 0;
}
