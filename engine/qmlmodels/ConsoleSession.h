#pragma once

#include "qmlmodels/AlarmListModel.h"
#include "qmlmodels/ChartWatch.h"
#include "qmlmodels/LinkStatisticsModel.h"
#include "qmlmodels/PlanDeskModel.h"
#include "qmlmodels/ReplayModel.h"
#include "qmlmodels/SessionsModel.h"
#include "qmlmodels/Tracks.h"
#include "qmlmodels/VariableTreeModel.h"
#include "session/Console.h"

#include <QObject>
#include <QVariantMap>
#include <QtQml/qqmlregistration.h>

// A running console as QML sees it: the console itself (session::Console:
// definitions, tree, alarms, scripts, links) and the models its components
// bind to. The shell hands it to QML as a typed property.
class ConsoleSession : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by the program")
    Q_PROPERTY(neptus::tree::VariableTreeModel *tree READ treeModel CONSTANT)
    Q_PROPERTY(neptus::alarms::AlarmListModel *alarms READ alarmModel CONSTANT)
    Q_PROPERTY(neptus::scripting::ScriptHost *scripts READ scripts CONSTANT)
    Q_PROPERTY(neptus::geo::Tracks *tracks READ tracks CONSTANT)
    Q_PROPERTY(neptus::transport::LinkStatisticsModel *links READ linksModel CONSTANT)
    Q_PROPERTY(PlanDeskModel *plans READ plansModel CONSTANT)
    // The charted water under each vehicle, with its alarm (--charts).
    Q_PROPERTY(ChartWatch *charts READ chartWatch CONSTANT)
    // The replay when this console is fed from a log (--replay), else null: nothing is sent then.
    Q_PROPERTY(ReplayModel *replay READ replay CONSTANT)
    // The operation's sessions from its database, for review (the program names the database).
    Q_PROPERTY(SessionsModel *sessions READ sessions CONSTANT)

public:
    explicit ConsoleSession(std::shared_ptr<const neptus::msg::Schema> schema,
                            const neptus::Clock *clock = &neptus::Clock::system(), QObject *parent = nullptr);
    ~ConsoleSession() override;

    neptus::session::Console &console() { return m_console; }
    neptus::tree::VariableTreeModel *treeModel() { return &m_treeModel; }
    neptus::alarms::AlarmListModel *alarmModel() { return &m_alarmModel; }
    neptus::transport::LinkStatisticsModel *linksModel() { return &m_linksModel; }
    neptus::scripting::ScriptHost *scripts() { return m_console.scripts(); }
    neptus::geo::Tracks *tracks() { return &m_tracks; }
    neptus::plans::PlanDesk &planDesk() { return m_planDesk; }
    neptus::plans::MissionShare &missionShare() { return m_share; }
    PlanDeskModel *plansModel() { return &m_plansModel; }
    ChartWatch *chartWatch() { return &m_chartWatch; }
    ReplayModel *replay() const { return m_replay; }
    SessionsModel *sessions() { return &m_sessions; }
    // Before QML sees the session: this console replays `replay` (kept by the caller).
    void setReplay(ReplayModel *replay);

    // For components (a joystick, a command button): sends a message, given
    // as JSON ({"abbrev": "Abort", "fields": {...}}), to a system. Returns ""
    // when sent, else why not.
    Q_INVOKABLE QString send(const QString &system, const QVariantMap &message);
    // For a command picker: the messages there are to send, [{abbrev, name,
    // category}] by category then name.
    Q_INVOKABLE QVariantList messageTypes() const;
    // A message's fields for an editor: [{abbrev, name, kind ("number",
    // "integer", "text", "enum", "bitfield", "message", "raw"), unit, min,
    // max, value (default as written), options ([abbrev] of an enum or bitfield)}].
    Q_INVOKABLE QVariantList fieldsOf(const QString &abbrev) const;
    // The operator trusts `host` as the system with IMC id `systemId` (when
    // several hosts send as it): commands go there. "" goes back to automatic.
    Q_INVOKABLE bool chooseSource(int systemId, const QString &host);
    // The operator forgets a system (gone for good): its rows, alarms,
    // track and statistics go; heard again, it is met anew.
    Q_INVOKABLE void forgetSystem(int systemId);

    // A plan as a MAVLink vehicle's mission and geofence (the desk's translation).
    static std::expected<neptus::plans::MavlinkPlan, QString> mavlinkPlanFor(const neptus::mission::Mission &mission,
                                                                             const neptus::mission::Plan &plan,
                                                                             const neptus::mission::VehicleDefinition *definition = nullptr);

private:
    neptus::session::Console m_console;
    neptus::tree::VariableTreeModel m_treeModel{&m_console.tree()};
    neptus::geo::Tracks m_tracks{&m_treeModel};
    neptus::alarms::AlarmListModel m_alarmModel{&m_console.alarmGraph()};
    neptus::transport::LinkStatisticsModel m_linksModel{&m_console.linkStatistics(), &m_console.tree()};
    neptus::plans::PlanDesk m_planDesk;
    neptus::plans::MissionShare m_share;
    PlanDeskModel m_plansModel{&m_planDesk, &m_share};
    ChartWatch m_chartWatch{&m_tracks, &m_console.alarmGraph()};
    ReplayModel *m_replay = nullptr;
    SessionsModel m_sessions;
};
