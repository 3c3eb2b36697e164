// The schema-driven property editor: typing a value updates the project and the mesh counts, a bad value is refused
// with the validator's message and the project keeps its old value, the solver form lists the registry's names; a
// hot pass's flow stress law is edited in the process form like any field, its range refused there.
#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QtTest>

#include "ProjectDocument.h"
#include "ProjectTreePanel.h"
#include "PropertyEditor.h"
#include "RunPanel.h"
#include "SchemaFields.h"
#include "project/ProjectSchema.h"
#include "solve/SolverStrategy.h"

using namespace rollsim;
using namespace rollsim::ui;

namespace {
const QString kSample = QStringLiteral(ROLLSIM_SOURCE_DIR "/samples/plate-hole-2d.json");

void retype(QLineEdit* line, const QString& text) {
  line->setFocus();
  line->selectAll();
  QTest::keyClick(line, Qt::Key_Backspace);
  QTest::keyClicks(line, text);
}
}  // namespace

class TestPropertyEditor : public QObject {
  Q_OBJECT

 private slots:
  void typing_updates_project_and_mesh_counts() {
    ProjectDocument doc;
    doc.open(kSample);
    PropertyEditor editor(&doc);
    editor.set_object("/bodies/0");
    editor.show();
    auto* line = qobject_cast<QLineEdit*>(editor.editor_for("/bodies/0/mesh/n_radial"));
    QVERIFY(line);
    QCOMPARE(line->text(), QStringLiteral("24"));
    QSignalSpy built(&doc, &ProjectDocument::modelChanged);
    retype(line, QStringLiteral("16"));
    QCOMPARE(doc.document()["bodies"][0]["mesh"]["n_radial"].get<int>(), 16);
    QVERIFY(editor.message().isEmpty());
    QCOMPARE(line->text(), QStringLiteral("16"));
    while (doc.counts().elements != 32L * 16) QVERIFY(built.wait(10000));  // "1" then "16" were both valid
    QCOMPARE(doc.counts().nodes, 33L * 17);
  }

  void bad_value_is_refused_with_the_validation_message() {
    ProjectDocument doc;
    doc.open(kSample);
    PropertyEditor editor(&doc);
    editor.set_object("/bodies/0");
    editor.show();
    auto* line = qobject_cast<QLineEdit*>(editor.editor_for("/bodies/0/mesh/n_radial"));
    QSignalSpy refused(&editor, &PropertyEditor::refused);
    retype(line, QStringLiteral("-3"));
    QVERIFY(refused.count() >= 1);
    QCOMPARE(editor.message(), QStringLiteral("bodies[0].mesh.n_radial: must be a positive integer, got -3"));
    QCOMPARE(line->text(), QStringLiteral("-3"));  // what was typed stays, marked
    QVERIFY(!line->styleSheet().isEmpty());
    QCOMPARE(doc.document()["bodies"][0]["mesh"]["n_radial"].get<int>(), 24);
    QVERIFY(!doc.modified());
    // a cross-field rule from the model builder's checks
    auto* around = qobject_cast<QLineEdit*>(editor.editor_for("/bodies/0/mesh/n_around"));
    retype(around, QStringLiteral("33"));
    QVERIFY(editor.message().startsWith(QStringLiteral("bodies[0].mesh.n_around")));
    QCOMPARE(doc.document()["bodies"][0]["mesh"]["n_around"].get<int>(), 32);
    // a good value clears the message
    retype(around, QStringLiteral("30"));
    QVERIFY(editor.message().isEmpty());
    QCOMPARE(doc.document()["bodies"][0]["mesh"]["n_around"].get<int>(), 30);
  }

  void form_follows_the_schema_variant() {
    ProjectDocument doc;
    doc.open(kSample);
    PropertyEditor editor(&doc);
    editor.set_object("/bodies/0");
    QVERIFY(editor.editor_for("/bodies/0/mesh/radius"));
    QVERIFY(editor.editor_for("/bodies/0/formulation"));
    auto* type = qobject_cast<QComboBox*>(editor.editor_for("/bodies/0/mesh/type"));
    QVERIFY(type);
    QCOMPARE(type->currentText(), QStringLiteral("plate_with_hole"));
    // every field of the declared schema has an editor
    const ObjectSchema* mesh = object_schema_at(doc.project().data, "/bodies/0/mesh");
    QVERIFY(mesh);
    for (const Field& f : fields_of(*mesh, doc.project().data["bodies"][0]["mesh"]))
      QVERIFY2(editor.editor_for("/bodies/0/mesh/" + f.name), f.name.c_str());
  }

  void a_hot_pass_edits_its_flow_stress_law_in_the_process_form() {
    ProjectDocument doc;
    doc.open(QStringLiteral(ROLLSIM_SOURCE_DIR "/samples/rolling-2d-hot.json"));
    PropertyEditor editor(&doc);
    editor.set_object("/process");
    editor.show();
    auto* law = qobject_cast<QComboBox*>(editor.editor_for("/process/slab_flow_stress/law"));
    QVERIFY(law);
    QCOMPARE(law->currentText(), QStringLiteral("shida"));
    auto* carbon = qobject_cast<QLineEdit*>(editor.editor_for("/process/slab_flow_stress/carbon"));
    QVERIFY(carbon);
    QCOMPARE(carbon->text(), QStringLiteral("0.2"));
    retype(carbon, QStringLiteral("0.45"));
    QVERIFY(editor.message().isEmpty());
    QCOMPARE(doc.document()["process"]["slab_flow_stress"]["carbon"].get<double>(), 0.45);
    retype(carbon, QStringLiteral("2"));  // beyond the 0.07–1.2 % Shida fitted
    QVERIFY(editor.message().startsWith(QStringLiteral("process.slab_flow_stress.carbon")));
    QCOMPARE(doc.document()["process"]["slab_flow_stress"]["carbon"].get<double>(), 0.45);
  }

  void solver_panel_lists_registry_and_writes_the_solver_section() {
    ProjectDocument doc;
    doc.open(kSample);
    RunPanel panel(&doc);
    PropertyEditor* editor = panel.solver_editor();
    auto* mode = qobject_cast<QComboBox*>(editor->editor_for("/solver/mode"));
    QVERIFY(mode);
    QStringList names;
    for (int i = 0; i < mode->count(); ++i)
      if (mode->itemData(i).isValid()) names << mode->itemData(i).toString();
    QStringList registry;  // the registry's strategies, then `auto`
    for (const auto& s : solver_mode_names()) registry << QString::fromStdString(s);
    QCOMPARE(names, registry);
    QCOMPARE(names.back(), QStringLiteral("auto"));
    QCOMPARE(mode->currentText(), QStringLiteral("direct"));
    QVERIFY(!mode->itemData(mode->findData(QStringLiteral("mixed")), Qt::ToolTipRole).toString().isEmpty());
    // every field the schema declares for `solver` appears (later fields join without code here)
    for (const Field& f : fields_of(*object_schema_at(doc.project().data, "/solver"), doc.project().data["solver"]))
      QVERIFY2(editor->editor_for("/solver/" + f.name), f.name.c_str());
    const int mixed = mode->findData(QStringLiteral("mixed"));
    mode->setCurrentIndex(mixed);
    emit mode->activated(mixed);
    QCOMPARE(doc.document()["solver"]["mode"].get<std::string>(), std::string("mixed"));
    auto* tol = qobject_cast<QLineEdit*>(editor->editor_for("/solver/cg_tolerance"));
    QVERIFY(tol);
    QCOMPARE(tol->placeholderText(), QString());  // no default: a rule (1e-4, or Newton's tolerance / 100)
    retype(tol, QStringLiteral("1e-6"));
    QCOMPARE(doc.project().data["solver"]["cg_tolerance"].get<double>(), 1e-6);
    QTest::keyClicks(tol, QStringLiteral("x"));  // "1e-6x": refused, the project keeps 1e-6
    QVERIFY(editor->message().startsWith(QStringLiteral("solver.cg_tolerance: must be a finite number")));
    QCOMPARE(doc.project().data["solver"]["cg_tolerance"].get<double>(), 1e-6);
    retype(tol, QStringLiteral("2"));  // cleared (unset, accepted), then "2" refused
    QVERIFY(editor->message().startsWith(QStringLiteral("solver.cg_tolerance: must be")));
    QVERIFY(!doc.project().data["solver"].contains("cg_tolerance"));
    QVERIFY(editor->message_for("/solver/cg_tolerance").startsWith(QStringLiteral("solver.cg_tolerance: must be")));
    QVERIFY(doc.refused_edit("/solver/cg_tolerance"));  // what blocks Save and Run
    retype(tol, QStringLiteral("1e-6"));
    QVERIFY(editor->message_for("/solver/cg_tolerance").isEmpty());
    QVERIFY(!doc.refused_edit("/solver/cg_tolerance"));
    auto* threads = qobject_cast<QLineEdit*>(editor->editor_for("/solver/threads"));
    retype(threads, QStringLiteral("2"));
    QCOMPARE(doc.document()["solver"]["threads"].get<int>(), 2);
  }

  void tree_lists_sections_and_selects_objects() {
    ProjectDocument doc;
    doc.open(kSample);
    ProjectTreePanel tree(&doc);
    PropertyEditor editor(&doc);
    connect(&tree, &ProjectTreePanel::objectSelected, &editor,
            [&editor](const QString& p) { editor.set_object(p.toStdString()); });
    tree.select("/materials/0");
    QCOMPARE(editor.object_pointer(), std::string("/materials/0"));
    QVERIFY(editor.editor_for("/materials/0/E"));
    tree.select("/boundary_conditions/2");
    QVERIFY(editor.editor_for("/boundary_conditions/2/uy"));
    // an edit keeps the selection (and the editor's focus)
    QVERIFY(doc.propose("/boundary_conditions/2/uy", 0.02).empty());
    QCOMPARE(tree.selected_pointer(), std::string("/boundary_conditions/2"));
  }

  void value_text_round_trips() {
    Field vec;
    vec.kind = Kind::Vector;
    QCOMPARE(parse_value_text(vec, QStringLiteral("1, 2.5")), json::parse("[1, 2.5]"));
    QCOMPARE(value_text(json::parse("[1, 2.5]")), QStringLiteral("1, 2.5"));
    QCOMPARE(parse_value_text(vec, QStringLiteral("1, x")), json("1, x"));
    Field num;
    num.kind = Kind::Number;
    QCOMPARE(parse_value_text(num, QStringLiteral("")), json());
    QCOMPARE(parse_value_text(num, QStringLiteral("1e-3")), json(1e-3));
    QCOMPARE(issue_path("/bodies/0/mesh/nx"), std::string("bodies[0].mesh.nx"));
    Field names;  // output.fields: the names as typed become an array, and show as typed
    names.kind = Kind::ChoiceList;
    QCOMPARE(parse_value_text(names, QStringLiteral("displacement, plastic_strain")),
             json::parse(R"(["displacement", "plastic_strain"])"));
    QCOMPARE(parse_value_text(names, QStringLiteral("[\"stress\"]")), json::parse(R"(["stress"])"));
    QCOMPARE(value_text(json::parse(R"(["displacement", "plastic_strain"])")),
             QStringLiteral("displacement, plastic_strain"));
  }
};

QTEST_MAIN(TestPropertyEditor)
#include "test_property_editor.moc"
