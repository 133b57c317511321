#pragma once

#include "alarms/AlarmGraph.h"
#include "alarms/HealthMonitor.h"
#include "core/Clock.h"
#include "log/Recorder.h"
#include "messages/SchemaSet.h"
#include "scripting/ScriptHost.h"
#include "session/EntityNaming.h"
#include "transport/LinkRouter.h"
#include "transport/LinkStatistics.h"
#include "transport/dds/DdsTransport.h"
#include "transport/imc/ImcUdpTransport.h"
#include "transport/mavlink/MavlinkTransport.h"
#include "tree/VariableTree.h"

#include <QObject>
#include <QTimer>

#include <atomic>
#include <memory>

namespace neptus::session {

class OperationsFeed;

// Everything one running console is made of, without any QML: the message
// definitions (the console's own, and others per system), the variable tree,
// the alarm graph, the health monitor, the alarm scripts (started on first
// use), the links to vehicles (IMC/UDP, DDS) with their statistics and
// router, and the queries a console makes on first contact. The console
// program hands it to QML through ConsoleSession; tests, fuzz targets and
// headless tools use it directly.
class Console : public QObject
{
    Q_OBJECT

public:
    explicit Console(std::shared_ptr<const msg::Schema> schema, const Clock *clock = &Clock::system(),
                     QObject *parent = nullptr);
    ~Console() override;

    const msg::Schema &schema() const { return *m_schema; }
    std::shared_ptr<const msg::Schema> sharedSchema() const { return m_schema; }
    msg::SchemaSet &schemas() { return *m_schemas; }
    std::shared_ptr<msg::SchemaSet> schemaSet() const { return m_schemas; }
    tree::VariableTree &tree() { return m_tree; }
    alarms::AlarmGraph &alarmGraph() { return m_graph; }
    alarms::HealthMonitor &health() { return m_health; }
    transport::LinkStatistics &linkStatistics() { return m_linkStatistics; }
    transport::ImcUdpTransport *imc() { return m_imc.get(); }
    transport::DdsTransport *dds() { return m_dds.get(); }
    // The MAVLink links, in the order started.
    const std::vector<std::unique_ptr<transport::MavlinkTransport>> &mavlinkLinks() const { return m_mavlink; }
    // The MAVLink dialects (msgdefs/mavlink/ardupilotmega.xml and what it
    // includes, or setMavlinkDialect's), loaded on first use; null if they do not load.
    std::shared_ptr<const msg::Schema> mavlinkSchema();
    // Made on first use: a console that runs no alarm scripts (a headless
    // recorder, the receive-path fuzz target) starts no script engine.
    scripting::ScriptHost *scripts();

    // Every packet the links receive and send goes to `recorder` too (null:
    // none); its problems (a full disk) raise the "recording" alarm. Any time.
    void setRecorder(log::Recorder *recorder);
    // Every message received and sent goes to `feed` too (the operation's
    // database; null: none). Any time.
    void setFeed(OperationsFeed *feed) { m_feed = feed; }
    // A console fed from a log (review): nothing is sent to anyone.
    void setReplaying(bool replaying) { m_replaying = replaying; }
    bool replaying() const { return m_replaying; }

    // Decodes what `system` (an IMC id such as "0x00d1", or the name it
    // announces) sends with the definitions in `file` (IMC.xml or IMC.xml.gz),
    // and encodes what goes to it with them. Call before starting the links.
    std::expected<void, QString> setDefinitionsFor(const QString &system, const QString &file);

    // Opens the links; an error says why (a busy port, a bad configuration),
    // and the console carries on without that link.
    std::expected<void, QString> startImc(transport::ImcUdpConfig config);
    std::expected<void, QString> startDds(transport::DdsConfig config);
    // A MAVLink link (UDP, TCP or serial); each has 256 console ids of its
    // own for the vehicles behind it (MavlinkConfig::idBase is set here).
    std::expected<void, QString> startMavlink(transport::MavlinkConfig config);
    // The MAVLink dialect file to read instead of ardupilotmega.xml (before startMavlink).
    std::expected<void, QString> setMavlinkDialect(const QString &file);
    // Takes a MAVLink link made with mavlinkSchema() and this console's IMC
    // schema, started or not (the fuzz target feeds an unstarted one through receive()).
    transport::MavlinkTransport *attachMavlink(std::unique_ptr<transport::MavlinkTransport> link);
    // The plan a MAVLink vehicle holds, for its progress (its PlanControlState):
    // the plan's id and, per mission item, the maneuver it belongs to.
    void labelMission(quint16 system, const QString &planId, const QStringList &maneuverOfItem);
    // The mode Stop puts a MAVLink vehicle in (its settings', else its autopilot's); "" when none has it.
    QString mavlinkStopMode(quint16 system) const;
    // Takes an IMC/UDP link made with schemaSet(), started or not (the fuzz
    // target feeds an unstarted one through receive()).
    transport::ImcUdpTransport *attachImc(std::unique_ptr<transport::ImcUdpTransport> imc);

    // A transport, by name ("IMC/UDP", "DDS"): commands to a system go over
    // the link it was last heard on. startImc/startDds add theirs.
    void addLink(const QString &name, transport::OutputSink *sink);
    // A peer speaks other message definitions: a Warning on
    // "systems/<system>/definitions" says so, so values are not silently misread.
    void definitionsDiffer(quint16 system, const QString &theirDigest, const QString &ourDigest);

    // `system` is (now) reached over `link`: commands go there (any thread).
    void heardOn(quint16 system, const QString &link);
    // A decoded message from any transport (any thread), the link it came on
    // and the size of its packet.
    void ingest(const msg::Message &message, const QString &link = {}, qsizetype bytes = 0);
    // What a vehicle's message means, made by its link (a MAVLink vehicle's
    // state in IMC words): into the tree, alarms and database like anything
    // received, but not counted as traffic (any thread).
    void ingestDerived(const msg::Message &message);
    // A packet from `peer` over `link` that could not be decoded (any thread);
    // `system` is 0xFFFF when even its header did not say who sent it.
    void decodeFailed(quint16 system, const QString &link, const QString &peer, const QString &reason);

    // Sends `message` to a system (by id or by the name it is shown by) over
    // the link it was heard on, and records it under "system/out" once sent;
    // an error says why it was not sent.
    std::expected<void, QString> send(quint16 system, msg::Message message);
    std::expected<void, QString> send(const QString &system, msg::Message message);
    // Sends `message` to every console and vehicle on DDS (consoles sharing a mission).
    std::expected<void, QString> broadcast(const msg::Message &message);

    // Several hosts (IMC/UDP) or participants (DDS, "dds:<GUID prefix>")
    // send as `system` (an impostor, or a vehicle on two networks): commands
    // go to `host` ("" lets the link choose again). False if the system was
    // not heard from that host.
    bool chooseSource(quint16 system, const QString &host);

    // Forgets a system everywhere: its tree branch, its alarms (to Unknown),
    // its link statistics and route, what was asked of it. Heard again, it
    // is met anew. check() does it for the systems the health monitor lets
    // go (HealthMonitor::setForgetAfter; short-lived ones after 10 min).
    void forget(quint16 system);

    // A few times a second: silence, entity queries. Once a second: rates and
    // link alarms. Timers call them; tests call them after moving their clock.
    void check();
    void tick();

    // Every node of the tree as "path<TAB>value text<TAB>unit", one a line,
    // in tree order: what the console knows, for tests and bug reports.
    QString dumpTree() const;

signals:
    // A vehicle's plan database or plan control spoke (PlanDB, PlanControl,
    // PlanControlState): for plans::PlanDesk. Emitted from the thread that received it.
    void planMessageReceived(const neptus::msg::Message &message);
    // Another console changed a shared mission (MissionChange): for plans::MissionShare.
    void sharedMissionReceived(const neptus::msg::Message &message);
    // A console (or vehicle) announced itself as `system` on DDS, or left: for plans::MissionShare.
    void participantJoined(quint16 system);
    void participantLeft(quint16 system);

private:
    void wireImc(transport::ImcUdpTransport &imc);
    transport::ImcUdpTransport *keepImc(std::unique_ptr<transport::ImcUdpTransport> imc);
    void wireMavlink(transport::MavlinkTransport &link);
    transport::MavlinkTransport *keepMavlink(std::unique_ptr<transport::MavlinkTransport> link);
    // Link health: decode errors in the last few seconds, and message types
    // the definitions lack, as alarms on "systems/<system>/link" and ".../definitions".
    void updateLinkAlarms();
    void updateDefinitionsAlarm(quint16 id, const transport::LinkStatistics::System &system);
    // Who sends as a system: several hosts, or an Announce naming addresses
    // elsewhere, raise a Warning on "systems/<system>/sources".
    void updateSourcesAlarm(quint16 id);
    // A link says who sends as `system` now, and where commands go ("" held).
    void sourcesChanged(quint16 system, const QStringList &senders, const QString &destination);

    // Hands a link's packet to the recorder, if there is one.
    void tap(QByteArrayView packet);
    // What every received message goes to (the tree, database, health, naming, plan desk).
    void take(const msg::Message &message);
    // A host sent too much, or this console fell behind: a Warning on "links/<host>".
    void overloaded(const QString &host, int overRate, int behind, int maximum);
    // A MAVLink vehicle's STATUSTEXT: warnings and worse are an alarm on
    // "systems/<vehicle>/statustext" that lapses a minute after the last.
    void statusText(quint16 system, int severity, const QString &text);

    const Clock *m_clock;
    std::atomic<log::Recorder *> m_recorder = nullptr;
    std::atomic<OperationsFeed *> m_feed = nullptr;
    QMetaObject::Connection m_recorderProblems;
    bool m_replaying = false;
    std::shared_ptr<const msg::Schema> m_schema;
    std::shared_ptr<msg::SchemaSet> m_schemas;
    tree::VariableTree m_tree;
    alarms::AlarmGraph m_graph;
    alarms::HealthMonitor m_health;
    EntityNaming m_naming;
    transport::LinkStatistics m_linkStatistics;
    transport::LinkRouter m_router;
    std::unique_ptr<scripting::ScriptHost> m_scripts;
    std::unique_ptr<transport::ImcUdpTransport> m_imc;
    std::unique_ptr<transport::DdsTransport> m_dds;
    std::vector<std::unique_ptr<transport::MavlinkTransport>> m_mavlink;
    std::shared_ptr<const msg::Schema> m_mavlinkSchema;
    QString m_mavlinkDialect;
    struct Said
    {
        alarms::Level level = alarms::Normal;
        qint64 ms = 0;
    };
    QHash<quint16, Said> m_statusTexts; // the last STATUSTEXT alarm per MAVLink vehicle
    QTimer m_checkTimer;
    QTimer m_tickTimer;
    // What the link alarms last said, per system, so they change only when it does.
    QHash<quint16, QString> m_linkAlarmText;
    QHash<quint16, QString> m_definitionsAlarmText;
    QHash<quint16, QString> m_announcedVersions;
    QHash<quint16, QString> m_digestNotes;
    struct Sources
    {
        QStringList hosts;
        QString destination;
        QString ignoredAnnounce; // why the last Announce (or MAVLink frame) from elsewhere was ignored
        qint64 ignoredMs = 0;
        QString alarmText;
    };
    QHash<quint16, Sources> m_sources;
};

} // namespace neptus::session
