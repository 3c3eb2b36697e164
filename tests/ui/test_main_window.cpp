// The whole window under Xvfb: the view draws the project's meshes, an edit in the property editor updates the
// status-bar counts and the view, a run from the Run button converges and colours the view by displacement,
// Cancel ends a run "cancelled", the window's screenshot is not blank, and after a run of three load increments the
// view toolbar's increment selector offers 1…3 and recolours the view with the chosen increment's fields; after a
// Newton run of a plastic block the view colours its elements by equivalent plastic strain and the log says which
// groups each iteration refactored and why; a rolling pass plots its roll force and torque as it runs, and the arc.
// A typed value that validation refuses stays in its field with its message under it, and Save and Run are refused
// until it is corrected: the window never writes a value the user did not type (the prefix 0.9 of a refused 0.95).
// Before a run the bottom dock shows the forecast: the pass in mill terms (bite angle, contact length, whether it
// bites, its speed) and the predicted cost, rebuilt with every edit; a run turns it to the convergence plots.
#include <QVTKOpenGLNativeWidget.h>
#include <QApplication>
#include <QChartView>
#include <QFile>
#include <QLabel>
#include <QLegend>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QSurfaceFormat>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "ForecastPanel.h"
#include "LogPanel.h"
#include "MainWindow.h"
#include "MeshView.h"
#include "ProcessPlot.h"
#include "ProjectDocument.h"
#include "ProjectTreePanel.h"
#include "PropertyEditor.h"
#include "ResidualPlot.h"
#include "RunPanel.h"
#include "RunPlots.h"

using namespace rollsim;
using namespace rollsim::ui;

namespace {
const QString kSample = QStringLiteral(ROLLSIM_SOURCE_DIR "/samples/plate-hole-2d.json");
const QString kPass = QStringLiteral(ROLLSIM_SOURCE_DIR "/samples/rolling-2d-36x6.json");

/// Standard deviation of the grey level: a blank (one-colour) image has none.
double grey_spread(const QImage& image) {
  double sum = 0, sum2 = 0;
  long n = 0;
  for (int y = 0; y < image.height(); y += 2)
    for (int x = 0; x < image.width(); x += 2) {
      const double g = qGray(image.pixel(x, y));
      sum += g;
      sum2 += g * g;
      ++n;
    }
  const double mean = sum / static_cast<double>(n);
  return std::sqrt(std::max(0.0, sum2 / static_cast<double>(n) - mean * mean));
}

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}
}  // namespace

class TestMainWindow : public QObject {
  Q_OBJECT

 private slots:
  void shows_the_project_and_its_counts() {
    MainWindow w;
    QVERIFY(w.open_file(kSample));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QCOMPARE(w.view()->drawn_cells(), 32L * 24);
    QVERIFY(w.counts_text().startsWith(QStringLiteral("nodes 825 · elements 768 · dofs ")));
    QVERIFY(w.windowTitle().startsWith(QStringLiteral("plate-hole-2d.json")));
  }

  void a_generated_pass_says_where_its_bodies_come_from() {
    // issue 36: the tree showed "materials (0)", "bodies (0)" for the rolling pass, whose process generates them
    MainWindow w;
    w.new_project();
    QStringList sections;
    for (int i = 0; i < w.tree()->topLevelItem(0)->childCount(); ++i)
      sections << w.tree()->topLevelItem(0)->child(i)->text(0);
    QVERIFY2(sections.contains(QStringLiteral("bodies (0 + 2 from the process)")), qPrintable(sections.join(", ")));
    QVERIFY2(sections.contains(QStringLiteral("materials (0 + 2 from the process)")), qPrintable(sections.join(", ")));
    QVERIFY2(sections.contains(QStringLiteral("probes (0)")), qPrintable(sections.join(", ")));
  }

  void the_forecast_shows_the_pass_in_mill_terms_before_it_runs() {
    // issue 36 item 4: bite angle, contact length, whether it bites, speed and the predicted cost, before running
    MainWindow w;
    w.new_project();
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    auto* tabs = w.findChild<QTabWidget*>(QStringLiteral("bottomTabs"));
    QCOMPARE(tabs->currentWidget(), static_cast<QWidget*>(w.forecast()));
    auto row = [&](const QString& name) {
      QTableWidget* t = w.forecast()->facts();
      for (int r = 0; r < t->rowCount(); ++r)
        if (t->item(r, 0)->text() == name) return t->item(r, 1)->text();
      return QString();
    };
    QCOMPARE(row(QStringLiteral("bite angle")), QStringLiteral("12.04°"));
    QCOMPARE(row(QStringLiteral("contact length")), QStringLiteral("62.9 mm"));
    QCOMPARE(row(QStringLiteral("bites")), QStringLiteral("yes"));
    QVERIFY(row(QStringLiteral("mean strain rate")).isEmpty());
    QVERIFY2(w.forecast()->headline().contains(QStringLiteral("120 increments, about")),
             qPrintable(w.forecast()->headline()));
    // edits rebuild the model, and the forecast with it
    QSignalSpy rebuilt(w.document(), &ProjectDocument::modelChanged);
    QVERIFY(w.document()->propose("/process/roll_speed", 60.0).empty());
    QVERIFY(rebuilt.wait(10000));
    QCOMPARE(row(QStringLiteral("roll surface speed")), QStringLiteral("1.88 m/s"));
    QVERIFY(w.document()->propose({{"/process/friction", "coulomb"}, {"/process/friction_coefficient", 0.1}}).empty());
    QVERIFY(rebuilt.wait(10000));
    QCOMPARE(row(QStringLiteral("bites")), QStringLiteral("no"));
    QVERIFY2(w.forecast()->headline().contains(QStringLiteral("nothing will be solved")),
             qPrintable(w.forecast()->headline()));
  }

  void editing_a_count_regenerates_the_mesh() {
    MainWindow w;
    QVERIFY(w.open_file(kSample));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.tree()->select("/bodies/0");
    auto* line = qobject_cast<QLineEdit*>(w.property_editor()->editor_for("/bodies/0/mesh/n_radial"));
    QVERIFY(line);
    line->setFocus();
    line->selectAll();
    QTest::keyClicks(line, QStringLiteral("12"));
    QCOMPARE(w.document()->document()["bodies"][0]["mesh"]["n_radial"].get<int>(), 12);
    QTRY_COMPARE_WITH_TIMEOUT(w.view()->drawn_cells(), 32L * 12, 10000);
    QVERIFY(w.counts_text().startsWith(QStringLiteral("nodes 429 · elements 384")));
    QVERIFY(w.isWindowModified());
    // a refused value leaves counts and view alone
    line->selectAll();
    QTest::keyClicks(line, QStringLiteral("0"));
    QVERIFY(w.property_editor()->message().contains(QStringLiteral("must be a positive integer, got 0")));
    QTest::qWait(100);
    QCOMPARE(w.view()->drawn_cells(), 32L * 12);
  }

  void a_refused_value_blocks_save_and_run_until_corrected() {
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("pass.json"));
    QVERIFY(QFile::copy(kPass, file));
    const std::string before = read_all(file.toStdString());
    MainWindow w;
    QVERIFY(w.open_file(file));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.tree()->select("/process");
    auto* line = qobject_cast<QLineEdit*>(w.property_editor()->editor_for("/process/reduction"));
    QVERIFY(line);
    line->setFocus();
    QTest::keyClicks(line, QStringLiteral("0.95"));  // 0, 0., 0.9 accepted on the way; 0.95 refused (at most 0.9)
    QCOMPARE(line->text(), QStringLiteral("0.95"));
    const QString why = w.property_editor()->message_for("/process/reduction");
    QVERIFY2(why.startsWith(QStringLiteral("process.reduction: ")), qPrintable(why));
    QVERIFY(!w.run_panel()->run_button()->isEnabled());
    QVERIFY(!w.save());
    QCOMPARE(read_all(file.toStdString()), before);  // nothing written: not the prefix 0.9
    QVERIFY(!w.start_run());
    QCOMPARE(w.run_status(), QStringLiteral("not run"));
    w.tree()->select("");  // away and back: the typed value and its message are still there
    w.tree()->select("/process");
    line = qobject_cast<QLineEdit*>(w.property_editor()->editor_for("/process/reduction"));
    QCOMPARE(line->text(), QStringLiteral("0.95"));
    QCOMPARE(w.property_editor()->message_for("/process/reduction"), why);
    line->setFocus();
    line->selectAll();
    QTest::keyClicks(line, QStringLiteral("0.2"));
    QVERIFY(w.property_editor()->message_for("/process/reduction").isEmpty());
    QVERIFY(w.run_panel()->run_button()->isEnabled());
    QVERIFY(w.save());
    nlohmann::json expected = nlohmann::json::parse(before);
    expected["process"]["reduction"] = 0.2;  // the saved file differs from the sample by what was typed, only
    QCOMPARE(nlohmann::json::parse(read_all(file.toStdString())), expected);
  }

  void run_button_converges_and_shows_results() {
    MainWindow w;
    QVERIFY(w.open_file(kSample));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QSignalSpy finished(w.worker(), &AnalysisWorker::finished);
    QTest::mouseClick(w.run_panel()->run_button(), Qt::LeftButton);
    QCOMPARE(w.run_status(), QStringLiteral("running"));
    QVERIFY(!w.run_panel()->run_button()->isEnabled());
    QVERIFY(finished.wait(60000));
    QCOMPARE(w.run_status(), QStringLiteral("converged"));
    QVERIFY(w.view()->has_results());
    QCOMPARE(w.view()->color_by(), color_by::Displacement);
    QVERIFY(w.run_panel()->run_button()->isEnabled());
    w.view()->set_color_by(color_by::VonMises);
    w.view()->set_deformation_scale(w.view()->suggested_deformation_scale());
    QVERIFY(w.view()->suggested_deformation_scale() > 1);
    QTemporaryDir dir;
    const auto vtu = dir.filePath(QStringLiteral("r.vtu")).toStdString();
    w.view()->export_vtu(vtu);
    QVERIFY(QFileInfo::exists(QString::fromStdString(vtu)));
    const QImage shot = w.screenshot();
    QCOMPARE(shot.size(), w.size());
    QVERIFY2(grey_spread(shot) > 10, "the window screenshot is blank");
  }

  void contact_pressure_colouring_needs_contact_results() {
    MainWindow w;
    QVERIFY(w.open_file(QStringLiteral(ROLLSIM_SOURCE_DIR "/samples/cylinder-indent-2d.json")));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(!w.view()->can_color_by(color_by::ContactPressure));  // no results yet
    QSignalSpy finished(w.worker(), &AnalysisWorker::finished);
    QVERIFY(w.start_run());
    QVERIFY(finished.wait(60000));
    QCOMPARE(w.run_status(), QStringLiteral("converged"));
    w.view()->set_color_by(color_by::ContactPressure);
    QCOMPARE(w.view()->color_by(), color_by::ContactPressure);
    // a model without contacts has no pressure to show: the view keeps a colouring it can draw
    QVERIFY(w.open_file(kSample));
    QVERIFY(w.start_run());
    QVERIFY(finished.wait(60000));
    QVERIFY(!w.view()->can_color_by(color_by::ContactPressure));
    w.view()->set_color_by(color_by::ContactPressure);
    QCOMPARE(w.view()->color_by(), color_by::Body);
  }

  void plastic_strain_colouring_after_a_newton_run() {
    // a plastic block squeezed 2 % in 4 increments: a cell field, coloured on the element faces
    const nlohmann::json project = {
        {"name", "squeeze"},
        {"dimension", 2},
        {"materials", {{{"name", "steel"}, {"E", 200e3}, {"nu", 0.3}, {"yield_stress", 250.0}}}},
        {"bodies",
         {{{"name", "block"},
           {"material", "steel"},
           {"formulation", "bbar"},
           {"mesh", {{"type", "block"}, {"nx", 8}, {"ny", 8}, {"lx", 10.0}, {"ly", 10.0}}}}}},
        {"boundary_conditions",
         {{{"type", "displacement"}, {"body", "block"}, {"set", "ymin"}, {"ux", 0.0}, {"uy", 0.0}},
          {{"type", "displacement"}, {"body", "block"}, {"set", "ymax"}, {"uy", -0.2}}}},
        {"analysis", {{"increments", 4}}}};
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("squeeze.json"));
    std::ofstream(file.toStdString()) << project.dump(1);
    MainWindow w;
    QVERIFY(w.open_file(file));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    const ColorBy plastic = QStringLiteral("plastic_strain");
    QVERIFY(!w.view()->can_color_by(plastic));  // no results yet
    QSignalSpy finished(w.worker(), &AnalysisWorker::finished);
    QVERIFY(w.start_run());
    QVERIFY(finished.wait(60000));
    QCOMPARE(w.run_status(), QStringLiteral("converged"));
    // the log tells, iteration by iteration, which groups were refactored and why
    const QString log = w.log()->toPlainText();
    QVERIFY2(log.contains(QStringLiteral("increment 1, iteration 1: block refactored (first)")), qPrintable(log));
    QVERIFY2(log.contains(QStringLiteral("block refactored (always)")), qPrintable(log));
    QVERIFY(w.view()->can_color_by(plastic));
    w.view()->set_color_by(plastic);
    QCOMPARE(w.view()->color_by(), plastic);
    QVERIFY2(grey_spread(w.screenshot()) > 10, "the window screenshot is blank");
  }

  void rolling_pass_plots_force_torque_and_the_arc() {
    // the window's default project, the paper's pass, over its first 6 mm (the whole 120 mm takes 20 s): the
    // force/torque chart grows with every increment while it runs, and shows every increment and the arc once it ends
    MainWindow w;
    w.new_project();
    QVERIFY(w.document()->propose("/process/travel", 6.0).empty());
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    ProcessPlot* rolling = w.plot()->process_plot();
    QVERIFY(!rolling->isVisible());  // nothing yet
    QSignalSpy begun(w.worker(), &AnalysisWorker::measuresBegun);
    QSignalSpy live(w.worker(), &AnalysisWorker::measured);
    QSignalSpy finished(w.worker(), &AnalysisWorker::finished);
    QVERIFY(w.start_run());
    // the bottom dock turns from the forecast to the convergence plots
    QCOMPARE(w.findChild<QTabWidget*>(QStringLiteral("bottomTabs"))->currentWidget(), static_cast<QWidget*>(w.plot()));
    QVERIFY(finished.wait(60000));
    QCOMPARE(w.run_status(), QStringLiteral("converged"));
    QVERIFY(live.count() >= 5);  // every increment but the last, as it completed
    QCOMPARE(begun.count(), 1);  // the columns: travel, roll force, torque, with their units
    const auto columns = begun.at(0).at(0).value<MeasureTable>();
    QCOMPARE(columns.columns.size(), size_t{3});
    QCOMPARE(QString::fromStdString(columns.columns[1].name), QStringLiteral("roll_force"));
    QCOMPARE(QString::fromStdString(columns.columns[1].unit), QStringLiteral("N/mm (per unit width)"));
    for (const QList<QVariant>& args : live) {
      const auto row = args.at(0).value<QVector<double>>();
      QCOMPARE(row.size(), 3);
      QVERIFY(row[0] > 0 && row[0] < 6);  // travel [mm]
      QVERIFY(row[1] > 4000);             // roll force [N/mm]
    }
    const auto outcome = finished.takeFirst().at(0).value<RunOutcome>();
    QVERIFY(rolling->isVisible());
    QCOMPARE(rolling->increments(), static_cast<int>(outcome.results->process->table("rolling")->rows.size()));
    QCOMPARE(rolling->increments(), live.count() + 1);
    QVERIFY(rolling->findChild<QWidget*>(QStringLiteral("processProfile"))->isVisible());
    // the legend in full under the title (Qt's one-row legend elided "roll …", "Sim…" at 1280 × 800)
    auto* history = rolling->findChild<QtCharts::QChartView*>(QStringLiteral("processHistory"));
    QVERIFY(!history->chart()->legend()->isVisible());
    for (const char* name : {"roll force", "torque", "Sims's force", "Sims's torque"})
      QVERIFY2(history->chart()->title().contains(QString::fromUtf8(name)), qPrintable(history->chart()->title()));
    // the results open as a rolling engineer reads them: deformed ×1, by plastic strain, on the roll gap
    QCOMPARE(w.view()->color_by(), QStringLiteral("plastic_strain"));
    QCOMPARE(w.view()->deformation_scale(), 1.0);
    QVERIFY(w.view()->framed());
    const double contact = std::sqrt(300.0 * 13.2);  // √(R Δh) of the default pass
    QCOMPARE((*w.view()->framed())[0], -2 * contact);
    w.view()->reset_camera();
    QVERIFY(!w.view()->framed());
    w.plot()->clear();
    QVERIFY(!rolling->isVisible());
  }

  void cancel_ends_the_run_cancelled() {
    MainWindow w;
    QVERIFY(w.open_file(kSample));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QSignalSpy finished(w.worker(), &AnalysisWorker::finished);
    connect(
        w.worker(), &AnalysisWorker::stageStarted, this,
        [&w](const QString& stage) {
          if (stage == QLatin1String("assemble")) w.worker()->cancel();
        },
        Qt::DirectConnection);
    QVERIFY(w.start_run());
    QVERIFY(finished.wait(60000));
    QCOMPARE(w.run_status(), QStringLiteral("cancelled"));
    QVERIFY(!w.view()->has_results());
    QCOMPARE(w.view()->drawn_cells(), 32L * 24);  // the mesh is still shown
    QVERIFY(w.run_panel()->run_button()->isEnabled());
  }
  void increment_selector_steps_through_a_three_increment_run() {
    // the Hertz sample, coarse (mesh size about 0.04 near the contact), in three load increments
    std::ifstream in(ROLLSIM_SOURCE_DIR "/samples/cylinder-indent-2d.json");
    nlohmann::json j = nlohmann::json::parse(in);
    j["bodies"][0]["mesh"]["nx"] = 38;
    j["bodies"][0]["mesh"]["ny"] = 38;
    j["bodies"][1]["mesh"]["n_around"] = 39;
    j["bodies"][1]["mesh"]["n_radial"] = 22;
    j["boundary_conditions"][3]["fy"] = -2.16 / 23;
    j["analysis"] = {{"increments", 3}};
    QTemporaryDir dir;
    const QString file = dir.filePath(QStringLiteral("hertz-3.json"));
    std::ofstream(file.toStdString()) << j.dump(2);
    MainWindow w;
    QVERIFY(w.open_file(file));
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    auto* selector = w.findChild<QSpinBox*>(QStringLiteral("incrementSelector"));
    QVERIFY(selector);
    QVERIFY(!selector->isVisible());  // no results yet
    QSignalSpy finished(w.worker(), &AnalysisWorker::finished);
    QVERIFY(w.start_run());
    QVERIFY(finished.wait(60000));
    QCOMPARE(w.run_status(), QStringLiteral("converged"));
    QCOMPARE(w.view()->increment_count(), 3);
    QCOMPARE(selector->maximum(), 3);
    QTRY_VERIFY(selector->isVisible());  // the toolbar lays its widgets out on the next event loop pass
    QCOMPARE(selector->minimum(), 1);
    QCOMPARE(selector->maximum(), 3);
    QCOMPARE(selector->value(), 3);
    QCOMPARE(w.view()->color_by(), color_by::Displacement);
    const double full = w.view()->color_range()[1];
    selector->setValue(1);
    QCOMPARE(w.view()->increment(), 0);
    const double first = w.view()->color_range()[1];
    QVERIFY2(first < 0.9 * full, "increment 1 shows a smaller |u| range than the last");
    selector->setFocus();
    QTest::keyClick(selector, Qt::Key_Up);  // keyboard: one increment on
    QCOMPARE(w.view()->increment(), 1);
    const double second = w.view()->color_range()[1];
    QVERIFY(second > first && second < full);
    QTemporaryDir out;
    const auto pvd = out.filePath(QStringLiteral("run.pvd")).toStdString();
    w.view()->export_pvd(pvd);
    QVERIFY(QFileInfo::exists(out.filePath(QStringLiteral("run_0003.vtu"))));
    QVERIFY(read_all(pvd).find("timestep=\"1\"") != std::string::npos);
    // a run of one increment hides the selector again
    QVERIFY(w.open_file(kSample));
    QVERIFY(w.start_run());
    QVERIFY(finished.wait(60000));
    QTRY_VERIFY(!selector->isVisible());
  }
};

int main(int argc, char** argv) {
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  TestMainWindow test;
  return QTest::qExec(&test, argc, argv);
}

#include "test_main_window.moc"
