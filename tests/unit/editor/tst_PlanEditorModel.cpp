// The plan editor's model: edits on a mission file's plan, each checked at
// once, undone and redone, saved and read back.
#include "Paths.h"
#include "Schemas.h"
#include "plans/MissionShare.h"
#include "plans/PlanDesk.h"
#include "alarms/AlarmGraph.h"
#include "qmlmodels/ChartWatch.h"
#include "qmlmodels/PlanEditorModel.h"
#include "qmlmodels/Tracks.h"
#include "qmlmodels/VariableTreeModel.h"

#include <QFile>
#include <QJsonArray>
#include <QSignalSpy>
#include <QTest>
#include <QTemporaryDir>

#include <array>

#include <cmath>

#include <gtest/gtest.h>

using namespace Qt::StringLiterals;

namespace {

// A copy of the shipped Leixões mission to edit.
QString exampleCopy(const QTemporaryDir &dir)
{
    const QString path = dir.filePath(u"leixoes.xml"_s);
    QFile::copy(neptus::test::sourcePath(u"docs/examples/leixoes.xml"_s), path);
    QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
    return path;
}

QVariantMap byId(const QVariantList &maneuvers, const QString &id)
{
    for (const QVariant &v : maneuvers)
        if (v.toMap().value(u"id"_s) == id)
            return v.toMap();
    return {};
}

} // namespace

TEST(PlanEditor, OpensAMissionAtItsFirstPlanWithItsVehiclesManeuvers)
{
    QTemporaryDir dir;
    PlanEditorModel editor;
    editor.setMissionPath(exampleCopy(dir));
    EXPECT_EQ(editor.error(), QString());
    EXPECT_EQ(editor.planIds(), (QStringList{u"survey"_s, u"patrol"_s, u"harbour-loop"_s}));
    EXPECT_EQ(editor.planId(), u"survey"_s);
    EXPECT_EQ(editor.vehicle(), u"lauv-sim-1"_s);
    EXPECT_TRUE(editor.maneuverTypes().contains(u"Goto"_s));
    EXPECT_EQ(editor.maneuvers().size(), 4);
    EXPECT_EQ(editor.problems().size(), 0);
    EXPECT_GT(editor.statistics().value(u"length"_s).toDouble(), 500);
    // The path carries the distance along its points and the depth, for the
    // profile (the plan's length also counts a timed loiter's laps).
    double along = 0;
    for (const QVariant &p : editor.path()) {
        EXPECT_GE(p.toMap().value(u"distance"_s).toDouble(), along);
        along = p.toMap().value(u"distance"_s).toDouble();
    }
    EXPECT_NEAR(along, editor.statistics().value(u"length"_s).toDouble(), 0.05 * along);
    EXPECT_EQ(editor.path().last().toMap().value(u"zUnits"_s), u"DEPTH"_s);
    EXPECT_FALSE(editor.canUndo());
    // When the vehicle gets to each maneuver: after the loiter's minute, then the rows.
    const double wait = byId(editor.maneuvers(), u"wait"_s).value(u"arrival"_s).toDouble();
    const double rows = byId(editor.maneuvers(), u"rows"_s).value(u"arrival"_s).toDouble();
    const double surface = byId(editor.maneuvers(), u"surface"_s).value(u"arrival"_s).toDouble();
    EXPECT_EQ(byId(editor.maneuvers(), u"go"_s).value(u"arrival"_s).toDouble(), 0);
    EXPECT_GE(rows, wait + 60);
    EXPECT_GT(surface, rows);
    EXPECT_LE(surface, editor.statistics().value(u"duration"_s).toDouble());
    // The other vehicles' plans, drawn beside it.
    ASSERT_EQ(editor.otherPlans().size(), 2);
    EXPECT_EQ(editor.otherPlans()[0].toMap().value(u"vehicle"_s), u"caravela-sim"_s);
    EXPECT_EQ(editor.otherPlans()[1].toMap().value(u"vehicle"_s), u"ardurover-1"_s);
    EXPECT_GE(editor.otherPlans()[0].toMap().value(u"path"_s).toList().size(), 3);
    editor.setPlanId(u"patrol"_s);
    EXPECT_EQ(editor.otherPlans()[0].toMap().value(u"id"_s), u"survey"_s);

    PlanEditorModel missing;
    missing.setMissionPath(dir.filePath(u"none.xml"_s));
    EXPECT_TRUE(missing.error().contains(u"none.xml"_s)) << missing.error().toStdString();
}

TEST(PlanEditor, AddMoveUndoRedo)
{
    QTemporaryDir dir;
    PlanEditorModel editor;
    editor.setMissionPath(exampleCopy(dir));
    QSignalSpy edited(&editor, &PlanEditorModel::edited);
    const double length = editor.statistics().value(u"length"_s).toDouble();

    const QString id = editor.addManeuver(u"Goto"_s, 41.1720, -8.7140);
    EXPECT_EQ(id, u"goto1"_s);
    EXPECT_EQ(edited.size(), 1) << "checked at once";
    EXPECT_EQ(editor.maneuvers().size(), 5);
    const auto *plan = editor.plan();
    EXPECT_EQ(plan->transitions.last().from, u"surface"_s) << "after the plan's last maneuver";
    EXPECT_EQ(plan->transitions.last().to, id);
    EXPECT_GT(editor.statistics().value(u"length"_s).toDouble(), length);
    EXPECT_TRUE(editor.modified());

    EXPECT_TRUE(editor.moveManeuver(id, 41.1725, -8.7135));
    EXPECT_NEAR(byId(editor.maneuvers(), id).value(u"lat"_s).toDouble(), 41.1725, 1e-9);
    EXPECT_TRUE(editor.undo());
    EXPECT_NEAR(byId(editor.maneuvers(), id).value(u"lat"_s).toDouble(), 41.1720, 1e-9) << "the move undone";
    EXPECT_TRUE(editor.undo());
    EXPECT_EQ(editor.maneuvers().size(), 4) << "the add undone";
    EXPECT_FALSE(editor.canUndo());
    EXPECT_TRUE(editor.redo());
    EXPECT_TRUE(editor.redo());
    EXPECT_NEAR(byId(editor.maneuvers(), id).value(u"lat"_s).toDouble(), 41.1725, 1e-9) << "both redone";
    EXPECT_FALSE(editor.canRedo());

    EXPECT_EQ(editor.addManeuver(u"Launch"_s, 41.1700, -8.7140), QString());
    EXPECT_TRUE(editor.error().startsWith(u"lauv-sim-1 cannot do Launch"_s)) << editor.error().toStdString();
}

// Out of the vehicle's range: kept, shown on the parameter and as a problem.
TEST(PlanEditor, AParameterOutOfRangeIsAProblem)
{
    QTemporaryDir dir;
    PlanEditorModel editor;
    editor.setMissionPath(exampleCopy(dir));
    EXPECT_TRUE(editor.setParameter(u"go"_s, u"z"_s, u"500"_s));
    EXPECT_EQ(editor.errorCount(), 1);
    const QVariantMap problem = editor.problems().first().toMap();
    EXPECT_EQ(problem.value(u"maneuver"_s), u"go"_s);
    EXPECT_TRUE(problem.value(u"message"_s).toString().contains(u"z = 500 m is outside lauv-sim-1's range [0, 100]"_s))
        << problem.value(u"message"_s).toString().toStdString();
    EXPECT_EQ(byId(editor.maneuvers(), u"go"_s).value(u"severity"_s), u"error"_s) << "the marker says so";
    bool shown = false;
    for (const QVariant &p : editor.parametersOf(u"go"_s))
        if (p.toMap().value(u"name"_s) == u"z"_s)
            shown = p.toMap().value(u"value"_s) == u"500"_s && !p.toMap().value(u"problem"_s).toString().isEmpty();
    EXPECT_TRUE(shown) << "the form marks the field";
    // The problems list is said changed only when it is: views rebuild it whole.
    QSignalSpy problems(&editor, &PlanEditorModel::problemsChanged);
    EXPECT_TRUE(editor.setParameter(u"go"_s, u"speed"_s, u"1.2"_s));
    EXPECT_EQ(problems.count(), 0) << "an edit that leaves the problems as they were";
    EXPECT_TRUE(editor.undo()); // the speed
    EXPECT_EQ(problems.count(), 0);
    EXPECT_TRUE(editor.undo()); // the depth
    EXPECT_EQ(editor.errorCount(), 0);
    EXPECT_EQ(problems.count(), 1) << "its problem gone";
}

TEST(PlanEditor, RemovingAManeuverJoinsItsNeighbours)
{
    QTemporaryDir dir;
    PlanEditorModel editor;
    editor.setMissionPath(exampleCopy(dir));
    EXPECT_TRUE(editor.removeManeuver(u"wait"_s));
    const auto *plan = editor.plan();
    ASSERT_EQ(plan->transitions.size(), 2);
    EXPECT_EQ(plan->transitions[0].from, u"rows"_s);
    EXPECT_EQ(plan->transitions[1].from, u"go"_s);
    EXPECT_EQ(plan->transitions[1].to, u"rows"_s);
    EXPECT_EQ(editor.problems().size(), 0);
    EXPECT_TRUE(editor.removeManeuver(u"go"_s));
    EXPECT_EQ(editor.plan()->start, u"rows"_s) << "the start moves on";
}

TEST(PlanEditor, RowsOverADrawnAreaSavedAndReadBack)
{
    QTemporaryDir dir;
    const QString path = exampleCopy(dir);
    PlanEditorModel editor;
    editor.setMissionPath(path);
    const QVariantList area{QVariantMap{{u"lat"_s, 41.1695}, {u"lon"_s, -8.7170}}, QVariantMap{{u"lat"_s, 41.1720}, {u"lon"_s, -8.7170}},
                            QVariantMap{{u"lat"_s, 41.1720}, {u"lon"_s, -8.7130}}, QVariantMap{{u"lat"_s, 41.1695}, {u"lon"_s, -8.7130}}};
    const QString id = editor.addRows(area, 25, 0, 0, false);
    ASSERT_FALSE(id.isEmpty()) << editor.error().toStdString();
    EXPECT_EQ(byId(editor.maneuvers(), id).value(u"type"_s), u"FollowPath"_s);
    EXPECT_GT(editor.plan()->maneuver(id)->points.size(), 4);
    EXPECT_EQ(editor.errorCount(), 0) << "inside the operating area";
    EXPECT_EQ(editor.addRows(QVariantList{area[0], area[1]}, 25, 0, 0, false), QString());
    EXPECT_EQ(editor.error(), u"a survey area needs at least three corners (it has 2)"_s);

    ASSERT_TRUE(editor.save()) << editor.error().toStdString();
    EXPECT_FALSE(editor.modified());
    PlanEditorModel again;
    again.setMissionPath(path);
    EXPECT_EQ(again.maneuvers().size(), 5);
    EXPECT_EQ(again.plan()->maneuver(id)->points, editor.plan()->maneuver(id)->points);
}

TEST(PlanEditor, TheGraphLaidOutInStepsFromTheStartWithConditionsChecked)
{
    QTemporaryDir dir;
    PlanEditorModel editor;
    editor.setMissionPath(exampleCopy(dir));
    // go → wait → rows → surface: a column each.
    const auto column = [&](const QString &id) { return byId(editor.nodes(), id).value(u"column"_s).toInt(); };
    EXPECT_EQ(column(u"go"_s), 0);
    EXPECT_EQ(column(u"surface"_s), 3);
    EXPECT_TRUE(byId(editor.nodes(), u"go"_s).value(u"start"_s).toBool());

    // A way back from the surface to the start when the battery is still good.
    ASSERT_TRUE(editor.addTransition(u"surface"_s, u"go"_s, u"sys[\"lauv-sim-1\"].Voltage.value > 24"_s));
    EXPECT_EQ(editor.transitions().size(), 4);
    EXPECT_FALSE(editor.transitions().last().toMap().value(u"plain"_s).toBool());
    EXPECT_EQ(editor.errorCount(), 0) << editor.problems().value(0).toMap().value(u"message"_s).toString().toStdString();

    // A typing slip: the problem names where, and the plan has an error (not sent).
    const QVariantMap typed = editor.checkCondition(u"$waited > 60 &&& 1"_s);
    EXPECT_FALSE(typed.value(u"ok"_s).toBool());
    EXPECT_EQ(typed.value(u"column"_s).toInt(), 16);
    ASSERT_TRUE(editor.setCondition(3, u"$waited > 60 &&& 1"_s));
    EXPECT_EQ(editor.transitions().last().toMap().value(u"column"_s).toInt(), 16);
    ASSERT_EQ(editor.errorCount(), 1);
    const QVariantMap problem = editor.problems().first().toMap();
    EXPECT_EQ(problem.value(u"maneuver"_s), u"surface"_s);
    EXPECT_TRUE(problem.value(u"message"_s).toString().contains(u"column 16"_s)) << problem.value(u"message"_s).toString().toStdString();
    EXPECT_FALSE(std::isnan(problem.value(u"lat"_s).toDouble())) << "marked on the map where the transition leaves";

    // Undone, the good condition is back; an unreached maneuver gets a column after the reached ones.
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.errorCount(), 0);
    ASSERT_TRUE(editor.removeTransition(0)); // go → wait
    EXPECT_GT(column(u"wait"_s), column(u"go"_s));
    EXPECT_EQ(editor.problems().first().toMap().value(u"kind"_s).toInt(), int(neptus::mission::PlanProblem::Kind::Unreachable));
    ASSERT_TRUE(editor.setStart(u"wait"_s));
    EXPECT_TRUE(byId(editor.nodes(), u"wait"_s).value(u"start"_s).toBool());
    EXPECT_EQ(column(u"wait"_s), 0);
    ASSERT_TRUE(editor.save());
    PlanEditorModel again;
    again.setMissionPath(editor.missionPath());
    EXPECT_EQ(again.plan()->start, u"wait"_s);
    EXPECT_EQ(again.plan()->transitions.last().condition, u"sys[\"lauv-sim-1\"].Voltage.value > 24"_s);
}

TEST(PlanEditor, MapFeaturesAddedMovedReshapedAndUndoneWithThePlanCheckedAgainstThem)
{
    QTemporaryDir dir;
    PlanEditorModel editor;
    editor.setMissionPath(exampleCopy(dir));
    QSignalSpy features(&editor, &PlanEditorModel::featuresChanged);
    const qsizetype before = editor.features().size();
    const auto byFeature = [&](const QString &id) { return byId(editor.features(), id); };

    // A mark where tapped; moved.
    const QString mark = editor.addFeature(u"mark"_s, {QVariantMap{{u"lat"_s, 41.1701}, {u"lon"_s, -8.6201}}});
    ASSERT_EQ(mark, u"mark1"_s) << editor.error().toStdString();
    EXPECT_EQ(features.size(), 1);
    EXPECT_EQ(editor.features().size(), before + 1);
    ASSERT_TRUE(editor.moveFeature(mark, 41.1702, -8.6202));
    EXPECT_DOUBLE_EQ(byFeature(mark).value(u"lat"_s).toDouble(), 41.1702);

    // A no-go polygon over the survey plan's first leg: the plan has an error at once.
    ASSERT_EQ(editor.errorCount(), 0);
    const auto go = byId(editor.maneuvers(), u"go"_s);
    const double lat = go.value(u"lat"_s).toDouble(), lon = go.value(u"lon"_s).toDouble();
    const QString area = editor.addFeature(u"polygon"_s, {QVariantMap{{u"lat"_s, lat - 0.0003}, {u"lon"_s, lon - 0.0003}},
                                                          QVariantMap{{u"lat"_s, lat + 0.0003}, {u"lon"_s, lon - 0.0003}},
                                                          QVariantMap{{u"lat"_s, lat + 0.0003}, {u"lon"_s, lon + 0.0003}}});
    ASSERT_FALSE(area.isEmpty()) << editor.error().toStdString();
    EXPECT_EQ(editor.errorCount(), 0) << "an area's role is 'area' until said";
    EXPECT_FALSE(editor.setFeatureProperty(area, u"role"_s, u"forbidden"_s));
    EXPECT_TRUE(editor.error().contains(u"no-go"_s)) << "the choices named: " << editor.error().toStdString();
    ASSERT_TRUE(editor.setFeatureProperty(area, u"role"_s, u"no-go"_s));
    EXPECT_GE(editor.errorCount(), 1);
    EXPECT_EQ(byFeature(area).value(u"outline"_s).toList().size(), 3);
    // Reshaped: a fourth corner, one moved.
    ASSERT_TRUE(editor.insertFeaturePoint(area, 2, lat, lon + 0.0006));
    EXPECT_EQ(byFeature(area).value(u"points"_s).toList().size(), 4);
    ASSERT_TRUE(editor.moveFeaturePoint(area, 0, lat - 0.0004, lon - 0.0004));
    EXPECT_FALSE(editor.removeFeaturePoint(u"mark1"_s, 0));
    EXPECT_FALSE(editor.setFeatureProperty(area, u"color"_s, u"red"_s)) << "#rrggbb only";
    EXPECT_FALSE(editor.setFeatureProperty(area, u"z-min"_s, u"deep"_s));
    ASSERT_TRUE(editor.setFeatureProperty(area, u"layer"_s, u"hazards"_s));
    EXPECT_TRUE(editor.layers().contains(u"hazards"_s));

    // A circle and a model, each with what the format requires.
    const QString circle = editor.addFeature(u"circle"_s, {QVariantMap{{u"lat"_s, 41.15}, {u"lon"_s, -8.63}}});
    EXPECT_EQ(byFeature(circle).value(u"outline"_s).toList().size(), 64);
    EXPECT_FALSE(editor.setFeatureProperty(circle, u"radius"_s, u"-3"_s));
    ASSERT_TRUE(editor.setFeatureProperty(circle, u"radius"_s, u"40"_s));
    const QString model = editor.addFeature(u"model"_s, {QVariantMap{{u"lat"_s, 41.151}, {u"lon"_s, -8.631}}});
    ASSERT_TRUE(editor.setFeatureProperty(model, u"file"_s, u"pier.obj"_s));
    EXPECT_EQ(byFeature(model).value(u"file"_s).toString(), dir.filePath(u"pier.obj"_s)) << "beside the mission";
    EXPECT_TRUE(editor.addFeature(u"polygon"_s, {QVariantMap{{u"lat"_s, 41.0}, {u"lon"_s, -8.0}}}).isEmpty());
    EXPECT_TRUE(editor.addFeature(u"dragon"_s, {QVariantMap{{u"lat"_s, 41.0}, {u"lon"_s, -8.0}}}).isEmpty());

    // Undo takes the no-go role back with the later edits; redo returns it.
    while (editor.errorCount() > 0 && editor.canUndo())
        editor.undo();
    EXPECT_EQ(byFeature(area).value(u"role"_s), u"area"_s);
    ASSERT_TRUE(editor.redo());
    EXPECT_GE(editor.errorCount(), 1);
    while (editor.canRedo())
        editor.redo();

    // Saved, read back as it was (the file is valid against the schema).
    ASSERT_TRUE(editor.save()) << editor.error().toStdString();
    PlanEditorModel again;
    again.setMissionPath(editor.missionPath());
    ASSERT_EQ(again.error(), QString());
    // (As JSON: a polygon's position is NaN, never equal to itself.)
    EXPECT_EQ(QJsonArray::fromVariantList(again.features()), QJsonArray::fromVariantList(editor.features()));
    ASSERT_TRUE(again.removeFeature(mark));
    EXPECT_EQ(again.features().size(), editor.features().size() - 1);
}

// The editor on a shared mission: its edits go to another console as they
// are made; the other's come into the editor (and the desk's file), said with who.
TEST(PlanEditor, ASharedMissionsEditsGoOutAndComeIn)
{
    QTemporaryDir dir;
    const auto schema = neptus::test::shippedSchema();
    neptus::tree::VariableTree tree;
    neptus::alarms::AlarmGraph graph;
    neptus::plans::PlanDesk desk(schema, tree, graph, [](quint16, const neptus::msg::Message &) -> std::expected<void, QString> {
        return std::unexpected(u"no vehicles here"_s);
    });
    // The other console, and the network between them (messages as they are).
    neptus::plans::MissionShare *ours = nullptr;
    neptus::plans::MissionShare theirs(schema, u"console-b"_s, [&](const neptus::msg::Message &m) -> std::expected<void, QString> {
        ours->receive(m);
        return {};
    });
    neptus::plans::MissionShare share(schema, u"console-a"_s, [&](const neptus::msg::Message &m) -> std::expected<void, QString> {
        theirs.receive(m);
        return {};
    });
    ours = &share;
    PlanDeskModel deskModel(&desk, &share);
    ASSERT_TRUE(desk.openMission(exampleCopy(dir)).has_value());
    PlanEditorModel editor;
    editor.setDesk(&deskModel);
    editor.setMissionPath(desk.missionPath());
    ASSERT_EQ(deskModel.share(true), QString());
    EXPECT_TRUE(deskModel.sharing());
    ASSERT_TRUE(theirs.start({}).has_value());
    ASSERT_EQ(theirs.mission().plans.size(), 3) << "the other console joined and got it all";

    // Ours: a Goto, at once on the other console.
    const QString id = editor.addManeuver(u"Goto"_s, 41.1720, -8.7140);
    ASSERT_NE(theirs.mission().plans[0].maneuver(id), nullptr);
    EXPECT_EQ(theirs.authorOf(u"plan:survey"_s), u"console-a"_s);

    // Theirs: a mark; the desk writes the file (after a burst) and the editor has it.
    neptus::mission::Mission edited = theirs.mission();
    neptus::mission::Feature mark;
    mark.kind = u"mark"_s;
    mark.id = u"from-b"_s;
    mark.position.lat = 41.1711;
    mark.position.lon = -8.7151;
    edited.maps[0].features.append(mark);
    QSignalSpy told(&deskModel, &PlanDeskModel::sharedChange);
    theirs.update(edited);
    ASSERT_TRUE(told.wait(2000));
    EXPECT_EQ(told[0][0].toString(), u"console-b"_s);
    EXPECT_TRUE(deskModel.shareStatus().contains(u"console-b"_s)) << deskModel.shareStatus().toStdString();
    EXPECT_FALSE(byId(editor.features(), u"from-b"_s).isEmpty()) << "in the editor";
    EXPECT_NE(editor.plan()->maneuver(id), nullptr) << "with our own edit kept";
    EXPECT_FALSE(editor.modified()) << "the desk saved it";
    QFile file(editor.missionPath());
    ASSERT_TRUE(file.open(QIODevice::ReadOnly));
    EXPECT_TRUE(file.readAll().contains("id=\"from-b\""));
    // Undone here, it is undone there too.
    ASSERT_TRUE(editor.undo());
    EXPECT_TRUE(byId(editor.features(), u"from-b"_s).isEmpty());
    EXPECT_EQ(theirs.mission().maps[0].features.size(), edited.maps[0].features.size() - 1);
}

// Export from the editor: off the GUI thread, step by step, into the
// mission's folder; a plan with errors is not exported.
TEST(PlanEditor, ExportsThePlanToItsVehiclesTargetsStepByStep)
{
    QTemporaryDir dir;
    PlanEditorModel editor;
    editor.setMissionPath(exampleCopy(dir));
    QStringList targets;
    for (const QVariant &t : editor.exportTargets())
        targets << t.toMap().value(u"target"_s).toString();
    ASSERT_TRUE(targets.contains(u"imc"_s)) << targets.join(u' ').toStdString();
    QSignalSpy progress(&editor, &PlanEditorModel::exportChanged);
    ASSERT_TRUE(editor.exportPlan(u"imc"_s)) << editor.error().toStdString();
    EXPECT_TRUE(editor.exporting().value(u"busy"_s).toBool());
    EXPECT_FALSE(editor.exportPlan(u"imc"_s)) << "one at a time";
    ASSERT_TRUE(QTest::qWaitFor([&] { return !editor.exporting().value(u"busy"_s).toBool(); }, 20000));
    EXPECT_GE(progress.size(), 4) << "began, translating, writing, done";
    EXPECT_EQ(editor.exporting().value(u"error"_s).toString(), QString());
    const QString path = editor.exporting().value(u"path"_s).toString();
    EXPECT_EQ(path, dir.filePath(u"survey.imc.xml"_s));
    QFile written(path);
    ASSERT_TRUE(written.open(QIODevice::ReadOnly));
    EXPECT_TRUE(written.readAll().contains("PlanSpecification"));

    EXPECT_FALSE(editor.exportPlan(u"iver"_s)) << "not this vehicle's";
    EXPECT_TRUE(editor.error().contains(u"iver"_s));
    ASSERT_TRUE(editor.setParameter(u"go"_s, u"z"_s, u"500"_s));
    EXPECT_FALSE(editor.exportPlan(u"imc"_s)) << "errors first";
    EXPECT_TRUE(editor.error().contains(u"errors"_s)) << editor.error().toStdString();
}

// A terrain in the mission (a 3D model with role "terrain", read through the
// model import helper): a point planned deeper than it is an error.
TEST(PlanEditor, APointPlannedBelowTheTerrainIsAnError)
{
    QTemporaryDir dir;
    PlanEditorModel editor;
    editor.setMissionPath(exampleCopy(dir));
    // A flat seabed 10 m down, 600 m square around the survey's start (Y up, as .obj files are).
    QFile obj(dir.filePath(u"seabed.obj"_s));
    ASSERT_TRUE(obj.open(QIODevice::WriteOnly));
    obj.write("v -300 -10 -300\nv 300 -10 -300\nv 300 -10 300\nv -300 -10 300\nf 1 2 3 4\n");
    obj.close();
    const auto go = byId(editor.maneuvers(), u"go"_s);
    const QString model = editor.addFeature(u"model"_s, {QVariantMap{{u"lat"_s, go.value(u"lat"_s)}, {u"lon"_s, go.value(u"lon"_s)}}});
    ASSERT_TRUE(editor.setFeatureProperty(model, u"file"_s, u"seabed.obj"_s));
    EXPECT_TRUE(editor.terrain().isEmpty()) << "an object until it is the terrain";
    ASSERT_TRUE(editor.setFeatureProperty(model, u"role"_s, u"terrain"_s));
    EXPECT_TRUE(editor.terrain().startsWith(u"reading seabed.obj"_s)) << editor.terrain().toStdString();
    ASSERT_TRUE(QTest::qWaitFor([&] { return editor.terrain().contains(u"triangles"_s); }, 20000)) << editor.terrain().toStdString();
    EXPECT_EQ(editor.errorCount(), 0) << "3 m deep over a 10 m bottom";

    ASSERT_TRUE(editor.setParameter(u"go"_s, u"z"_s, u"12"_s));
    ASSERT_EQ(editor.errorCount(), 1) << editor.terrain().toStdString() << " "
                                      << editor.problems().value(0).toMap().value(u"message"_s).toString().toStdString();
    const QVariantMap problem = editor.problems().first().toMap();
    EXPECT_EQ(problem.value(u"kind"_s).toInt(), int(neptus::mission::PlanProblem::Kind::BelowBottom));
    EXPECT_EQ(problem.value(u"maneuver"_s), u"go"_s);
    EXPECT_TRUE(problem.value(u"message"_s).toString().contains(u"12.0 m deep where the bottom is 10.0 m deep"_s))
        << problem.value(u"message"_s).toString().toStdString();
    ASSERT_TRUE(editor.undo());
    EXPECT_EQ(editor.errorCount(), 0);
    // Saved and opened again, the terrain is read again.
    ASSERT_TRUE(editor.save());
    PlanEditorModel again;
    again.setMissionPath(editor.missionPath());
    ASSERT_TRUE(QTest::qWaitFor([&] { return again.terrain().contains(u"triangles"_s); }, 20000)) << again.terrain().toStdString();
    EXPECT_TRUE(again.setParameter(u"go"_s, u"z"_s, u"11"_s));
    EXPECT_EQ(again.errorCount(), 1);
}

// The terrain asked for its height: interpolated on a slope, the highest of
// two layers, nothing off the mesh.
TEST(PlanEditor, TheSeabedIsInterpolatedUnderAPoint)
{
    neptus::models::Mesh mesh;
    const auto vertex = [](float east, float north, float up) {
        return neptus::models::Mesh::Vertex{{east, north, up}, {0, 0, 1}, {1, 1, 1, 1}};
    };
    // A slope from 20 m down at the west edge to 10 m down at the east, and a pier deck at 2 m up over x 40..60.
    mesh.vertices = {vertex(0, 0, -20), vertex(100, 0, -10), vertex(100, 100, -10), vertex(0, 100, -20),
                     vertex(40, 40, 2), vertex(60, 40, 2), vertex(60, 60, 2)};
    mesh.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6};
    std::copy_n(std::array<float, 3>{0, 0, -20}.begin(), 3, mesh.boundsMin);
    std::copy_n(std::array<float, 3>{100, 100, 2}.begin(), 3, mesh.boundsMax);
    const neptus::models::Seabed seabed(mesh);
    EXPECT_NEAR(*seabed.heightAt(25, 70), -17.5, 1e-4);
    EXPECT_NEAR(*seabed.heightAt(75, 10), -12.5, 1e-4);
    EXPECT_NEAR(*seabed.heightAt(59, 45), 2, 1e-4) << "the deck over the slope";
    EXPECT_FALSE(seabed.heightAt(150, 50).has_value());
    EXPECT_FALSE(seabed.heightAt(std::nan(""), 50).has_value());
}

// With the console's charts read, every edit is also checked against them: the
// Leixões survey passes a charted 0-1 m shoal 150 m west of it; its last maneuver
// dragged onto the shoal is unsafe, saying where; undone, it is not.
TEST(PlanEditor, ChecksEveryEditAgainstTheConsolesCharts)
{
    QTemporaryDir dir;
    PlanEditorModel editor;
    editor.setMissionPath(exampleCopy(dir));
    ASSERT_EQ(editor.errorCount(), 0);
    neptus::tree::VariableTree tree;
    neptus::tree::VariableTreeModel model{&tree};
    neptus::geo::Tracks tracks{&model};
    neptus::alarms::AlarmGraph graph;
    ChartWatch watch(&tracks, &graph);
    editor.setCharts(&watch);
    EXPECT_EQ(editor.errorCount(), 0) << "no cells read yet";
    const auto area = [](const QString &cls, double west, double east, double south, double north, QMap<QString, QString> attributes) {
        neptus::charts::Feature f;
        f.objectClass = cls;
        f.geometry = neptus::charts::Feature::Geometry::Area;
        f.parts = {{{west, south, 0}, {east, south, 0}, {east, north, 0}, {west, north, 0}}};
        f.attributes = std::move(attributes);
        return f;
    };
    neptus::charts::Cell cell;
    cell.name = u"XX5DOURO.000"_s;
    cell.usageBand = 5;
    cell.features = {area(u"M_COVR"_s, -8.75, -8.65, 41.13, 41.23, {{u"CATCOV"_s, u"1"_s}}),
                     area(u"DEPARE"_s, -8.75, -8.65, 41.13, 41.23, {{u"DRVAL1"_s, u"10"_s}, {u"DRVAL2"_s, u"20"_s}}),
                     area(u"DEPARE"_s, -8.7185, -8.7175, 41.1700, 41.1710, {{u"DRVAL1"_s, u"0"_s}, {u"DRVAL2"_s, u"1"_s}})};
    cell.index();
    watch.setCells(std::make_shared<const std::vector<neptus::charts::Cell>>(std::vector<neptus::charts::Cell>{cell}));
    QStringList said;
    for (const QVariant &p : editor.problems())
        said << p.toMap().value(u"message"_s).toString();
    EXPECT_EQ(editor.errorCount(), 0) << said.join(u'\n').toStdString();
    ASSERT_TRUE(editor.moveManeuver(u"surface"_s, 41.1705, -8.7180));
    ASSERT_GE(editor.errorCount(), 1) << "the drag is checked against the chart";
    QVariantMap shoal;
    said.clear();
    for (const QVariant &p : editor.problems()) {
        said << p.toMap().value(u"message"_s).toString();
        if (said.last().startsWith(u"'surface' (PopUp): a leg enters water charted 0.0–1.0 m, shallower than the"_s))
            shoal = p.toMap();
    }
    ASSERT_FALSE(shoal.isEmpty()) << said.join(u'\n').toStdString();
    EXPECT_EQ(shoal.value(u"severity"_s), u"error"_s);
    EXPECT_TRUE(shoal.contains(u"lat"_s));
    editor.undo();
    EXPECT_EQ(editor.errorCount(), 0);
}

// The rows views draw from are told only what changed: a moved maneuver is
// one changed row (and those whose arrival time moved with it), an added one
// one inserted row, a removed one one removed row; nothing is reset, so a
// view of 1,000 maneuvers keeps 999 delegates as they were.
TEST(PlanEditor, ViewsAreToldOnlyTheRowsAnEditChanged)
{
    QTemporaryDir dir;
    PlanEditorModel editor;
    editor.setMissionPath(exampleCopy(dir));
    RowModel *rows = editor.maneuverRows();
    ASSERT_EQ(rows->count(), 4);
    QSignalSpy reset(rows, &QAbstractItemModel::modelReset), inserted(rows, &QAbstractItemModel::rowsInserted),
        removed(rows, &QAbstractItemModel::rowsRemoved), changed(rows, &QAbstractItemModel::dataChanged);

    // The last one moved: its row alone (nothing comes after it).
    ASSERT_TRUE(editor.moveManeuver(u"surface"_s, 41.1722, -8.7130));
    ASSERT_EQ(changed.size(), 1);
    EXPECT_EQ(changed[0][0].toModelIndex().row(), 3);
    EXPECT_EQ(changed[0][1].toModelIndex().row(), 3);
    EXPECT_DOUBLE_EQ(rows->get(3).value(u"lat"_s).toDouble(), 41.1722);
    EXPECT_EQ(rows->get(3).value(u"maneuver"_s), u"surface"_s);

    // One added at the end: one row inserted there.
    changed.clear();
    const QString added = editor.addManeuver(u"Goto"_s, 41.1725, -8.7140);
    ASSERT_EQ(inserted.size(), 1);
    EXPECT_EQ(inserted[0][1].toInt(), 4);
    EXPECT_EQ(inserted[0][2].toInt(), 4);
    EXPECT_EQ(rows->get(4).value(u"maneuver"_s), added);
    EXPECT_TRUE(changed.isEmpty()) << "the rows before it are as they were";

    // The first one moved: its row, and the later ones' arrival times.
    ASSERT_TRUE(editor.moveManeuver(u"go"_s, 41.1700, -8.7100));
    ASSERT_GE(changed.size(), 1);
    EXPECT_EQ(changed[0][0].toModelIndex().row(), 0);

    // One removed from the middle: that row removed, the others kept.
    ASSERT_TRUE(editor.removeManeuver(u"wait"_s));
    ASSERT_EQ(removed.size(), 1);
    EXPECT_EQ(removed[0][1].toInt(), 1);
    EXPECT_EQ(removed[0][2].toInt(), 1);
    EXPECT_EQ(rows->count(), 4);
    EXPECT_EQ(reset.size(), 0);
    // The list the tests and scripts read says the same.
    EXPECT_EQ(editor.maneuvers().size(), 4);
    EXPECT_EQ(editor.maneuvers()[1].toMap().value(u"id"_s), u"rows"_s);
    EXPECT_EQ(editor.maneuvers()[1].toMap().value(u"index"_s), 1);

    // Undo puts it back in its place: one row inserted.
    inserted.clear();
    ASSERT_TRUE(editor.undo());
    ASSERT_EQ(inserted.size(), 1);
    EXPECT_EQ(inserted[0][1].toInt(), 1);
    EXPECT_EQ(rows->get(1).value(u"maneuver"_s), u"wait"_s);
    EXPECT_EQ(reset.size(), 0);
}

// The selected maneuver's parameters, by row: a change of one parameter is
// that row; another maneuver's edit leaves the form alone.
TEST(PlanEditor, TheSelectedManeuversParametersChangeByTheRow)
{
    QTemporaryDir dir;
    PlanEditorModel editor;
    editor.setMissionPath(exampleCopy(dir));
    editor.setSelected(u"go"_s);
    RowModel *form = editor.parameters();
    ASSERT_GT(form->count(), 3);
    const int speed = form->indexOf(u"speed"_s);
    ASSERT_GE(speed, 0);
    QSignalSpy inserted(form, &QAbstractItemModel::rowsInserted), removed(form, &QAbstractItemModel::rowsRemoved),
        changed(form, &QAbstractItemModel::dataChanged);

    ASSERT_TRUE(editor.setParameter(u"go"_s, u"speed"_s, u"1.2"_s));
    ASSERT_EQ(changed.size(), 1);
    EXPECT_EQ(changed[0][0].toModelIndex().row(), speed);
    EXPECT_EQ(form->get(speed).value(u"value"_s), u"1.2"_s);
    // Out of the vehicle's range: the row says why.
    ASSERT_TRUE(editor.setParameter(u"go"_s, u"speed"_s, u"99"_s));
    EXPECT_FALSE(form->get(speed).value(u"problem"_s).toString().isEmpty());

    changed.clear();
    ASSERT_TRUE(editor.moveManeuver(u"surface"_s, 41.1722, -8.7130));
    EXPECT_TRUE(changed.isEmpty());
    EXPECT_TRUE(inserted.isEmpty());
    EXPECT_TRUE(removed.isEmpty());

    editor.setSelected(QString());
    EXPECT_EQ(form->count(), 0);
}

TEST(RowModelTest, KeepsTheRowsBothListsShareAndTellsTheRest)
{
    RowModel model({u"name"_s, u"value"_s});
    const auto row = [](const char *name, double value) { return RowModel::Row{QString::fromLatin1(name), value}; };
    model.setRows({row("a", 1), row("b", 2), row("c", 3)});
    QSignalSpy inserted(&model, &QAbstractItemModel::rowsInserted), removed(&model, &QAbstractItemModel::rowsRemoved),
        changed(&model, &QAbstractItemModel::dataChanged), reset(&model, &QAbstractItemModel::modelReset);
    const double none = std::numeric_limits<double>::quiet_NaN();

    model.setRows({row("a", 1), row("b", none), row("c", 3)});
    ASSERT_EQ(changed.size(), 1);
    EXPECT_EQ(changed[0][0].toModelIndex().row(), 1);
    model.setRows({row("a", 1), row("b", none), row("c", 3)});
    EXPECT_EQ(changed.size(), 1) << "no value (NaN) is the same as no value";
    const int revision = model.revision();

    model.setRows({row("a", 1), row("x", 9), row("b", none), row("c", 3)});
    ASSERT_EQ(inserted.size(), 1);
    EXPECT_EQ(inserted[0][1].toInt(), 1);
    EXPECT_EQ(model.indexOf(u"b"_s), 2);
    EXPECT_GT(model.revision(), revision);

    model.setRows({row("c", 3)});
    ASSERT_EQ(removed.size(), 1);
    EXPECT_EQ(removed[0][1].toInt(), 0);
    EXPECT_EQ(removed[0][2].toInt(), 2);
    EXPECT_EQ(model.count(), 1);
    EXPECT_EQ(model.data(model.index(0), Qt::UserRole + 2).toDouble(), 3);
    EXPECT_EQ(model.roleNames().value(Qt::UserRole + 1), "name");
    EXPECT_EQ(reset.size(), 0);
}
