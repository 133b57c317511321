#pragma once

#include "mission/Mission.h"
#include "mission/PlanCheck.h"
#include "mission/PlanGeometry.h"
#include "mission/Vehicle.h"
#include "qmlmodels/ChartWatch.h"
#include "qmlmodels/PlanDeskModel.h"
#include "qmlmodels/RowModel.h"
#include "models/ModelImport.h"
#include "models/Seabed.h"
#include "scripting/ScriptRunner.h"

#include <QObject>
#include <QPointer>
#include <QPointF>

#include <memory>
#include <optional>
#include <QStringList>
#include <QVariantList>
#include <QtQml/qqmlregistration.h>

// One plan of a mission file being drawn on the map (the plan editor): add
// a maneuver where the operator taps (its vehicle's defaults), move it, edit
// its parameters, remove it, lay rows over a drawn area; undo and redo every
// edit; after each one the plan's geometry, statistics and problems
// (mission::checkPlan) are worked out again, so the map shows them at once.
// Saving writes the mission file (the previous one kept as .bak).
class PlanEditorModel : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    // The mission file; setting it opens it ("" closes).
    Q_PROPERTY(QString missionPath READ missionPath WRITE setMissionPath NOTIFY missionChanged)
    Q_PROPERTY(QStringList planIds READ planIds NOTIFY missionChanged)
    // The plan being edited (one of planIds).
    Q_PROPERTY(QString planId READ planId WRITE setPlanId NOTIFY planChanged)
    Q_PROPERTY(QString vehicle READ vehicle NOTIFY planChanged)
    // The maneuvers its vehicle can do (its definition's; every known type without one).
    Q_PROPERTY(QStringList maneuverTypes READ maneuverTypes NOTIFY planChanged)
    // The maneuvers in plan order, for views (rows told by the row, so a
    // view of a thousand keeps its delegates through an edit): roles
    // maneuver (its id), type, lat, lon, severity ("error" | "warning" | ""),
    // arrival (seconds from the start when the vehicle gets there; -1: never).
    Q_PROPERTY(RowModel *maneuverRows READ maneuverRows CONSTANT)
    // The same as a list, made when read (tests, scripts):
    // [{id, type, lat, lon, index, severity, arrival}].
    Q_PROPERTY(QVariantList maneuvers READ maneuvers NOTIFY edited)
    // The maneuver the operator works on ("": none) and its parameters, by the row:
    // roles name, value, unit, type, min, max (NaN: none), values, problem.
    Q_PROPERTY(QString selected READ selected WRITE setSelected NOTIFY selectedChanged)
    Q_PROPERTY(RowModel *parameters READ parameters CONSTANT)
    // Every point the vehicle will pass, transits included, in execution
    // order: [{lat, lon, maneuver, distance (m along the plan), z, zUnits}].
    Q_PROPERTY(QVariantList path READ path NOTIFY edited)
    // The profile along the path: {units: the z units it uses, of DEPTH,
    // ALTITUDE, HEIGHT; top: {unit: its highest z (at least 1 m)}}; each
    // unit's lines by profileLines().
    Q_PROPERTY(QVariantMap profile READ profile NOTIFY edited)
    // [{severity: "error" | "warning", kind, maneuver, message, lat, lon (NaN: none)}], worst first.
    // Said changed only when it is (a list views rebuild whole: an edit that
    // left the problems as they were recreated the rows under the finger).
    Q_PROPERTY(QVariantList problems READ problems NOTIFY problemsChanged)
    // The plan as a graph, laid out in columns by the number of steps from
    // the start (maneuvers the start does not reach after those):
    // [{id, type, index, column, row, start, severity}] and
    // [{index, from, to, condition, plain, problem, line, column}] (problem:
    // why the condition does not compile, at line/column of the condition).
    Q_PROPERTY(QVariantList nodes READ nodes NOTIFY edited)
    Q_PROPERTY(QVariantList transitions READ transitions NOTIFY edited)
    Q_PROPERTY(int errorCount READ errorCount NOTIFY edited)
    // {maneuvers, length (m), duration (s, -1: never ends), maxDepth (m, -1: none)}.
    Q_PROPERTY(QVariantMap statistics READ statistics NOTIFY edited)
    // The mission's checklists' items, in order: [{list, group, item
    // (indices), checklist (its name or id), groupName, text, note, variable,
    // min, max (NaN: none)}].
    Q_PROPERTY(QVariantList checklistItems READ checklistItems NOTIFY checklistsChanged)
    // The mission's other plans, drawn fainter in their vehicles' colours:
    // [{id, vehicle, path: [{lat, lon}]}].
    Q_PROPERTY(QVariantList otherPlans READ otherPlans NOTIFY otherPlansChanged)
    // The mission's map features, to draw and edit (missionFeatures()).
    Q_PROPERTY(QVariantList features READ features NOTIFY featuresChanged)
    // The layers the features are in ("" is the features without one).
    Q_PROPERTY(QStringList layers READ layers NOTIFY featuresChanged)
    Q_PROPERTY(bool modified READ modified NOTIFY edited)
    Q_PROPERTY(bool canUndo READ canUndo NOTIFY edited)
    Q_PROPERTY(bool canRedo READ canRedo NOTIFY edited)
    // What the plan's vehicle's definition translates it to: [{target, name, extension}].
    Q_PROPERTY(QVariantList exportTargets READ exportTargets NOTIFY planChanged)
    // The export under way or last done: {busy, target, step (1-3), steps (3),
    // what, path (written), error, started (ms since the epoch)}.
    Q_PROPERTY(QVariantMap exporting READ exporting NOTIFY exportChanged)
    // The mission's terrain (a 3D model with role "terrain"): "" when it
    // has none, else what became of it ("reading seabed.obj", "seabed.obj:
    // 2 triangles", or why it could not be read). Points planned deeper than
    // it are errors of the plan.
    Q_PROPERTY(QString terrain READ terrain NOTIFY terrainChanged)
    // The console's plan desk: with the mission shared, every edit goes to
    // the other consoles and theirs come here (the last change wins).
    Q_PROPERTY(PlanDeskModel *desk READ desk WRITE setDesk NOTIFY deskChanged)
    // The console's charts (ConsoleSession.charts): with cells loaded, every edit is also checked
    // against them (charts::checkAgainstCharts: land, shallows, hazards, restricted areas).
    Q_PROPERTY(ChartWatch *charts READ charts WRITE setCharts NOTIFY chartsChanged)
    // Why the last open, save or edit did not happen ("" when it did).
    Q_PROPERTY(QString error READ error NOTIFY errorChanged)

public:
    explicit PlanEditorModel(QObject *parent = nullptr);

    QString missionPath() const { return m_path; }
    void setMissionPath(const QString &path);
    QStringList planIds() const;
    QString planId() const { return m_planId; }
    void setPlanId(const QString &id);
    QString vehicle() const;
    QStringList maneuverTypes() const;
    RowModel *maneuverRows() const { return m_maneuverRows; }
    QVariantList maneuvers() const;
    QString selected() const { return m_selected; }
    void setSelected(const QString &id);
    RowModel *parameters() const { return m_parameters; }
    // The maneuver drawn nearest to lat/lon within `metres` ("" when none is).
    Q_INVOKABLE QString maneuverNear(double lat, double lon, double metres) const;
    QVariantList path() const { return m_pathPoints; }
    QVariantMap profile() const;
    // One unit's stretches of the profile (broken where the plan changes
    // units), as polygons in [0, 1] × [0, 1]: x the distance along the plan
    // over its length, y the z over the unit's top (DEPTH drawn down from the
    // top: y = z / top; ALTITUDE and HEIGHT up from the bottom: 1 - z / top).
    // A QList<QList<QPointF>>, for a PathMultiline scaled to its Shape (no JavaScript per point).
    Q_INVOKABLE QVariant profileLines(const QString &unit) const;
    QVariantList problems() const { return m_problemList; }
    QVariantList nodes() const;
    QVariantList transitions() const;
    int errorCount() const;
    QVariantMap statistics() const;
    QVariantList features() const { return m_featureList; }
    QVariantList otherPlans() const { return m_otherPlans; }
    QVariantList checklistItems() const;
    QStringList layers() const;
    bool modified() const { return m_modified; }
    bool canUndo() const { return !m_undo.isEmpty(); }
    bool canRedo() const { return !m_redo.isEmpty(); }
    QString error() const { return m_error; }
    PlanDeskModel *desk() const { return m_desk; }
    ChartWatch *charts() const { return m_charts; }
    void setCharts(ChartWatch *charts);
    QString terrain() const { return m_terrainState; }
    QVariantList exportTargets() const;
    QVariantMap exporting() const { return m_export; }
    // Translates the plan (the mission processor, off the GUI thread) to
    // `target`, into the mission's folder as <plan>.<extension>: false (and
    // `error`) when it cannot start: errors in the plan, no such target, one under way.
    Q_INVOKABLE bool exportPlan(const QString &target);
    void setDesk(PlanDeskModel *desk);

    // A maneuver of `type` at a position, after the plan's last one (a
    // transition from it), with its vehicle's defaults: its id, or "".
    Q_INVOKABLE QString addManeuver(const QString &type, double lat, double lon);
    Q_INVOKABLE bool moveManeuver(const QString &id, double lat, double lon);
    Q_INVOKABLE bool removeManeuver(const QString &id);
    // Sets one parameter (text, as typed); a value out of the vehicle's
    // range is kept and shown as a problem, so the plan cannot be sent.
    Q_INVOKABLE bool setParameter(const QString &id, const QString &name, const QString &value);
    // [{name, value, unit, type, min, max (NaN: none), values, problem}]:
    // the vehicle's parameters of the maneuver's type, then any other it has.
    Q_INVOKABLE QVariantList parametersOf(const QString &id) const;
    // Rows over an area drawn as [{lat, lon}]: the new FollowPath's id, or "".
    Q_INVOKABLE QString addRows(const QVariantList &area, double spacing, double angle, double overshoot, bool crossHatch);
    // A FollowPath along a line drawn as [{lat, lon}] (two points or more): its id, or "".
    Q_INVOKABLE QString addPathAlong(const QVariantList &line);
    // The graph: a transition (condition "" is ManeuverIsDone), its
    // condition (kept even when it does not compile, then shown as a
    // problem so the plan cannot be sent), removing one, the start.
    Q_INVOKABLE bool addTransition(const QString &from, const QString &to, const QString &condition);
    Q_INVOKABLE bool setCondition(int transition, const QString &condition);
    Q_INVOKABLE bool removeTransition(int transition);
    Q_INVOKABLE bool setStart(const QString &id);
    // A condition as it is typed: {ok, line, column, message}.
    Q_INVOKABLE QVariantMap checkCondition(const QString &condition) const;
    // The map: a feature of `kind` (mark, transponder, path, polygon, circle,
    // box, cylinder, ellipsoid, image, model) at the points tapped ([{lat,
    // lon}]: two or more for a path, three or more for a polygon, one for the
    // rest), in the mission's first map: its id, or "".
    Q_INVOKABLE QString addFeature(const QString &kind, const QVariantList &points);
    // Moves the whole feature so that its position (or first point) is at lat/lon.
    Q_INVOKABLE bool moveFeature(const QString &id, double lat, double lon);
    // Reshapes: one point of a path or polygon, or an image's corner.
    Q_INVOKABLE bool moveFeaturePoint(const QString &id, int index, double lat, double lon);
    // A point more after `index` (a path's or polygon's), or one less.
    Q_INVOKABLE bool insertFeaturePoint(const QString &id, int index, double lat, double lon);
    Q_INVOKABLE bool removeFeaturePoint(const QString &id, int index);
    Q_INVOKABLE bool removeFeature(const QString &id);
    // One property (featureProperties' names), checked as the mission
    // format has it: a bad value is refused with the reason in `error`.
    Q_INVOKABLE bool setFeatureProperty(const QString &id, const QString &name, const QString &value);
    // What the feature's properties form shows: [{name, value, type: "text" |
    // "number" | "choice" | "color", choices, unit}].
    Q_INVOKABLE QVariantList featureProperties(const QString &id) const;
    // Checklists: an item at the end of the first checklist's last group
    // (a checklist "checks" with a group "General" made when there is none);
    // one field of an item (text, note, variable, min, max; a bad number is
    // refused); removing one.
    Q_INVOKABLE bool addChecklistItem(const QString &text);
    Q_INVOKABLE bool setChecklistItem(int list, int group, int item, const QString &field, const QString &value);
    Q_INVOKABLE bool removeChecklistItem(int list, int group, int item);
    Q_INVOKABLE bool undo();
    Q_INVOKABLE bool redo();
    Q_INVOKABLE bool save();
    // Writes the mission to another file and edits that one from now on.
    Q_INVOKABLE bool saveAs(const QString &path);
    // Writes the mission as LSTS Neptus writes its own (.nmisz), for operators
    // who keep Neptus; the mission edited stays this one. {ok, message}: the
    // message says what Neptus had no words for, or why nothing was written.
    Q_INVOKABLE QVariantMap exportNeptus(const QString &path);
    // The vehicles with a definition (what a new mission's plan may be for).
    Q_INVOKABLE QStringList knownVehicles() const;

    // The editor's own copy (tests, benchmarks).
    const neptus::mission::Plan *plan() const;

signals:
    void missionChanged();
    void planChanged();
    void featuresChanged();
    void checklistsChanged();
    void otherPlansChanged();
    void deskChanged();
    void chartsChanged();
    void exportChanged();
    void terrainChanged();
    void edited();
    void problemsChanged();
    void errorChanged();
    void selectedChanged();

private:
    neptus::mission::Plan *editable();
    // Keeps the plan as it was for undo, applies nothing itself.
    void remember();
    void changed(); // geometry, problems and statistics again; edited()
    void fail(const QString &why);
    QString freshId(const QString &type) const;
    neptus::mission::Maneuver *find(const QString &id);
    QString addPattern(const neptus::mission::Maneuver &made); // a FollowPath made by a pattern generator
    neptus::mission::Feature *feature(const QString &id);
    void featuresEdited();   // the feature list again, the plan checked again (areas change it)
    void checklistsEdited(); // told and shared; nothing else depends on them
    void missionReplaced();  // opened, or another console's: everything again
    void restore(neptus::mission::Mission mission); // undo, redo
    QList<RowModel::Row> maneuverRowsNow() const;
    QList<RowModel::Row> parameterRows(const QString &id) const;
    QVariantList problemList() const;

    QString m_path, m_planId, m_error;
    neptus::mission::Mission m_mission;
    // The vehicle definitions the checks use: the plan desk's (vehicles()), else read here once.
    const neptus::mission::VehicleCatalog &vehicles() const;
    mutable std::optional<neptus::mission::VehicleCatalog> m_ownVehicles;
    QList<neptus::mission::Mission> m_undo, m_redo; // implicitly shared: a copy is cheap
    bool m_modified = false;
    neptus::mission::PlanGeometry m_geometry;
    neptus::mission::PlanGeometryCache m_geometryCache; // a drag works out one maneuver again, not a thousand
    QList<neptus::mission::PlanProblem> m_problems;
    QList<neptus::mission::PlanProblem> m_shownProblems; // what m_problemList says
    // Conditions checked so far: compiling one takes milliseconds, a plan is checked on every edit.
    mutable QHash<QString, std::optional<neptus::scripting::CompileError>> m_conditionChecks;
    const std::optional<neptus::scripting::CompileError> &conditionProblem(const QString &condition) const;
    QVariantList m_pathPoints, m_problemList, m_featureList; // made once per edit, read by every view
    RowModel *m_maneuverRows, *m_parameters;
    // The profile: each unit's runs of (distance, z), made with the path.
    QHash<QString, QList<QList<QPointF>>> m_profileRuns;
    QHash<QString, double> m_profileTop;
    double m_profileLength = 1;
    QString m_selected;
    QVariantList m_otherPlans; // when the mission or the plan being edited changes
    QPointer<PlanDeskModel> m_desk;
    QPointer<ChartWatch> m_charts;
    QVariantMap m_export;
    // The terrain: read by the model import helper, asked at every planned point.
    std::unique_ptr<neptus::models::ModelImport> m_terrainImport;
    std::optional<neptus::models::Seabed> m_seabed;
    QString m_terrainFile, m_terrainState;
    neptus::mission::GeoPosition m_terrainOrigin;
    void terrainAgain(); // when the features change: another terrain to read?
    void checkBottom();  // the plan's points against it, into m_problems
    void adoptShared(); // another console's change
    void otherPlansAgain();
};
