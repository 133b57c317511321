#pragma once

#include "AlarmGraph.h"
#include "AlarmListModel.h"
#include "DdsTransport.h"
#include "EntityNaming.h"
#include "HealthMonitor.h"
#include "ImcUdpTransport.h"
#include "LinkRouter.h"
#include "LinkStatistics.h"
#include "LinkStatisticsModel.h"
#include "SchemaSet.h"
#include "ScriptHost.h"
#include "Tracks.h"
#include "VariableTree.h"
#include "VariableTreeModel.h"

#include <QObject>
#include <QTimer>
#include <QtQml/qqmlregistration.h>

#include <memory>

// Everything one running console is made of, in one place: the message
// definitions (the console's own, and others per system), the variable tree
// and its QML model, the alarm graph and its list model, the health monitor,
// the alarm scripts, the links to vehicles (IMC/UDP, DDS) with their
// statistics, and the queries a console makes on first contact. The shell
// hands it to QML as a property.
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

public:
    explicit ConsoleSession(std::shared_ptr<const neptus::msg::Schema> schema, QObject *parent = nullptr);
    ~ConsoleSession() override;

    const neptus::msg::Schema &schema() const { return *m_schema; }
    neptus::msg::SchemaSet &schemas() { return *m_schemas; }
    neptus::tree::VariableTree &variableTree() { return m_tree; }
    neptus::alarms::AlarmGraph &alarmGraph() { return m_graph; }
    neptus::alarms::HealthMonitor &health() { return m_health; }
    neptus::transport::LinkStatistics &linkStatistics() { return m_linkStatistics; }
    neptus::tree::VariableTreeModel *treeModel() { return &m_treeModel; }
    neptus::alarms::AlarmListModel *alarmModel() { return &m_alarmModel; }
    neptus::transport::LinkStatisticsModel *linksModel() { return &m_linksModel; }
    // Made on first use: a session that runs no alarm scripts (a headless
    // recorder, the receive-path fuzz target) starts no script engine.
    neptus::scripting::ScriptHost *scripts();
    neptus::geo::Tracks *tracks() { return &m_tracks; }
    neptus::transport::ImcUdpTransport *imc() { return m_imc.get(); }
    neptus::transport::DdsTransport *dds() { return m_dds.get(); }

    // Decodes what `system` (an IMC id such as "0x00d1", or the name it
    // announces) sends with the definitions in `file` (IMC.xml or IMC.xml.gz),
    // and encodes what goes to it with them. Call before starting the links.
    std::expected<void, QString> setDefinitionsFor(const QString &system, const QString &file);

    // Opens the links; an error says why (a busy port, a bad configuration),
    // and the session carries on without that link.
    std::expected<void, QString> startImc(const neptus::transport::ImcUdpConfig &config);
    std::expected<void, QString> startDds(const neptus::transport::DdsConfig &config);
    // Takes an IMC/UDP link made with schemaSet(), started or not (the fuzz
    // target feeds an unstarted one through receive()).
    neptus::transport::ImcUdpTransport *attachImc(std::unique_ptr<neptus::transport::ImcUdpTransport> imc);
    std::shared_ptr<neptus::msg::SchemaSet> schemaSet() const { return m_schemas; }

    // A transport, by name ("IMC/UDP", "DDS"): commands to a system go over
    // the link it was last heard on. startImc/startDds add theirs.
    void addLink(const QString &name, neptus::tree::VariableTree::OutputSink *sink);
    // A peer speaks other message definitions: a Warning on
    // "systems/<system>/definitions" says so, so values are not silently misread.
    void definitionsDiffer(quint16 system, const QString &theirDigest, const QString &ourDigest);

    // A decoded message from any transport (any thread), the link it came on
    // and the size of its packet.
    void ingest(const neptus::msg::Message &message, const QString &link = {}, qsizetype bytes = 0);
    // A packet from `peer` over `link` that could not be decoded (any thread);
    // `system` is 0xFFFF when even its header did not say who sent it.
    void decodeFailed(quint16 system, const QString &link, const QString &peer, const QString &reason);
    // Once a second: rates, link alarms, entity queries (tests call it after moving their clock).
    void tick();

    // For components (a joystick, a command button): sends a message, given
    // as JSON ({"abbrev": "Abort", "fields": {...}}), to a system through the
    // tree's output branch. Returns "" when sent, else why not.
    Q_INVOKABLE QString send(const QString &system, const QVariantMap &message);

    // Every node of the tree as "path<TAB>value text<TAB>unit", one a line,
    // in tree order: what the console knows, for tests and bug reports.
    QString dumpTree() const;

private:
    // Link health: decode errors in the last few seconds, and message types
    // the definitions lack, as alarms on "systems/<system>/link" and ".../definitions".
    void updateLinkAlarms();
    void updateDefinitionsAlarm(quint16 id, const neptus::transport::LinkStatistics::System &system);

    std::shared_ptr<const neptus::msg::Schema> m_schema;
    std::shared_ptr<neptus::msg::SchemaSet> m_schemas;
    neptus::tree::VariableTree m_tree;
    neptus::tree::VariableTreeModel m_treeModel{&m_tree};
    neptus::geo::Tracks m_tracks{&m_treeModel};
    neptus::alarms::AlarmGraph m_graph;
    neptus::alarms::AlarmListModel m_alarmModel{&m_graph};
    neptus::alarms::HealthMonitor m_health{m_graph, m_tree};
    neptus::tree::EntityNaming m_naming;
    neptus::transport::LinkStatistics m_linkStatistics;
    neptus::transport::LinkStatisticsModel m_linksModel{&m_linkStatistics, &m_tree};
    neptus::transport::LinkRouter m_router;
    std::unique_ptr<neptus::scripting::ScriptHost> m_scripts;
    std::unique_ptr<neptus::transport::ImcUdpTransport> m_imc;
    std::unique_ptr<neptus::transport::DdsTransport> m_dds;
    QTimer m_healthCheck;
    QTimer m_second;
    // What the link alarms last said, per system, so they change only when it does.
    QHash<quint16, QString> m_linkAlarmText;
    QHash<quint16, QString> m_definitionsAlarmText;
    QHash<quint16, QString> m_announcedVersions;
    QHash<quint16, QString> m_digestNotes;
};
