#pragma once

#include "AlarmGraph.h"
#include "AlarmListModel.h"
#include "HealthMonitor.h"
#include "LinkRouter.h"
#include "ScriptHost.h"
#include "Tracks.h"
#include "VariableTree.h"
#include "VariableTreeModel.h"

#include <QObject>
#include <QTimer>
#include <QtQml/qqmlregistration.h>

#include <memory>

// Everything one running console is made of, in one place: the message
// definitions, the variable tree and its QML model, the alarm graph and its
// list model, the health monitor and the alarm scripts. The shell hands it to
// QML as a property; transports (a later issue) feed ingest().
class ConsoleSession : public QObject
{
    Q_OBJECT
    QML_ELEMENT
    QML_UNCREATABLE("made by the program")
    Q_PROPERTY(neptus::tree::VariableTreeModel *tree READ treeModel CONSTANT)
    Q_PROPERTY(neptus::alarms::AlarmListModel *alarms READ alarmModel CONSTANT)
    Q_PROPERTY(neptus::scripting::ScriptHost *scripts READ scripts CONSTANT)
    Q_PROPERTY(neptus::geo::Tracks *tracks READ tracks CONSTANT)

public:
    explicit ConsoleSession(std::shared_ptr<const neptus::msg::Schema> schema, QObject *parent = nullptr);
    ~ConsoleSession() override;

    const neptus::msg::Schema &schema() const { return *m_schema; }
    neptus::tree::VariableTree &variableTree() { return m_tree; }
    neptus::alarms::AlarmGraph &alarmGraph() { return m_graph; }
    neptus::tree::VariableTreeModel *treeModel() { return &m_treeModel; }
    neptus::alarms::AlarmListModel *alarmModel() { return &m_alarmModel; }
    neptus::scripting::ScriptHost *scripts() { return m_scripts.get(); }
    neptus::geo::Tracks *tracks() { return &m_tracks; }

    // A transport, by name ("IMC/UDP", "DDS"): commands to a system go over
    // the link it was last heard on.
    void addLink(const QString &name, neptus::tree::VariableTree::OutputSink *sink);
    // A peer speaks other message definitions: a Warning on
    // "systems/<system>/definitions" says so, so values are not silently misread.
    void definitionsDiffer(quint16 system, const QString &theirDigest, const QString &ourDigest);

    // A decoded message from any transport (any thread), and the link it came on.
    void ingest(const neptus::msg::Message &message, const QString &link = {});

    // For components (a joystick, a command button): sends a message, given
    // as JSON ({"abbrev": "Abort", "fields": {...}}), to a system through the
    // tree's output branch. Returns "" when sent, else why not.
    Q_INVOKABLE QString send(const QString &system, const QVariantMap &message);

private:
    std::shared_ptr<const neptus::msg::Schema> m_schema;
    neptus::tree::VariableTree m_tree;
    neptus::tree::VariableTreeModel m_treeModel{&m_tree};
    neptus::geo::Tracks m_tracks{&m_treeModel};
    neptus::alarms::AlarmGraph m_graph;
    neptus::alarms::AlarmListModel m_alarmModel{&m_graph};
    neptus::alarms::HealthMonitor m_health{m_graph, m_tree};
    neptus::transport::LinkRouter m_router;
    std::unique_ptr<neptus::scripting::ScriptHost> m_scripts;
    QTimer m_healthCheck;
};
